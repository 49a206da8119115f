"""A static check of a submission's files, before anything is built.

It flags what an exercise never needs and what could change how the tests run:
  - a preprocessor #define or #undef (it could silence CHECK, or rename what a test calls);
  - an #include of anything but the standard library, Eigen, fmt, the kit's public headers and the
    exercise files themselves;
  - a process-control call: exit, _Exit, quick_exit, abort, terminate, system, fork, exec*,
    popen, kill, raise, signal, longjmp, atexit, syscall, dlopen, or inline asm;
  - file-system access: streams on files, std::filesystem, fopen, open, write, remove, rename…
    (no exercise reads or writes a file; the sandbox would stop the write anyway).
Each such finding is an "integrity" finding: the exercises written in that file score 0, with
the finding as the reason. Other preprocessor conditionals (#if, #ifdef) are listed as notes.
Comments and string literals are blanked before the scan, so prose never trips it."""
import pathlib
import re

STANDARD_HEADERS = set("""
algorithm any array atomic bit bitset cassert cctype cerrno cfenv cfloat charconv chrono cinttypes
climits clocale cmath codecvt compare complex concepts cstddef cstdint cstdio cstdlib cstring ctime
cuchar cwchar cwctype deque exception execution format forward_list functional initializer_list iomanip ios
iosfwd iostream istream iterator limits list locale map memory memory_resource new numbers numeric
optional ostream queue random ranges ratio regex scoped_allocator set span sstream stack stdexcept
streambuf string string_view system_error tuple type_traits typeindex typeinfo unordered_map
unordered_set utility valarray variant vector version math.h stddef.h stdint.h float.h limits.h assert.h
""".split())

# Unqualified too for names nothing else is called; `system` and `signal` only when qualified, since
# an ODE's right-hand side is often called `system(t, u)`.
PROCESS_CONTROL = re.compile(
    r"(?<![\w.>:])(?:(?:std)?\s*::\s*)?(exit|abort|fork|popen|kill|raise|atexit)\s*\(|"
    r"(?<![\w.>:])(?:std)?\s*::\s*(system|signal)\s*\(")
# Names no exercise needs whatever follows them (a call, or taking the address to call later):
# leaving the process, reaching the evidence descriptor, or the system below the library.
FORBIDDEN_NAMES = re.compile(
    r"\b(_Exit|_exit|quick_exit|at_quick_exit|vfork|exec[lv]p?e?|execvpe|sigaction|longjmp|setjmp|"
    r"syscall|dlopen|ptrace|getenv|secure_getenv|environ|dprintf|KIT_EVIDENCE_FD)\b")
INLINE_ASM = re.compile(r"\b(asm|__asm__|__asm)\b")
FILE_SYSTEM = re.compile(r"\b(basic_ofstream|basic_ifstream|basic_fstream|ofstream|ifstream|fstream|filebuf|"
                         r"filesystem|FILE)\b|\b(fopen|fdopen|freopen|openat|creat|unlink|rmdir|mkdir|truncate|"
                         r"dup2?)\s*\(|(?<![\w.>])::\s*(open|write|remove|rename)\s*\(")
# An include guard or a feature macro: #define NAME with no value, NAME in capitals.
HARMLESS_DEFINE = re.compile(r"^\s*#\s*define\s+(?:[A-Z0-9_]+_HPP?_?|[A-Z0-9_]+_H_?|_USE_MATH_DEFINES)\s*$")
DIRECTIVE = re.compile(r"^\s*(?:#|%:)\s*(\w+)\s*(.*)$")  # %: is the digraph of #


def blank_comments_and_strings(text):
    """The text with comments and string/char literals replaced by spaces (newlines kept)."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c == "'" and i > 0 and text[i - 1].isalnum() and i + 1 < n and text[i + 1].isalnum():
            out.append(c)  # a digit separator (1'000'000), not a character literal
            i += 1
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            j = min(j + 1, n)
            out.append(c + " " * max(0, j - i - 2) + (c if j - i >= 2 else ""))
            i = j
        else:
            out.append(c)
            i += 1
    return "".join(out)


def kit_public_headers(kit_root):
    include = pathlib.Path(kit_root) / "common" / "include"
    return {p.relative_to(include).as_posix() for p in include.rglob("*.hpp")}


def allowed_include(target, angle, kit_headers, exercise_files):
    library = target in STANDARD_HEADERS or target.startswith(("Eigen/", "fmt/")) or target in kit_headers
    return library or (not angle and target in exercise_files)


def check(text, name, kit_headers, exercise_files):
    """Findings for one file: dicts {file, line, severity: integrity|note, what}."""
    findings = []
    raw_lines = text.splitlines()
    code_lines = blank_comments_and_strings(text).splitlines()
    for number, (raw, code) in enumerate(zip(raw_lines, code_lines), start=1):
        directive = DIRECTIVE.match(code)
        if directive:
            word = directive.group(1)
            if word == "define" and HARMLESS_DEFINE.match(raw):
                findings.append({"file": name, "line": number, "severity": "note", "what": f"#define ({raw.strip()[:80]})"})
            elif word in ("define", "undef"):
                findings.append({"file": name, "line": number, "severity": "integrity",
                                 "what": f"preprocessor #{word} ({raw.strip()[:80]})"})
            elif word == "include":
                target = re.match(r'\s*(?:#|%:)\s*include\s*([<"])([^>"]+)[>"]', raw)
                if not target or not allowed_include(target.group(2), target.group(1) == "<", kit_headers,
                                                     exercise_files):
                    findings.append({"file": name, "line": number, "severity": "integrity",
                                     "what": f"#include outside the standard library, Eigen and the kit ({raw.strip()[:80]})"})
            elif word == "pragma":
                continue
            elif word in ("if", "ifdef", "ifndef", "elif", "else", "endif"):
                findings.append({"file": name, "line": number, "severity": "note",
                                 "what": f"preprocessor #{word}"})
            else:  # include_next, import, line, error… : nothing an exercise needs
                findings.append({"file": name, "line": number, "severity": "integrity",
                                 "what": f"preprocessor #{word}"})
            continue
        for match in PROCESS_CONTROL.finditer(code):
            findings.append({"file": name, "line": number, "severity": "integrity",
                             "what": f"process-control call {match.group(1) or match.group(2)}()"})
        for match in FORBIDDEN_NAMES.finditer(code):
            findings.append({"file": name, "line": number, "severity": "integrity",
                             "what": f"use of {match.group(1)}"})
        if INLINE_ASM.search(code):
            findings.append({"file": name, "line": number, "severity": "integrity", "what": "inline assembly"})
        for match in FILE_SYSTEM.finditer(code):
            findings.append({"file": name, "line": number, "severity": "integrity",
                             "what": f"file-system access {match.group(1) or match.group(2)}"})
    return findings
