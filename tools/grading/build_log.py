"""What went wrong, from the build log and a test's output, in one line a student can act on."""
import re


def first_error(log, student_file):
    """The first compiler error of a student's program, preferring one in the student's own file,
    with the path cut to the file's name; or the log's last line (a limit that stopped it)."""
    found = [line.strip() for line in log.splitlines() if re.search(r"\berror\b", line)]
    own = [line for line in found if re.search(rf"(^|/){re.escape(student_file)}:\d+", line)]
    if own or found:
        return re.sub(r"^.*?/([^/]+:\d+:\d+: )", r"\1", (own or found)[0])[:400]
    lines = [line.strip() for line in log.splitlines() if line.strip()]
    return (lines[-1] if lines else "did not compile")[:400]


def first_failure(output):
    """The line that says best why a test failed: the placeholder's sentence, else Catch's first
    'failed:' line, else the first line of output."""
    placeholder = re.search(r"(ex \d+\.\d+ is not implemented yet[^'\n]*)", output)
    if placeholder:
        return placeholder.group(1)
    for line in output.splitlines():
        if "failed:" in line:
            return re.sub(r"^.*?([\w.-]+:\d+): failed: ", r"\1: ", line.strip())[:400]
    for line in output.splitlines():
        if line.strip():
            return line.strip()[:400]
    return ""
