#!/usr/bin/env bash
# Builds the stepwise program (release preset) and runs it.
#
#   scripts/run.sh                   runs config/default.scene
#   scripts/run.sh ARGS…             runs `build/release/stepwise ARGS…`, e.g.
#   scripts/run.sh run config/X.scene --duration 5 --csv out.csv
#
# Setup, configure and build messages go to stderr, so stdout is only what
# stepwise prints. Paths in ARGS are relative to the directory you run from.
# The exit status is stepwise's (0 ok, 1 simulation failure, 2 bad scene file
# or command line), or non-zero from setup or the build when those fail.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir="$root/build/release"

bash "$root/scripts/setup.sh" >&2

# Configure once; later builds re-run CMake by themselves when a CMakeLists.txt
# changes. Configure again when the presets file is newer than the cache.
if [[ ! -f "$build_dir/build.ninja" || ! -f "$build_dir/CMakeCache.txt" \
      || "$root/CMakePresets.json" -nt "$build_dir/CMakeCache.txt" ]]; then
    (cd "$root" && cmake --preset release) >&2
fi
(cd "$root" && cmake --build --preset release --target stepwise) >&2

if [[ $# -eq 0 ]]; then
    exec "$build_dir/stepwise" run "$root/config/default.scene"
fi
exec "$build_dir/stepwise" "$@"
