#!/usr/bin/env bash
# Fuzzes the scene loader and the command line (tests/fuzz/): libFuzzer, with AddressSanitizer
# and UndefinedBehaviorSanitizer, built by clang-14 (the `fuzz` preset).
#
#   scripts/fuzz.sh              builds, then runs each fuzzer for 60 s, the two side by side (what CI does)
#   scripts/fuzz.sh 3600         one hour each
#   scripts/fuzz.sh --no-build 60
#
# Seeds: every shipped scene (config/, lectures/) for the loader, tests/fuzz/seeds/cli/ for the
# command line, and the inputs that once broke them (tests/fuzz/regressions/); the loader also gets a dictionary of the record and field names found in them.
# What a run adds to the corpus stays in build/fuzz/corpus/ for the next run. A crash, a leak,
# undefined behaviour or a hang (over 10 s on one input) stops the fuzzer: its input is saved in
# build/fuzz/artifacts/, the script says how to reproduce it, and exits 1. Once it is fixed, copy
# the input into tests/fuzz/regressions/scenes/ or cli/: tests/test_fuzz_regressions.cpp replays
# every file there through the same oracles (tests/fuzz/fuzz_oracles.hpp).
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
build=true
seconds=60
for arg in "$@"; do
    case $arg in
        --no-build) build=false ;;
        -h|--help) sed -n '2,/^[^#]/{/^#/p}' "$0"; exit 0 ;;
        *[!0-9]*|'') echo "fuzz.sh: expected a number of seconds or --no-build, found '$arg'" >&2; exit 2 ;;
        *) seconds=$arg ;;
    esac
done

if $build; then
    cmake --preset fuzz >&2
    cmake --build --preset fuzz -j "${STEPWISE_JOBS:-2}" >&2
fi
bin=build/fuzz/tests/fuzz
work=build/fuzz
mkdir -p "$work/artifacts" "$work/corpus/scenes" "$work/corpus/cli" "$work/seeds/scenes"
find config lectures tests/fuzz/regressions/scenes -name '*.scene' -exec cp {} "$work/seeds/scenes/" \;
# The dictionary: record names and "Field=" words of the shipped scenes.
{
    find config lectures -name '*.scene' -exec cat {} + |
        grep -v '^#' | grep -oE '(^[A-Za-z]+|[A-Za-z]+=)' | sort -u | sed 's/.*/"&"/'
    printf '"%s"\n' "," "(" ")" "1/60" "true" "false" "1e308" "-0" "nan" "inf" "#" '\x0A'
} > "$work/scene.dict"

# Each fuzzer's messages go to its own report, printed once both have stopped, so that two
# fuzzers running side by side do not interleave their lines.
run() {
    local target=$1
    shift
    local report="$work/$target.report"
    echo "fuzz.sh: $target for $seconds s" > "$report"
    if ! "$bin/$target" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
            -artifact_prefix="$work/artifacts/$target-" "$@" 2> "$work/$target.log"; then
        {
            echo "fuzz.sh: $target FAILED; the end of its log ($work/$target.log):"
            tail -40 "$work/$target.log"
            echo "fuzz.sh: reproduce with: $bin/$target $work/artifacts/$target-<crash file>"
        } >> "$report"
        return 1
    fi
    grep -E '^stat::(number_of_executed_units|new_units_added)' "$work/$target.log" | sed "s/^/fuzz.sh: $target: /" >> "$report"
}
# Side by side, a core each, when STEPWISE_JOBS (default 2) allows: each still fuzzes for its
# $seconds, and the run takes half the time. STEPWISE_JOBS=1 runs one after the other.
status=0
if [[ ${STEPWISE_JOBS:-2} -ge 2 ]]; then
    run fuzz_scene_loader -dict="$work/scene.dict" "$work/corpus/scenes" "$work/seeds/scenes" &
    loader=$!
    run fuzz_command_line "$work/corpus/cli" tests/fuzz/seeds/cli tests/fuzz/regressions/cli &
    cli=$!
    wait "$loader" || status=1
    wait "$cli" || status=1
else
    run fuzz_scene_loader -dict="$work/scene.dict" "$work/corpus/scenes" "$work/seeds/scenes" || status=1
    run fuzz_command_line "$work/corpus/cli" tests/fuzz/seeds/cli tests/fuzz/regressions/cli || status=1
fi
cat "$work/fuzz_scene_loader.report" "$work/fuzz_command_line.report" >&2
exit $status
