#!/usr/bin/env python3
"""The static check reads a file as the compiler does: a line splice or a raw string literal
does not hide a #define or a forbidden call from it, and legitimate code is not flagged.

Each case is a small header: the ones that evade a regex scan of the raw text must give the
expected integrity finding, on the right line; the legitimate ones must give none. Then every
file of solutions/ must give none. Fast (no build).

Usage: static_check_evasions.py
"""
import json
import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tools"))
from grading import static_check  # noqa: E402

BS = "\\"  # one backslash, for the line splices below

# (what, source, the finding expected: (line, a part of its text))
EVASIONS = [
    ("#define split by a splice", f"#pragma once\n#def{BS}\nine CHECK(...) ((void)0)\n", (2, "#define")),
    ("# split from define", f"#{BS}\n define REQUIRE(...) ((void)0)\n", (1, "#define")),
    ("a splice with spaces after the backslash (GCC joins it)", f"#undef{BS}  \n CHECK\n", (1, "#undef")),
    ("std::system split by a splice", f'inline int x = std::sys{BS}\ntem("true");\n', (1, "system()")),
    ("quick_exit split twice", f"inline void f() {{ qu{BS}\nick_{BS}\nexit(0); }}\n", (1, "quick_exit")),
    ("a splice in the middle of std::_Exit, on line 3", f"#pragma once\n\nvoid f() {{ std::_Ex{BS}\nit(0); }}\n",
     (3, "_Exit")),
    ("a call after a raw string holding a quote",
     'inline const char* a = R"x(")x"; inline int b = (std::_Exit(0), 0); inline const char* c = "(";\n',
     (1, "_Exit")),
    ("a call after a prefixed raw string holding quotes and a comment opener",
     'inline auto a = u8R"q(" /* ")q"; inline int b = (std::_Exit(0), 0); // */\n', (1, "_Exit")),
    ("a #define after a multi-line LR raw string",
     'inline auto a = LR"(\n"\n)";\n#define CHECK(...) ((void)0)\ninline auto b = "(";\n', (4, "#define")),
    ("a call after a u8 character literal (not a digit separator)",
     "inline auto c = u8'a'; inline int d = (std::_Exit(0), 0); inline auto e = 'b';\n", (1, "_Exit")),
    ("a splice inside a string hides nothing", f'inline auto s = "a{BS}\nb"; inline int t = (std::_Exit(0), 0);\n',
     (2, "_Exit")),
    ("posix_spawn declared by hand", 'extern "C" int posix_spawn(int*, const char*, const void*, const void*,'
     " char* const*, char* const*);\n", (1, "posix_spawn")),
    ("an include that starts with an allowed prefix and climbs out",
     "#pragma once\n#include <Eigen/../../../../work/main/solutions/rk4.hpp>\n", (2, "#include")),
    ("an include by absolute path", '#include "/work/main/solutions/rk4.hpp"\n', (1, "#include")),
    ("a function taken without a call, qualified", "inline auto out = ::write;\n", (1, "address of write")),
    ("a function taken by address", "inline void (*leave)(int) = &std::exit;\n", (1, "address of exit")),
]

LEGITIMATE = [
    ("an include guard", "#ifndef KIT_RK4_HPP\n#define KIT_RK4_HPP\n#include <cmath>\n#endif  // KIT_RK4_HPP\n"),
    ("std::remove and an ODE's system(t, u)",
     "#include <algorithm>\n#include <vector>\ninline void f(std::vector<int>& v) {\n"
     "  v.erase(std::remove(v.begin(), v.end(), 0), v.end());\n}\n"
     "template <class S> auto g(S system, double t, double u) { return system(t, u); }\n"),
    ("a raw string holding #define, a call and a comment opener",
     'inline const char* doc = R"(\n#define CHECK(x) nothing\nstd::_Exit(0); /* system("x")\n)";\n'
     'inline const char* more = u8R"end(std::exit(1) )" still inside)end";\n'),
    ("strings and characters holding quotes, slashes and names",
     "inline const char* a = \"say \\\"std::exit(1)\\\" // not a comment\";\n"
     "inline const char b = '\"'; inline const char c = '\\''; inline const char* d = \"\\\\\";\n"
     "inline const wchar_t e = L'x'; inline const char* f = u8\"fork()\";\n"),
    ("digit separators next to character literals",
     "inline const long n = 1'000'000; inline const char q = 'x'; inline const double h = 0x1'0p-4;\n"),
    ("a splice that continues a comment", f"// a comment that ends with a backslash {BS}\nstd::_Exit(0);\n"
     "inline int kept = 1;\n"),
    ("a block comment with prose", "/* don't call std::exit(1) or #define here */\ninline int z = 0;\n"),
    ("a #pragma and Windows line endings", "#pragma once\r\n#include <cmath>\r\ninline double r = std::sqrt(2.0);\r\n"),
    ("a reference parameter named system or write",
     "template <class S> double f(const S& system, double& write) { return system(0.0, write); }\n"),
]


def integrity(text):
    return [f for f in static_check.check(text, "case.hpp", set(), {"case.hpp"}) if f["severity"] == "integrity"]


def main():
    problems = []
    for what, text, (line, part) in EVASIONS:
        found = integrity(text)
        good = any(f["line"] == line and part in f["what"] for f in found)
        print(f"{'ok  ' if good else 'FAIL'} flagged: {what}: {[(f['line'], f['what']) for f in found]}")
        if not good:
            problems.append(f"not flagged at line {line} ({part}): {what}")
    for what, text in LEGITIMATE:
        found = integrity(text)
        print(f"{'ok  ' if not found else 'FAIL'} not flagged: {what}: {[(f['line'], f['what']) for f in found]}")
        if found:
            problems.append(f"flagged though legitimate: {what}")
    kit_headers = static_check.kit_public_headers(ROOT)
    solutions = sorted((ROOT / "solutions").glob("*.hpp"))
    names = {p.name for p in solutions}
    points = json.loads((ROOT / "tests/grading/points.json").read_text(encoding="utf-8"))
    for path in solutions:
        # Each solution includes only the kit headers points.json allows its exercise.
        allowed = {h for e in points["exercises"] if e["file"] == path.name for h in e["headers"]}
        found = [f for f in static_check.check(path.read_text(encoding="utf-8"), path.name, kit_headers, names, allowed)
                 if f["severity"] == "integrity"]
        if found:
            problems.append(f"solutions/{path.name} flagged: {found}")
    rigid = static_check.check("#include <kit/rigid/rigid_integrators.hpp>\n", "rigid_quaternion_step.hpp", kit_headers, names,
                               {"kit/rigid/rigid_body.hpp"})
    if not rigid:
        problems.append("a kit header its exercise may not use was not flagged")
    print(f"{len(EVASIONS)} evasions, {len(LEGITIMATE)} legitimate cases, {len(solutions)} solution files; "
          f"{len(problems)} problems")
    for problem in problems:
        print(problem, file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
