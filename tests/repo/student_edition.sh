#!/usr/bin/env bash
# The student edition holds no solution, builds, passes the tests that apply, and self-grades.
set -euo pipefail
kit_root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
work=${1:?usage: [KIT_TEST_LIBRARIES=BUILD/lib KIT_TEST_PROGRAMS=BUILD/tests] student_edition.sh WORK_DIR}
# The edition's common/ and chapters/ are the kit's own, file for file: its tree may link the kit's
# libraries rather than compile them again (the edition without production code, whose common/
# differs, links them only when no object of theirs read a file it leaves out). When everything but exercises/ is the kit's own too, it also takes
# the programs no exercise goes into (judges, test_common) from the kit's build, once ninja's record
# of what each of their compiles read shows no file of solutions/: the edition's own compiles are
# its chapters, the ones a student's work changes.
libraries=${KIT_TEST_LIBRARIES:-}
programs=${KIT_TEST_PROGRAMS:-}
rm -rf "$work"
mkdir -p "$work"
cd "$kit_root"
./kit student-edition "$work/edition"
python3 tools/student_edition.py check "$kit_root" "$work/edition"
# The check can fail: the kit itself, solutions and all, is full of solution code.
if python3 tools/student_edition.py check "$kit_root" "$kit_root" >/dev/null 2>&1; then
  echo "FAILED: the solution-code check finds nothing in the full kit"; exit 1
fi
grep -q "solves some exercises another way" "$work/edition/README.md" || { echo "FAILED: the README does not say what production code gives away"; exit 1; }

cd "$work/edition"
if [ -n "$libraries" ] && diff -rq "$kit_root/common" common >/dev/null &&
   diff -rq -x __pycache__ "$kit_root/chapters" chapters >/dev/null; then
  shared=("-DKIT_LIBRARIES=$libraries")
  if [ -n "$programs" ] && diff -q "$kit_root/CMakeLists.txt" CMakeLists.txt >/dev/null &&
     diff -rq -x __pycache__ "$kit_root/cmake" cmake >/dev/null && diff -rq -x __pycache__ "$kit_root/tests" tests >/dev/null; then
    read_solutions=$(ninja -C "$(dirname "$programs")" -t deps | awk '/^[^ ]/ { object = $1 } /^ / { print object, $1 }' |
      grep -E "^tests/CMakeFiles/(test_common|grade_ex[0-9_]+|kit_remote_student|replay_[a-z]+_scene|kit_test_pch|kit_catch_main|kit_remote_judge)[.]dir/" |
      grep -E "/(solutions|exercises)/" || true)
    if [ -z "$read_solutions" ]; then
      shared+=("-DKIT_TEST_PROGRAMS=$programs")
    else
      printf 'the kit'"'"'s test programs read solutions/ or exercises/, so the edition compiles its own:\n%s\n' "$read_solutions" | head -5
    fi
  fi
  echo "the edition's tree takes from the kit's build: ${shared[*]}"
  cmake --preset release -B build "${shared[@]}" >/dev/null
fi
# Instructor-only commands refuse with a reason.
if ./kit exercises-check 2>/dev/null; then echo "FAILED: exercises-check ran without solutions/"; exit 1; fi
./kit test
# exercises/ as shipped, nothing solved: every chapter of the edition's own tree runs what needs
# no exercise and names what waits (the third tree of chapters.partial-runs, checked here).
python3 "$kit_root/tests/repo/partial_runs.py" --built none "$work/edition/build" "$work/none"
# A student who solved everything grades their own copy at full marks, from the edition alone.
# Beside the kit's build, the batch shares the kit's program cache: a program is taken from it only
# when every input of its compile (the edition's harness, headers and library objects, the
# compiler, the file) is byte for byte one the kit compiled in the sandbox.
cp -r exercises "$work/mine"
cp "$kit_root"/solutions/*.hpp "$work/mine/"
cache=()
[ -z "$programs" ] || cache=(--cache "$(dirname "$programs")/grade-cache")
./kit grade --out "$work/grades" ${cache[@]+"${cache[@]}"} "$work/mine" >/dev/null 2>"$work/grade.err" ||
  { cat "$work/grade.err"; exit 1; }
grep "programs from earlier batches" "$work/grade.err" || true
python3 - "$work/grades/mine/grade.json" <<'PY'
import json, sys
g = json.load(open(sys.argv[1], encoding="utf-8"))
print(f"self-grade in the student edition: {g['points']} / {g['max_points']}")
sys.exit(0 if g["points"] == g["max_points"] and g["sandboxed"] else 1)
PY

# Without production code: none of its files, and chapter 4's DOPRI5 is the student's own
# (ex 4.2 on the Dormand–Prince tableau with ex 4.3's PI law), which takes Hairer's 985
# evaluations on Arenstorf at 1e-6 exactly as the production one does (ANCHORS.md).
cd "$kit_root"
./kit student-edition "$work/bare" --without-production >/dev/null
for file in common/include/kit/ode/dopri5.hpp common/include/kit/ode/pi_step_control.hpp \
            common/include/kit/ode/dopri5_work_method.hpp tests/common/ode/test_dopri5.cpp tests/bench/bench_adaptive.cpp; do
  [ ! -e "$work/bare/$file" ] || { echo "FAILED: the edition without production code holds $file"; exit 1; }
done
grep -q "runs on your own ex 4.2 and ex 4.3" "$work/bare/README.md" || { echo "FAILED: its README does not say so"; exit 1; }
cd "$work/bare"
# Its common/ is the kit's less the production headers, its chapters/ the kit's. When no
# preprocessor line left in common/ names one of them (an #include, a __has_include, a #define), no
# source of kit_common can include one; when ninja's record shows no object of the kit's
# kit_lessons read one, neither does a lesson: its libraries are the kit's, and the tree links those.
bare_library=""
if [ -n "$libraries" ]; then
  differences=$(diff -rq "$kit_root/common" common || true)
  removed=$(sed -n "s|^Only in $kit_root/common[^:]*: ||p" <<<"$differences")
  others=$(grep -v "^Only in $kit_root/common" <<<"$differences" || true)
  named=$(printf '%s\n' $removed | sed 's/[.]/[.]/g' | paste -sd'|')
  lessons_read=$(ninja -C "$(dirname "$libraries")" -t deps | awk '/^[^ ]/ { object = $1 } /^ / { print object, $1 }' |
    grep "^chapters/CMakeFiles/kit_lessons[.]dir/" | grep -E "/kit/.*/($named)\$" || true)
  if [ -n "$removed" ] && [ -z "$others" ] && ! grep -rqE "^[[:space:]]*#.*($named)" common && [ -z "$lessons_read" ] &&
     diff -rq -x __pycache__ "$kit_root/chapters" chapters >/dev/null; then
    echo "the edition without production code links the kit's libraries: it leaves out only" $removed
    cmake --preset release -B build "-DKIT_LIBRARIES=$libraries" >/dev/null
    bare_library=yes
  fi
fi
./kit --impl "$work/mine" run 04-adaptive-rk -- --no-plot --quiet >/dev/null
bare_build=$(./kit --impl "$work/mine" build-dir)
"$bare_build/bin/04-adaptive-rk" --no-plot --json >"$work/bare-04.json"
python3 - "$work/bare-04.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1], encoding="utf-8"))
detail, vdp = s["detail"], s["van_der_pol"]
print(f"without production: {detail['method']}, {detail['rhs_evals']} evaluations; Van der Pol {vdp['accepted']} steps")
ok = (detail["method"] == "DOPRI5 (ex 4.2, 4.3)" and detail["rhs_evals"] == 985 and detail["rejected"] == 23
      and "Dormand-Prince 5(4) (kit)" in s["work_precision"] and "DOPRI5 (kit)" not in s["work_precision"]
      and vdp["accepted"] > 10000 and not s.get("skipped"))
sys.exit(0 if ok else 1)
PY
# As shipped (nothing solved), chapter 4 runs GSL and Boost, names what waits for ex 4.2, and
# draws its figures.
./kit run 04-adaptive-rk -- --quiet >/dev/null
"$(./kit build-dir)/bin/04-adaptive-rk" --no-plot --json >"$work/bare-stubs-04.json"
python3 - "$work/bare-stubs-04.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1], encoding="utf-8"))
waits = {entry["reason"].split()[1] for entry in s.get("skipped", [])}
print(f"without production, nothing solved: chapter 4 waits for {sorted(waits)}")
sys.exit(0 if "4.2" in waits and "GSL rkck" in s["work_precision"] else 1)
PY
# Its unit tests are the kit's less tests/common/ode/test_dopri5.cpp. When it links the kit's library,
# its tests/ is the kit's less that file and the DOPRI5 benchmark, and ninja's record of the kit's
# test_common shows that no other object of it read a removed header, solutions/ or exercises/,
# and `nm` that none needs a symbol test_dopri5.o defines, the edition's test_common is the kit's
# without test_dopri5.cpp's test cases: it runs that rather than compiling it again.
reuse_tests=""
if [ -n "$bare_library" ] && [ -n "$programs" ]; then
  kit_build=$(dirname "$programs")
  objects="$kit_build/tests/CMakeFiles/test_common.dir/common"
  dopri5_object="$objects/ode/test_dopri5.cpp.o"
  tests_differences=$(diff -rq -x __pycache__ "$kit_root/tests" tests || true)
  tests_others=$(grep -vE "^Only in $kit_root/tests/(common/ode: test_dopri5[.]cpp|bench: bench_adaptive[.]cpp)\$" \
                 <<<"$tests_differences" || true)
  if [ -z "$tests_others" ] && grep -q "test_dopri5[.]cpp" <<<"$tests_differences" && [ -f "$dopri5_object" ]; then
    read_removed=$(ninja -C "$kit_build" -t deps | awk '/^[^ ]/ { object = $1 } /^ / { print object, $1 }' |
      grep "^tests/CMakeFiles/test_common[.]dir/" | grep -v "/test_dopri5[.]cpp[.]o" |
      grep -E "/(solutions|exercises)/|/kit/.*/($named)\$" || true)
    strong=$(nm -g --defined-only "$dopri5_object" | awk '$2 ~ /^[TDBR]$/ { print $3 }' | sort -u)
    wanted=$(find "$objects" -name '*.o' ! -path "$dopri5_object" -exec nm -u {} + | awk '{ print $NF }' | sort -u)
    needed=$(comm -12 <(printf '%s\n' "$strong") <(printf '%s\n' "$wanted") | grep . || true)
    if [ -z "$read_removed" ] && [ -z "$needed" ]; then
      reuse_tests=yes
    else
      printf 'the kit'"'"'s test_common depends on what the edition leaves out, so the edition compiles its own:\n%s\n' \
        "$read_removed$needed" | head -5
    fi
  fi
fi
if [ -n "$reuse_tests" ]; then
  echo "the edition without production code runs the kit's test_common less test_dopri5.cpp's cases"
  "$programs/test_common" "~[#test_dopri5]" -# >"$work/bare-common.log" 2>&1 || { tail -40 "$work/bare-common.log"; exit 1; }
  tail -3 "$work/bare-common.log"
else
  cmake --build "$bare_build" --target test_common >/dev/null
  ctest --test-dir "$bare_build" -R '^common$' --output-on-failure
fi
echo "student edition: ok"
