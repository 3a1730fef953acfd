#!/usr/bin/env bash
# Everything CI checks, in the order CI checks it (.ci/run calls this script):
#
#   1. setup        scripts/setup.sh installs any missing package
#   2. ci build     configure + build the `ci` preset (Release, warnings are errors)
#   3. ci tests     ctest --preset ci (the viewer's screenshot tests run under xvfb-run)
#   4. docs         Doxygen API reference into build/ci/docs/html; any warning fails
#   5. asan build   configure + build the `asan` preset (Debug, ASan + UBSan, warnings are errors)
#   6. asan tests   ctest --preset asan (without the tests labelled slow, e.g. the 210-box
#                   pyramid's 10 s: the ci tests run them; under the sanitizers they take
#                   over 15 minutes on 2 cores and check no code the shorter tests miss)
#   7. fuzz build   configure + build the `fuzz` preset (clang-14, libFuzzer, ASan + UBSan)
#   8. fuzz         scripts/fuzz.sh --no-build 60: the scene loader and the command line, 60 s each
#
# Prints a header "==> [N/8] part: command" before each part, "--> part: OK"
# or "--> part: FAILED" after it, and a one-line summary at the end; exits
# non-zero if any part failed. The parts after a failure still run (so one run
# shows every problem), except the tests of a build that failed.
# Works from any directory. Build parallelism: STEPWISE_JOBS (default 2).
set -uo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root" || exit 1
jobs=${STEPWISE_JOBS:-2}

start=$SECONDS
passed=()
failed=()
skipped=()
total=8
n=0

# part NAME SHOWN COMMAND… : runs COMMAND under a header naming the part and
# showing the command lines SHOWN, and records how it went.
part() {
    local name=$1 shown=$2
    shift 2
    n=$((n + 1))
    local t0=$SECONDS
    echo
    echo "==> [$n/$total] $name: $shown"
    if "$@"; then
        echo "--> $name: OK ($((SECONDS - t0)) s)"
        passed+=("$name")
        return 0
    fi
    echo "--> $name: FAILED ($((SECONDS - t0)) s)"
    failed+=("$name")
    return 1
}

skip() {
    n=$((n + 1))
    echo
    echo "==> [$n/$total] $1: skipped ($2)"
    skipped+=("$1")
}

configure_and_build() {
    cmake --preset "$1" && cmake --build --preset "$1" -j "$jobs"
}

if ! part "setup" "scripts/setup.sh" bash scripts/setup.sh; then
    echo
    echo "test.sh: FAILED at setup: the packages above are missing ($((SECONDS - start)) s)"
    exit 1
fi

docs() {
    part "docs" "cmake --build --preset ci --target docs (any Doxygen warning fails)" \
        cmake --build --preset ci -j "$jobs" --target docs
}

if part "ci build" "cmake --preset ci && cmake --build --preset ci -j $jobs" configure_and_build ci; then
    part "ci tests" "ctest --preset ci" ctest --preset ci
    docs
else
    skip "ci tests" "the ci build failed"
    # The docs need only a configured build directory, not a successful build.
    if [[ -f build/ci/build.ninja ]]; then
        docs
    else
        skip "docs" "the ci preset did not configure"
    fi
fi

if part "asan build" "cmake --preset asan && cmake --build --preset asan -j $jobs" configure_and_build asan; then
    part "asan tests" "ctest --preset asan" ctest --preset asan
else
    skip "asan tests" "the asan build failed"
fi

if part "fuzz build" "cmake --preset fuzz && cmake --build --preset fuzz -j $jobs" configure_and_build fuzz; then
    part "fuzz" "scripts/fuzz.sh --no-build ${STEPWISE_FUZZ_SECONDS:-60}" bash scripts/fuzz.sh --no-build "${STEPWISE_FUZZ_SECONDS:-60}"
else
    skip "fuzz" "the fuzz build failed"
fi

elapsed=$((SECONDS - start))
duration="$((elapsed / 60)) min $((elapsed % 60)) s"
join() { local IFS=','; echo "$*" | sed 's/,/, /g'; }
echo
if [[ ${#failed[@]} -eq 0 && ${#skipped[@]} -eq 0 ]]; then
    echo "test.sh: OK: all $total parts passed ($(join "${passed[@]}")) in $duration"
    exit 0
fi
summary="test.sh: FAILED: $(join "${failed[@]}")"
if [[ ${#skipped[@]} -gt 0 ]]; then
    summary+="; skipped: $(join "${skipped[@]}")"
fi
if [[ ${#passed[@]} -gt 0 ]]; then
    summary+="; passed: $(join "${passed[@]}")"
fi
echo "$summary; in $duration"
exit 1
