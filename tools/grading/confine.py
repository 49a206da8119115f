"""The last step before a sandboxed command starts: set its resource limits, forbid new processes
if asked, then exec it. Run by the grader inside the sandbox (and bare with --no-sandbox):

  python3 -I -S confine.py --as BYTES --fsize BYTES --cpu SECONDS [--no-spawn] -- COMMAND...

  --as      RLIMIT_AS, bytes of address space;
  --fsize   RLIMIT_FSIZE, bytes a process may write to any one file;
  --cpu     RLIMIT_CPU, seconds of CPU time per process: SIGXCPU at SECONDS, SIGKILL a second later;
  --no-spawn  a seccomp filter kills the process (SIGSYS) the moment it calls fork, vfork, clone
            or clone3: no child process, no thread. For the graded tests, which need neither.
Core dumps are always off (RLIMIT_CORE 0).

Why seccomp and not RLIMIT_NPROC: the kernel never applies RLIMIT_NPROC to processes whose real
user is root (copy_process() exempts INIT_USER), and that stays true inside bubblewrap's user
namespace, which maps root to root. A grader run as root would get no limit at all. The filter
holds for every user, in the sandbox or not.

Exit status 125 when the limits cannot be set: the command never runs unconfined.
Standard library only, no kit imports: it runs with -I -S from the read-only kit."""
import ctypes
import os
import platform
import resource
import struct
import sys

# <linux/filter.h>, <linux/seccomp.h>, <linux/audit.h>
BPF_LD_W_ABS = 0x00 | 0x00 | 0x20   # BPF_LD | BPF_W | BPF_ABS
BPF_JEQ_K = 0x05 | 0x10 | 0x00      # BPF_JMP | BPF_JEQ | BPF_K
BPF_JGE_K = 0x05 | 0x30 | 0x00      # BPF_JMP | BPF_JGE | BPF_K
BPF_RET_K = 0x06 | 0x00             # BPF_RET | BPF_K
SECCOMP_RET_KILL_PROCESS = 0x80000000
SECCOMP_RET_ALLOW = 0x7FFF0000
PR_SET_NO_NEW_PRIVS = 38
PR_SET_SECCOMP = 22
SECCOMP_MODE_FILTER = 2
OFFSET_NR, OFFSET_ARCH = 0, 4  # struct seccomp_data

# machine -> (AUDIT_ARCH_*, syscall numbers that create a process or thread, first number of
# another ABI sharing the architecture tag (x32 on x86_64), or None)
SPAWN_SYSCALLS = {
    "x86_64": (0xC000003E, {"clone": 56, "fork": 57, "vfork": 58, "clone3": 435}, 0x40000000),
    "aarch64": (0xC00000B7, {"clone": 220, "clone3": 435}, None),
}


def no_spawn_filter(machine):
    """The classic-BPF program: any other architecture tag, any x32 call, and every spawning call
    kill the process; everything else is allowed."""
    arch, numbers, foreign_abi = SPAWN_SYSCALLS[machine]
    program = [(BPF_LD_W_ABS, 0, 0, OFFSET_ARCH), ("kill_unless_eq", arch), (BPF_LD_W_ABS, 0, 0, OFFSET_NR)]
    if foreign_abi is not None:
        program.append(("kill_if_ge", foreign_abi))
    program += [("kill_if_eq", n) for n in sorted(numbers.values())]
    program.append((BPF_RET_K, 0, 0, SECCOMP_RET_ALLOW))
    kill_at = len(program)
    program.append((BPF_RET_K, 0, 0, SECCOMP_RET_KILL_PROCESS))
    code = []
    for index, entry in enumerate(program):
        to_kill = kill_at - index - 1  # jump offsets count from the next instruction
        if entry[0] == "kill_unless_eq":
            code.append((BPF_JEQ_K, 0, to_kill, entry[1]))
        elif entry[0] == "kill_if_eq":
            code.append((BPF_JEQ_K, to_kill, 0, entry[1]))
        elif entry[0] == "kill_if_ge":
            code.append((BPF_JGE_K, to_kill, 0, entry[1]))
        else:
            code.append(entry)
    return b"".join(struct.pack("=HBBI", *instruction) for instruction in code), len(code)


class SockFprog(ctypes.Structure):
    _fields_ = [("len", ctypes.c_ushort), ("filter", ctypes.c_void_p)]


def forbid_spawning():
    machine = platform.machine()
    if machine not in SPAWN_SYSCALLS:
        raise OSError(f"no process filter for this machine ({machine}); known: {', '.join(SPAWN_SYSCALLS)}")
    code, count = no_spawn_filter(machine)
    buffer = ctypes.create_string_buffer(code, len(code))
    program = SockFprog(count, ctypes.cast(buffer, ctypes.c_void_p))
    libc = ctypes.CDLL(None, use_errno=True)
    libc.prctl.argtypes = [ctypes.c_int, ctypes.c_ulong, ctypes.c_ulong, ctypes.c_ulong, ctypes.c_ulong]
    if libc.prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0:
        raise OSError(ctypes.get_errno(), "prctl(PR_SET_NO_NEW_PRIVS)")
    if libc.prctl(PR_SET_SECCOMP, SECCOMP_MODE_FILTER, ctypes.addressof(program), 0, 0) != 0:
        raise OSError(ctypes.get_errno(), "prctl(PR_SET_SECCOMP)")


def main(argv):
    try:
        split = argv.index("--")
    except ValueError:
        split = len(argv)
    options, command = argv[1:split], argv[split + 1:]
    limits, spawn = {}, True
    i = 0
    while i < len(options):
        if options[i] == "--no-spawn":
            spawn = False
            i += 1
        elif options[i] in ("--as", "--fsize", "--cpu") and i + 1 < len(options) and options[i + 1].isdigit():
            limits[options[i]] = int(options[i + 1])
            i += 2
        else:
            print(f"confine: unexpected argument {options[i]!r}", file=sys.stderr)
            return 125
    if not command or set(limits) != {"--as", "--fsize", "--cpu"}:
        print("confine: usage: confine.py --as BYTES --fsize BYTES --cpu SECONDS [--no-spawn] -- COMMAND...",
              file=sys.stderr)
        return 125
    try:
        resource.setrlimit(resource.RLIMIT_AS, (limits["--as"], limits["--as"]))
        resource.setrlimit(resource.RLIMIT_FSIZE, (limits["--fsize"], limits["--fsize"]))
        resource.setrlimit(resource.RLIMIT_CPU, (limits["--cpu"], limits["--cpu"] + 1))
        resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
        if not spawn:
            forbid_spawning()
    except (OSError, ValueError) as why:
        print(f"confine: cannot set the limits: {why}", file=sys.stderr)
        return 125
    try:
        os.execvp(command[0], command)
    except OSError as why:
        print(f"confine: cannot run {command[0]}: {why}", file=sys.stderr)
        return 127


if __name__ == "__main__":
    sys.exit(main(sys.argv))
