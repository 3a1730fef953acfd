#!/usr/bin/env bash
# Builds the debug preset and starts gdb on a scene or on a lecture's gdb session: one command.
#
#   scripts/debug.sh SCENE [GDB ARGS…] [-- RUN ARGS…]
#       gdb on `build/debug/stepwise run SCENE RUN ARGS…`, with the scene's breakpoints
#       (lectures/gdb/breakpoints/NAME.gdb) loaded when it has them; then type `run`.
#   scripts/debug.sh lectures/gdb/NN-NAME.gdb [GDB ARGS…]
#       a lecture's session, on the command line its header gives ("interactive:");
#       it runs, stops where the lecture stops, and leaves you at the (gdb) prompt.
#   scripts/debug.sh --dry-run …
#       prints the commands (configure, build, scene copy, gdb) without running them.
#       (It builds the program only, target stepwise: gdb needs no tests.)
#   scripts/debug.sh --prepare …
#       builds and makes the session's scene copy, but starts no gdb (VS Code's tasks use it,
#       before a launch entry of .vscode/launch.json runs the session).
#
# Examples:
#   scripts/debug.sh config/lesson03_bounce.scene
#   scripts/debug.sh config/lesson08_heavy_on_light.scene -- --steps 2
#   scripts/debug.sh lectures/gdb/03-first-impact.gdb
#   scripts/debug.sh lectures/gdb/03-first-impact.gdb -q -batch     (print every answer and exit)
#
# The debug preset builds with -O0 -g3 -fno-inline and takes the plain path, so every stage is a
# function gdb can stop in (README.md, "Debugging a lesson"). A session that runs on a copy of a
# scene says so in its header ("scene copy:"); the script makes the copy first. Paths are relative
# to the repository's root, where the script runs gdb (the sessions source lectures/gdb/stepwise.py
# by that path). Exit status: gdb's; 1 when the build fails; 2 for a bad command line, a missing
# file, or no gdb.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
usage="usage: scripts/debug.sh [--dry-run | --prepare] SCENE [GDB ARGS…] [-- RUN ARGS…]
       scripts/debug.sh [--dry-run | --prepare] lectures/gdb/NN-NAME.gdb [GDB ARGS…]"

dry_run=0
prepare_only=0
while [[ ${1:-} == --dry-run || ${1:-} == --prepare ]]; do
    [[ $1 == --dry-run ]] && dry_run=1 || prepare_only=1
    shift
done
if [[ $# -eq 0 || ${1:-} == -h || ${1:-} == --help ]]; then
    echo "$usage" >&2
    exit 2
fi
target=$1
shift
# Relative to the repository's root, where gdb runs; an absolute path stays as it is.
if [[ $target != /* && ! -e "$root/$target" && -e "$PWD/$target" ]]; then
    target=$(realpath --relative-to="$root" "$PWD/$target")
fi

gdb_args=()
run_args=()
while [[ $# -gt 0 ]]; do
    if [[ $1 == -- ]]; then
        shift
        run_args=("$@")
        break
    fi
    gdb_args+=("$1")
    shift
done

# What gdb is started on: gdb -x FILE … --args build/debug/stepwise ARGS…
program=(build/debug/stepwise)
commands_file=""
copy_command=""
case $target in
    *.scene)
        [[ -f "$root/$target" || -f "$target" ]] || { echo "debug.sh: no scene file '$target'" >&2; exit 2; }
        breakpoints="lectures/gdb/breakpoints/$(basename "$target" .scene).gdb"
        [[ -f "$root/$breakpoints" ]] && commands_file=$breakpoints
        program+=(run "$target" "${run_args[@]}")
        ;;
    *.gdb)
        [[ -f "$root/$target" ]] || { echo "debug.sh: no gdb session '$target'" >&2; exit 2; }
        if [[ ${#run_args[@]} -gt 0 ]]; then
            echo "debug.sh: a session brings its own command line; '-- ${run_args[*]}' is not used with one" >&2
            exit 2
        fi
        # "#   interactive:  gdb -x SESSION --args build/debug/stepwise run SCENE [OPTIONS]"
        interactive=$(sed -n 's/^#   interactive: *gdb .*--args build\/debug\/stepwise //p' "$root/$target")
        if [[ -z $interactive ]]; then
            echo "debug.sh: $target has no '#   interactive:  gdb … --args build/debug/stepwise …' line" >&2
            exit 2
        fi
        read -r -a session_args <<<"$interactive"
        program+=("${session_args[@]}")
        commands_file=$target
        # "#   scene copy:  sed … config/X.scene > /tmp/Y.scene"
        copy_command=$(sed -n 's/^#   scene copy: *//p' "$root/$target")
        scene=${session_args[1]:-}
        if [[ -z $copy_command && $scene == /tmp/* && ! -f $scene ]]; then
            echo "debug.sh: $target runs on $scene, a copy of a scene you make yourself:" \
                 "$(sed -n 's/^#   your copy: *//p' "$root/$target")" >&2
            exit 2
        fi
        ;;
    *)
        echo "debug.sh: '$target' is neither a scene (.scene) nor a gdb session (.gdb)" >&2
        echo "$usage" >&2
        exit 2
        ;;
esac

gdb_command=(gdb)
[[ -n $commands_file ]] && gdb_command+=(-x "$commands_file")
gdb_command+=("${gdb_args[@]}" --args "${program[@]}")

if [[ $dry_run == 1 ]]; then
    echo "cmake --preset debug"
    echo "cmake --build --preset debug -j2 --target stepwise"
    [[ -n $copy_command ]] && echo "$copy_command"
    [[ $prepare_only == 1 ]] && exit 0
    line=$(printf '%q ' "${gdb_command[@]}")
    echo "${line% }"
    exit 0
fi

if [[ $prepare_only == 0 ]] && ! command -v gdb >/dev/null 2>&1; then
    echo "debug.sh: gdb is not installed; scripts/setup.sh installs it" >&2
    exit 2
fi
cd "$root"
# Configure once, and again when the presets file is newer than the cache (as scripts/run.sh).
if [[ ! -f build/debug/build.ninja || ! -f build/debug/CMakeCache.txt || CMakePresets.json -nt build/debug/CMakeCache.txt ]]; then
    cmake --preset debug >&2 || exit 1
fi
cmake --build --preset debug -j2 --target stepwise >&2 || exit 1  # the program only: gdb needs no tests
if [[ -n $copy_command ]]; then
    bash -c "$copy_command" || { echo "debug.sh: the scene copy failed: $copy_command" >&2; exit 1; }
fi
[[ $prepare_only == 1 ]] && exit 0
exec "${gdb_command[@]}"
