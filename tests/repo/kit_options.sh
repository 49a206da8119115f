#!/usr/bin/env bash
# ./kit never ignores what it is told: global options are honoured before or after the command,
# a command refuses arguments it does not take (exit 2), and `run` needs neither LaTeX nor Catch2.
set -uo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
failures=0
check() {  # check DESCRIPTION EXPECTED ACTUAL
  if [ "$2" = "$3" ]; then echo "ok: $1"; else echo "FAILED: $1: expected [$2], got [$3]"; failures=$((failures + 1)); fi
}
exit_of() { "$@" >/dev/null 2>&1; echo $?; }

before=$(./kit --impl exercises build-dir)
after=$(./kit build-dir --impl exercises)
check "--impl before and after the command select the same build" "$before" "$after"
check "--impl=DIR is the same as --impl DIR" "$before" "$(./kit build-dir --impl=exercises)"
[ "$before" != "$(./kit build-dir)" ] || { echo "FAILED: --impl after the command was ignored"; failures=$((failures + 1)); }
check "--preset after the command" "$(./kit --preset debug build-dir)" "$(./kit build-dir --preset debug)"

check "build with an extra argument exits 2" 2 "$(exit_of ./kit build extra)"
check "build --impl of a missing folder exits 2" 2 "$(exit_of ./kit build --impl /nonexistent/student)"
message=$(./kit build --impl /nonexistent/student 2>&1 >/dev/null)
[[ "$message" == *"--impl /nonexistent/student"* ]] || { echo "FAILED: message does not name the flag and value: $message"; failures=$((failures + 1)); }
check "an unknown preset exits 2" 2 "$(exit_of ./kit build-dir --preset bogus)"
check "--impl without a folder exits 2" 2 "$(exit_of ./kit run --impl)"
check "grade refuses --impl (it takes folders)" 2 "$(exit_of ./kit grade --impl exercises solutions)"
check "an unknown command exits 2" 2 "$(exit_of ./kit frobnicate)"
check "exercises-check refuses arguments" 2 "$(exit_of ./kit exercises-check now)"

check "run needs no LaTeX package" 0 "$(./kit deps --for run --list | grep -c -e texlive -e latexmk)"
check "grade needs no LaTeX package" 0 "$(./kit deps --for grade --list | grep -c -e texlive -e latexmk)"
[ "$(./kit deps --for slides --list | grep -c texlive)" -gt 0 ] || { echo "FAILED: slides must install texlive"; failures=$((failures + 1)); }
check "ccache is never required" 0 "$(./kit deps --for test --list | grep -c ccache)"
check "run needs no test framework" 0 "$(./kit deps --for run --list | grep -c catch2)"
check "figures needs no test framework" 0 "$(./kit deps --for figures --list | grep -c catch2)"
for command in test build grade evidence; do
  check "$command needs Catch2" 1 "$(./kit deps --for "$command" --list | grep -cx catch2)"
done
check "deps --for an unknown command exits 2" 2 "$(exit_of ./kit deps --for frobnicate --list)"
message=$(./kit deps --for frobnicate --list 2>&1 >/dev/null)
[[ "$message" == *"--for 'frobnicate'"*"run figures build test"* ]] || { echo "FAILED: deps --for's refusal does not name the value and the choices: $message"; failures=$((failures + 1)); }

# view: the chapters with 3D pages are 5 to 9; anything else is refused before anything is built.
check "view without a chapter exits 2" 2 "$(exit_of ./kit view)"
check "view of an unknown chapter exits 2" 2 "$(exit_of ./kit view 42)"
message=$(./kit view 03 2>&1 >/dev/null)
check "view of a chapter without 3D pages exits 2" 2 "$(exit_of ./kit view 03)"
[[ "$message" == *"03-rk2"*"05 to 09"* ]] || { echo "FAILED: view 03's refusal does not say which chapters have pages: $message"; failures=$((failures + 1)); }
check "view takes at most a chapter and a page" 2 "$(exit_of ./kit view 07 cloth extra)"
check "run installs three.js (the pages)" 1 "$(./kit deps --for run --list | grep -cx libjs-three)"
check "run needs no browser" 0 "$(./kit deps --for run --list | grep -c chromium)"

echo "$failures failed"
exit $((failures > 0))
