"""A static check of a submission's files, before anything is built.

It flags what an exercise never needs and what could change how the tests run:
  - a preprocessor #define or #undef (it could silence CHECK, or rename what a test calls);
  - an #include of anything but the standard library, Eigen, fmt, the kit's public headers and the
    exercise files themselves;
  - a process-control call: exit, _Exit, quick_exit, abort, terminate, system, fork, exec*,
    posix_spawn, pthread_create, popen, kill, raise, signal, longjmp, atexit, syscall, dlopen, or
    inline asm;
  - file-system access: streams on files, std::filesystem, fopen, open, write, remove, rename…
    (no exercise reads or writes a file; the sandbox would stop the write anyway).
Each such finding is an "integrity" finding: the exercises written in that file score 0, with
the finding as the reason. Other preprocessor conditionals (#if, #ifdef) are listed as notes.
The scan reads the file as the compiler does: line splices (a backslash at the end of a line)
joined first, then comments and string and character literals, raw ones included (R"x(…)x",
u8R, LR…), blanked, so prose never trips it and neither `#def\<newline>ine` nor a call hidden
behind a literal gets past it."""
import bisect
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
    r"syscall|dlopen|ptrace|getenv|secure_getenv|environ|dprintf|posix_spawnp?|pthread_create|KIT_EVIDENCE_FD)\b")
# Taking a process-control or file-system function's address, to call it later through a pointer.
# (After an operator, a bracket or `return`: `const Spring& system` declares a reference.) A
# qualified name needs no `&`: `auto out = ::write;` is a pointer too.
ADDRESS_TAKEN = re.compile(r"(?:(?:^|[=(,{;?:!|]|\breturn)\s*&\s*(?:(?:std)?\s*::\s*)?|(?<![\w>])(?:std)?\s*::\s*)"
                           r"(exit|abort|fork|popen|kill|raise|atexit|system|signal|open|write|"
                           r"remove|rename|unlink|fopen|dup2?)\b(?!\s*\()")
INLINE_ASM = re.compile(r"\b(asm|__asm__|__asm)\b")
FILE_SYSTEM = re.compile(r"\b(basic_ofstream|basic_ifstream|basic_fstream|ofstream|ifstream|fstream|filebuf|"
                         r"filesystem|FILE)\b|\b(fopen|fdopen|freopen|openat|creat|unlink|rmdir|mkdir|truncate|"
                         r"dup2?)\s*\(|(?<![\w.>])::\s*(open|write|remove|rename)\s*\(")
# An include guard or a feature macro: #define NAME with no value, NAME in capitals.
HARMLESS_DEFINE = re.compile(r"^\s*#\s*define\s+(?:[A-Z0-9_]+_HPP?_?|[A-Z0-9_]+_H_?|_USE_MATH_DEFINES)\s*$")
DIRECTIVE = re.compile(r"^\s*(?:#|%:)\s*(\w+)\s*(.*)$")  # %: is the digraph of #


RAW_PREFIXES = {"R", "u8R", "uR", "UR", "LR"}
RAW_OPENING = re.compile(r'"([^ ()\\\t\v\f\n]{0,16})\(')  # "delimiter( of a raw string
# Translation phase 2: a backslash at the end of a line joins it to the next. GCC and Clang also
# join when spaces or tabs come between the backslash and the newline (with a warning).
SPLICE = re.compile(r"\\[ \t\f\v]*$")


def splice_lines(text):
    """(joined text, starts): the text with line endings made \\n and every backslash-newline
    removed, and starts[k] the offset in it where physical line k + 1 begins.

    The standard reverts splices inside a raw string literal, which this does not: joining there
    can only end a raw string earlier than the compiler does, so more is scanned as code, never
    less."""
    lines = text.replace("\r\n", "\n").replace("\r", "\n").split("\n")
    joined, starts, size = [], [], 0
    for number, line in enumerate(lines):
        starts.append(size)
        last = number == len(lines) - 1
        splice = None if last else SPLICE.search(line)
        piece = line[:splice.start()] if splice else line + ("" if last else "\n")
        joined.append(piece)
        size += len(piece)
    return "".join(joined), starts


def _is_identifier_char(c):
    return c.isalnum() or c in "_$" or ord(c) > 127


def blank(text, keep_literals=False):
    """`text` (already spliced) with comments, and unless `keep_literals` string and character
    literals (raw ones too, with their u8/u/U/L prefixes), replaced by spaces; newlines and length
    kept. Numbers are read whole, so a digit separator (1'000) never opens a character literal."""
    out, i, n = [], 0, len(text)

    def blanked(start, stop):
        return re.sub(r"[^\n]", " ", text[start:stop])

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
            out.append(blanked(i, j))
            i = j
        elif c.isalpha() or c in "_$" or ord(c) > 127:  # an identifier, or a literal's prefix
            j = i + 1
            while j < n and _is_identifier_char(text[j]):
                j += 1
            word = text[i:j]
            opening = RAW_OPENING.match(text, j) if word in RAW_PREFIXES else None
            if opening:
                closing = ")" + opening.group(1) + '"'
                k = text.find(closing, opening.end())
                k = n if k < 0 else k + len(closing)
                out.append(text[i:k] if keep_literals else word + '"' + blanked(j + 1, k - 1) + '"')
                i = k
            else:  # a prefix (u8"…", L'…') is followed by its literal, read on the next turn
                out.append(word)
                i = j
        elif c.isdigit() or (c == "." and i + 1 < n and text[i + 1].isdigit()):  # a pp-number
            j = i + 1
            while j < n:
                if text[j] in "eEpP" and j + 1 < n and text[j + 1] in "+-":
                    j += 2
                elif _is_identifier_char(text[j]) or text[j] == ".":
                    j += 1
                elif text[j] == "'" and j + 1 < n and _is_identifier_char(text[j + 1]):
                    j += 2  # a digit separator
                else:
                    break
            out.append(text[i:j])
            i = j
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            j = min(j, n)
            closed = j < n and text[j] == c
            stop = j + 1 if closed else j  # unterminated: the rest of the line, as the compiler does
            out.append(text[i:stop] if keep_literals else c + " " * (stop - i - 1 - closed) + (c if closed else ""))
            i = stop
        else:
            out.append(c)
            i += 1
    return "".join(out)


def blank_comments_and_strings(text):
    """The text with line splices joined, and comments and string/char literals replaced by spaces."""
    return blank(splice_lines(text)[0])


def kit_public_headers(kit_root):
    include = pathlib.Path(kit_root) / "common" / "include"
    return {p.relative_to(include).as_posix() for p in include.rglob("*.hpp")}


def allowed_include(target, angle, kit_headers, exercise_files, exercise_headers=None):
    """Whether an exercise file may include `target`: the standard library, Eigen, {fmt}, the kit
    headers its exercise may use (exercise_headers; every public kit header when None), and, in
    quotes, another exercise file. No path may climb (..), start at the root or hold a backslash."""
    parts = target.split("/")
    if target.startswith("/") or "\\" in target or ".." in parts or "." in parts or "" in parts:
        return False
    kit = target in kit_headers and (exercise_headers is None or target in exercise_headers)
    library = target in STANDARD_HEADERS or target.startswith(("Eigen/", "fmt/")) or kit
    return library or (not angle and target in exercise_files)


def check(text, name, kit_headers, exercise_files, exercise_headers=None):
    """Findings for one file: dicts {file, line, severity: integrity|note, what}.

    Phase 2 first (line splices joined), then comments and literals blanked, then the checks, line
    by line; a finding names the physical line where its match begins."""
    findings = []
    joined, starts = splice_lines(text)
    code_text, bare_text = blank(joined), blank(joined, keep_literals=True)
    offset = 0
    for code, bare in zip(code_text.split("\n"), bare_text.split("\n")):
        line_start, offset = offset, offset + len(code) + 1

        def line_of(column):
            return bisect.bisect_right(starts, line_start + column)

        def found(severity, what, column=0):
            findings.append({"file": name, "line": line_of(column), "severity": severity, "what": what})

        shown = " ".join(bare.split())[:80]
        directive = DIRECTIVE.match(code)
        if directive:
            word = directive.group(1)
            if word == "define" and HARMLESS_DEFINE.match(bare):
                found("note", f"#define ({shown})")
            elif word in ("define", "undef"):
                found("integrity", f"preprocessor #{word} ({shown})")
            elif word == "include":
                target = re.match(r'\s*(?:#|%:)\s*include\s*([<"])([^>"]+)[>"]', bare)
                if not target or not allowed_include(target.group(2), target.group(1) == "<", kit_headers,
                                                     exercise_files, exercise_headers):
                    found("integrity", f"#include outside the standard library, Eigen and the kit headers this "
                                       f"exercise may use ({shown})")
            elif word == "pragma":
                if not re.match(r"^\s*(?:#|%:)\s*pragma\s+once\s*$", code):
                    found("note", f"#pragma ({shown})")
            elif word in ("if", "ifdef", "ifndef", "elif", "else", "endif"):
                found("note", f"preprocessor #{word}")
            else:  # include_next, import, line, error… : nothing an exercise needs
                found("integrity", f"preprocessor #{word}")
            continue
        for match in PROCESS_CONTROL.finditer(code):
            found("integrity", f"process-control call {match.group(1) or match.group(2)}()", match.start())
        for match in FORBIDDEN_NAMES.finditer(code):
            found("integrity", f"use of {match.group(1)}", match.start())
        for match in ADDRESS_TAKEN.finditer(code):
            found("integrity", f"the address of {match.group(1)}", match.start())
        asm = INLINE_ASM.search(code)
        if asm:
            found("integrity", "inline assembly", asm.start())
        for match in FILE_SYSTEM.finditer(code):
            found("integrity", f"file-system access {match.group(1) or match.group(2)}", match.start())
    return findings
