#!/usr/bin/env bash
# tests/platform/debian.sh RELEASE [STAGE...]: the README's two commands on a fresh install of a
# Debian release, as a new user runs them. It installs a minimal root of RELEASE from Debian's
# package archive (debootstrap), clones this kit's committed HEAD into it, and runs there, in
# order, printing each stage's wall-clock time:
#   run     ./kit run: every chapter, with only the chapters' packages (no Catch2 is installed)
#   bench   ./kit bench cloth-implicit: installs Bullet into the tree `run` configured, then builds
#           and runs that benchmark (a package a command installs serves that command at once)
#   test    ./kit test: every test (CI=true: warnings are errors)
#   quick   ./kit test --quick: every test but the slow ones (CI=true), as CI runs it; after
#           `run`, without the figures.NN tests, which would draw what `run` has just drawn
#   sanitizers  ./kit --preset asan-ubsan build with the release's clang (installed by the kit),
#           then ./kit fuzz 30
#   grades  ./kit grade of solutions/, exercises/ and a partly solved copy (five exercises solved,
#           ex 3.2 with its weights over 5): class.csv and every grade.json, kept in RELEASE.grades/ to
#           be compared with another release's (the same points under Catch2 v2 and v3)
#   refused ./kit run on a release the kit cannot serve (bullseye, say): it must exit 2 with a
#           message that names what is missing and why, never a CMake or compiler error
#   root    nothing more: the fresh root alone, for a later call with KIT_PLATFORM_REUSE=yes (CI
#           makes it while the host's build keeps the cores busy, downloading beside compiling)
# Default: run, bench and test. Needs root (debootstrap, mounts); the root's own / is the kit's machine,
# entered by pivot_root in a private mount namespace (not chroot, in which bubblewrap, the
# grader's sandbox, could not create its namespaces). Everything it mounts goes with that namespace.
#
# Environment: KIT_PLATFORM_DIR (default /var/tmp/kit-platform) holds RELEASE/ (the root, made
# anew at every call unless KIT_PLATFORM_REUSE=yes) and RELEASE.figures/ (the chapters' data files, for compare_figures.py);
# KIT_PLATFORM_MIRROR (default http://deb.debian.org/debian).
# Example: tests/platform/debian.sh trixie && tests/platform/debian.sh bookworm &&
#          tests/platform/compare_figures.py /var/tmp/kit-platform/{bookworm,trixie}.figures
set -euo pipefail
usage() { echo "usage: $0 RELEASE [run|bench|test|quick|sanitizers|grades|refused|root]...   (RELEASE: bookworm, trixie, ...)" >&2; exit 2; }
(($# >= 1)) || usage
release=$1
shift
[[ "$release" =~ ^[a-z]+$ ]] || { echo "debian.sh: RELEASE '$release': expected a Debian code name such as bookworm or trixie" >&2; exit 2; }
stages=("$@")
((${#stages[@]})) || stages=(run bench test)
for stage in "${stages[@]}"; do
  case "$stage" in run | bench | test | quick | sanitizers | grades | refused | root) ;; *) echo "debian.sh: unknown stage '$stage'; stages: run bench test quick sanitizers grades refused root" >&2; exit 2 ;; esac
done
[ "$(id -u)" -eq 0 ] || { echo "debian.sh: needs root (debootstrap and mounts)" >&2; exit 2; }

kit=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
top=${KIT_PLATFORM_DIR:-/var/tmp/kit-platform}
mirror=${KIT_PLATFORM_MIRROR:-http://deb.debian.org/debian}
root=$top/$release
mkdir -p "$top"

timed() {  # timed NAME COMMAND...: runs it, prints its time, fails the script when it fails
  local name=$1 started=$SECONDS code=0
  shift
  printf '\n=== %s: %s ===\n' "$release" "$name"
  "$@" || code=$?
  printf '=== %s: %s: %s in %d s ===\n' "$release" "$name" "$([ $code -eq 0 ] && echo passed || echo "FAILED (exit $code)")" \
    $((SECONDS - started))
  return $code
}

install_root() {
  command -v debootstrap >/dev/null || { apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq debootstrap >/dev/null; }
  [ -e /usr/share/debootstrap/scripts/"$release" ] || { echo "debian.sh: this debootstrap does not know '$release'" >&2; exit 2; }
  rm -rf "$root"
  debootstrap --variant=minbase --include=ca-certificates,git "$release" "$root" "$mirror" >"$top/$release.debootstrap.log" 2>&1 ||
    { tail -20 "$top/$release.debootstrap.log"; return 1; }
  cp /etc/resolv.conf "$root/etc/resolv.conf"
  # The committed kit, as a clone of it is.
  git clone -q "$kit" "$root/root/kit"
  git -C "$root/root/kit" log -1 --format='kit at %h'
}

# inside COMMAND: runs COMMAND (a bash script) in the root, as root, from the kit's folder.
inside() {
  unshare --mount --propagation private --fork bash -euc '
    root=$1; shift
    mount --bind "$root" "$root"
    mount -t proc proc "$root/proc"
    mount --rbind /sys "$root/sys"
    mount --rbind /dev "$root/dev"
    mkdir -p "$root/.host"
    cd "$root"
    pivot_root . .host
    umount -l /.host
    exec /usr/sbin/chroot / /usr/bin/env -i HOME=/root LANG=C.UTF-8 TERM=dumb CI=true \
      PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin bash -euc "cd /root/kit && $1"
  ' inside "$root" "$1"
}

# KIT_PLATFORM_REUSE=yes keeps a root made before, with what it installed and built, and brings its
# clone to this kit's HEAD: for more stages on the same root. A fresh root is the real test.
if [ "${KIT_PLATFORM_REUSE:-}" = yes ] && [ -d "$root/root/kit/.git" ]; then
  git -C "$root/root/kit" fetch -q "$kit" HEAD && git -C "$root/root/kit" reset -q --hard FETCH_HEAD
  git -C "$root/root/kit" log -1 --format="reusing the $release root; kit at %h: %s"
else
  timed "a fresh $release root from Debian's archive" install_root
fi
inside '. /etc/os-release; echo "$PRETTY_NAME"'
for stage in "${stages[@]}"; do
  case "$stage" in
    root) ;;
    run)
      timed "./kit run" inside './kit run >/root/kit-run.log 2>&1 || { tail -40 /root/kit-run.log; exit 1; }; tail -3 /root/kit-run.log'
      # A student who only runs chapters installs no test framework.
      inside 'if dpkg -s catch2 >/dev/null 2>&1; then echo "./kit run installed catch2"; exit 1; fi; echo "no catch2 after ./kit run"'
      rm -rf "$top/$release.figures"
      cp -r "$root/root/kit/build/figures" "$top/$release.figures"
      ;;
    bench)
      timed "./kit bench cloth-implicit (installs Bullet into the tree run configured)" \
        inside './kit bench cloth-implicit >/root/kit-bench.log 2>&1 || { tail -40 /root/kit-bench.log; exit 1; }; grep -c "" /root/kit-bench.log; grep -m3 -i bullet /root/kit-bench.log'
      ;;
    test | quick)
      words="./kit test"
      if [ "$stage" = quick ]; then words+=" --quick"; fi
      # After `run` in this root, every chapter has just drawn its figures at the lecture's sizes
      # into build/figures, where the figures.NN tests would draw them again, at the same sizes:
      # the quick stage leaves those out (-E), also as the decks' fixtures (-FS), and the decks
      # are built from what `run` drew.
      if [ "$stage" = quick ] && [[ " ${stages[*]} " == *" run "* ]]; then
        words+=" -E '^figures[.]' -FS '^figures[.]'"
      fi
      timed "$words" inside "$words"' >/root/kit-test.log 2>&1 || { grep -E "tests passed|tests failed|\*\*\*Failed|Timeout|Not Run" /root/kit-test.log | tail -40; exit 1; }; tail -4 /root/kit-test.log'
      ;;
    sanitizers)
      timed "./kit --preset asan-ubsan build (the release's clang), then ./kit fuzz 30" inside '
        { ./kit --preset asan-ubsan build && ./kit fuzz 30; } >/root/kit-sanitizers.log 2>&1 ||
          { grep -E "error|warning" /root/kit-sanitizers.log | head -20; tail -20 /root/kit-sanitizers.log; exit 1; }
        clang++ --version | head -1; grep -c "warning:" /root/kit-sanitizers.log || true; grep "^kit:" /root/kit-sanitizers.log | tail -4'
      ;;
    grades)
      timed "./kit grade solutions/, exercises/ and a partly solved copy" inside '
        rm -rf /root/partly && cp -r exercises /root/partly
        for f in midpoint sprite_emit cloth_pcg fem_strain rigid_exponential_map; do cp solutions/$f.hpp /root/partly/; done
        sed "s|dt / 6|dt / 5|" solutions/rk4.hpp >/root/partly/rk4.hpp  # ex 3.2 with its weights over 5: wrong
        grep -q "dt / 5" /root/partly/rk4.hpp || { echo "the wrong ex 3.2 was not made"; exit 1; }
        ./kit grade --out /root/grades solutions exercises /root/partly >/root/kit-grade.log 2>&1 ||
          { tail -30 /root/kit-grade.log; exit 1; }
        tail -5 /root/kit-grade.log'
      rm -rf "$top/$release.grades"
      mkdir -p "$top/$release.grades"
      (cd "$root/root/grades" && cp --parents class.csv */grade.json "$top/$release.grades/")
      ;;
    refused)
      timed "./kit run is refused with exit 2 and a reason" inside '
        code=0; ./kit run >/root/kit-run.log 2>&1 || code=$?
        grep "^kit:" /root/kit-run.log | tail -12
        if grep -q "CMake Error" /root/kit-run.log; then echo "a CMake error reached the user"; exit 1; fi
        [ "$code" -eq 2 ] || { echo "exit $code, not 2"; tail -20 /root/kit-run.log; exit 1; }
        grep -q -e "still missing" -e "older than" /root/kit-run.log || { echo "no reason given"; exit 1; }'
      ;;
  esac
done
inside 'for p in g++ clang cmake ninja-build catch2 libboost-dev libgsl-dev gnuplot-nox libcairo2 libfmt-dev libcli11-dev \
          libtomlplusplus-dev libeigen3-dev nlohmann-json3-dev libstb-dev python3 bubblewrap texlive-latex-recommended \
          poppler-utils libbullet-dev zlib1g; do
          printf "%-28s %s\n" "$p" "$(dpkg-query -W -f="\${Version}" "$p" 2>/dev/null || echo "(not installed)")"; done' \
  | tee "$top/$release.versions"
