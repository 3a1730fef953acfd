#!/usr/bin/env bash
# Draws every figure of the lectures, lectures/images/*.png, from numbers the engine computes.
#
# No figure is drawn by hand. Each one's numbers come from the engine: `stepwise run --csv`,
# `stepwise plot --data` (src/app/plot.cpp) or `stepwise-figures`, a small program that stops a
# lecture's scene at the stage the lecture looks at (bench/figures/main.cpp). Each one's drawing is
# a gnuplot script, bench/figures/NAME.gp, which draws the closed-form answer beside the engine's
# numbers wherever the lecture derives one. One figure is `stepwise plot` itself, the command
# students use for their own runs. The CTest test `figures` (label docs) runs this script into a
# scratch folder and checks that it makes exactly the images of lectures/images/, and the
# `[lectures]` test checks that every lecture shows at least one of them.
#
#   scripts/figures.sh                     build (release preset), then write lectures/images/*.png
#   scripts/figures.sh --out DIR           write the images into DIR instead
#   scripts/figures.sh --build-dir DIR     use DIR/stepwise and DIR/bench/figures/stepwise-figures
#   scripts/figures.sh --no-build          do not build first (with --build-dir: as they are)
#   scripts/figures.sh --list              print the images it makes, one file name a line, and stop
#
# Needs gnuplot (Debian: gnuplot-nox; scripts/setup.sh installs it). A few seconds once built.
# Exit status: 0 when every image was written; 1 when one could not be (what failed is printed);
# 2 for a bad option.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
out=lectures/images
build_dir=build/release
build=1
list=0
while [[ $# -gt 0 ]]; do
    case $1 in
        --out) out=${2:?--out needs a folder}; shift 2 ;;
        --build-dir) build_dir=${2:?--build-dir needs a folder}; shift 2 ;;
        --no-build) build=0; shift ;;
        --list) list=1; shift ;;
        -h|--help) sed -n '2,/^[^#]/{/^#/p}' "$0"; exit 0 ;;
        *) echo "figures.sh: unknown option '$1' (see --help)" >&2; exit 2 ;;
    esac
done

# The figures, in lecture order: file name, then the function below that draws it.
figures=(
    "01-euler-lag.png:euler_lag"
    "02-spring-energy.png:spring_energy"
    "03-bounce-energy.png:bounce_energy"
    "03-impulse-geometry.png:impulse_geometry"
    "03a-end-of-bounce.png:end_of_bounce"
    "04-dzhanibekov-flips.png:dzhanibekov"
    "05-sat-axes.png:sat_axes"
    "06-clipping.png:clipping"
    "07-bowling.png:bowling"
    "07a-warm-starting.png:warm_starting"
    "08-soft-contact.png:soft_contact"
    "08a-waves.png:waves"
    "08a-colours.png:colours"
    "09-stability-limit.png:stability_limit"
    "10-gjk-bounds.png:gjk_bounds"
    "11-mpr-depth.png:mpr_depth"
    "12-capsule-roll.png:capsule_roll"
    "13-terminal-speed.png:terminal_speed"
    "14-inflation.png:inflation"
)
if [[ $list == 1 ]]; then
    for entry in "${figures[@]}"; do echo "${entry%%:*}"; done
    exit 0
fi

if ! command -v gnuplot > /dev/null; then
    echo "figures.sh: gnuplot is not installed (Debian: sudo apt-get install gnuplot-nox, or scripts/setup.sh)" >&2
    exit 1
fi
if [[ $build == 1 ]]; then
    # build/PRESET is configured by its preset when it is not yet; another folder must be configured already.
    if [[ ! -f "$build_dir/build.ninja" && $build_dir == build/* ]]; then cmake --preset "${build_dir#build/}" >&2; fi
    cmake --build "$build_dir" -j "${STEPWISE_JOBS:-2}" --target stepwise stepwise-figures >&2
fi
stepwise="$build_dir/stepwise"
figures_program="$build_dir/bench/figures/stepwise-figures"
for program in "$stepwise" "$figures_program"; do
    if [[ ! -x $program ]]; then echo "figures.sh: $program is not built (drop --no-build)" >&2; exit 1; fi
done

mkdir -p "$out"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# draw NAME.gp OUT.png: the figure script, with the data folder and the output file.
draw() { gnuplot -e "dir='$work'; out='$2'" "bench/figures/$1"; }
# plot ARGS...: `stepwise plot`, quietly (it says what it wrote; the scenes' warnings still show).
plot() { "$stepwise" plot "$@" > /dev/null; }
# copy SCENE FROM TO: a copy of a shipped scene in the work folder, one World field changed.
copy() { sed "s/$2/$3/" "config/$1" > "$work/$4"; grep -q "$3" "$work/$4"; }

euler_lag() {
    plot config/lesson01_explicit_euler.scene --quantity position --component y --data "$work/euler-throw.csv"
    draw 01-euler-lag.gp "$1"
}

spring_energy() {
    # Three periods of the reference spring (w = 10 rad/s), with each integrator.
    for integrator in Euler SymplecticEuler Verlet; do
        copy reference_spring.scene Integrator=SymplecticEuler "Integrator=$integrator" "spring-$integrator.scene"
        plot "$work/spring-$integrator.scene" --quantity energy --component total --duration 1.8849555921538759 \
            --data "$work/spring-energy-$integrator.csv"
    done
    draw 02-spring-energy.gp "$1"
}

bounce_energy() {
    # Straight from `stepwise plot`, as a student would draw it.
    plot config/lesson03_bounce.scene --quantity energy --out "$1" --size 800x450
}

impulse_geometry() {
    "$figures_program" impulse-geometry > "$work/impulse-geometry.dat"
    draw 03-impulse-geometry.gp "$1"
}

end_of_bounce() {
    "$figures_program" bounce-impulses > "$work/bounce-impulses.dat"
    draw 03a-end-of-bounce.gp "$1"
}

dzhanibekov() {
    "$stepwise" run config/lesson04_dzhanibekov.scene --csv "$work/dzhanibekov.csv" > /dev/null
    draw 04-dzhanibekov-flips.gp "$1"
}

sat_axes() {
    "$figures_program" sat-axes > "$work/sat-axes.dat"
    draw 05-sat-axes.gp "$1"
}

clipping() {
    "$figures_program" clipping > "$work/clipping.dat"
    draw 06-clipping.gp "$1"
}

bowling() {
    "$stepwise" run config/lesson07_bowling.scene --csv "$work/bowling.csv" > /dev/null
    draw 07-bowling.gp "$1"
}

warm_starting() {
    copy lesson07_incline.scene "Solver=Impulse" "Solver=Impulse, WarmStarting=false" incline-cold.scene
    for kind in warm cold; do
        scene=config/lesson07_incline.scene
        [[ $kind == cold ]] && scene="$work/incline-cold.scene"
        plot "$scene" --quantity velocity --object sticky --component norm --data "$work/sticky-$kind-speed.csv"
        plot "$scene" --quantity position --object sticky --data "$work/sticky-$kind-position.csv"
    done
    draw 07a-warm-starting.gp "$1"
}

soft_contact() {
    # A ball set down exactly touching the floor, on a soft contact slow enough to watch, with
    # little damping: with the relax pass (the default) and without it (the soft solve alone).
    # The figure's exact curve is drawn for the same frequency and damping ratio.
    local hertz=5 damping=0.2
    cat > "$work/soft-relax.scene" <<EOF
World, Solver=SequentialImpulse, TimeStep=1/60, Duration=1, ContactHertz=$hertz, ContactDampingRatio=$damping, Sleep=false
CollisionPlane, Name=floor, Position=(0, 0, 0), Normal=(0, 1, 0)
DynamicObject, Name=ball, Position=(0, 0.5, 0), Radius=0.5, Mass=1, Elasticity=0, Friction=0
EOF
    sed 's/Sleep=false/Sleep=false, RelaxIterations=0/' "$work/soft-relax.scene" > "$work/soft-bare.scene"
    for kind in relax bare; do
        plot "$work/soft-$kind.scene" --quantity position --component y --data "$work/soft-$kind.csv"
    done
    gnuplot -e "dir='$work'; out='$1'; f=$hertz; zeta=$damping" bench/figures/08-soft-contact.gp
}

waves() {
    "$figures_program" waves 120 > "$work/waves.dat"
    draw 08a-waves.gp "$1"
}

colours() {
    "$figures_program" colours 300 > "$work/colours.dat"
    draw 08a-colours.gp "$1"
}

stability_limit() {
    plot config/stress_spring_edge.scene --quantity position --component x --duration 1 --data "$work/spring-edge.csv"
    plot config/stress_spring_past.scene --quantity position --component x --duration 1 --data "$work/spring-past.csv"
    draw 09-stability-limit.gp "$1"
}

capsule_roll() {
    plot config/lesson12_capsule_ramp.scene --quantity velocity --object capsule,cylinder --component norm \
        --data "$work/capsule-roll.csv"
    draw 12-capsule-roll.gp "$1"
}

terminal_speed() {
    plot config/lesson13_terminal_speed.scene --quantity velocity --object stokes,newton --component norm \
        --data "$work/terminal-speed.csv"
    draw 13-terminal-speed.gp "$1"
}

inflation() {
    # One file per ball: the run's CSV has a row per body and step.
    "$stepwise" run config/lesson14_inflate.scene --csv "$work/inflation.csv" > /dev/null
    for ball in ico ball; do awk -F, -v name="$ball" '$2 == name' "$work/inflation.csv" > "$work/inflation-$ball.csv"; done
    draw 14-inflation.gp "$1"
}

gjk_bounds() {
    "$figures_program" gjk-bounds > "$work/gjk-bounds.dat"
    draw 10-gjk-bounds.gp "$1"
}

mpr_depth() {
    "$figures_program" mpr-depth > "$work/mpr-depth.dat"
    draw 11-mpr-depth.gp "$1"
}

failed=()
for entry in "${figures[@]}"; do
    name=${entry%%:*}
    rm -f "$out/$name"
    # In a subshell of its own, so that the first command that fails ends that figure (bash ignores
    # set -e inside a function called from an `if`), and the other figures are still drawn.
    set +e
    (set -e; "${entry#*:}" "$out/$name")
    status=$?
    set -e
    if [[ $status == 0 && -s "$out/$name" ]]; then
        echo "figures.sh: $out/$name"
    else
        echo "figures.sh: FAILED: $out/$name" >&2
        failed+=("$name")
    fi
done
if [[ ${#failed[@]} -gt 0 ]]; then
    echo "figures.sh: ${#failed[@]} figure(s) not made: ${failed[*]}" >&2
    exit 1
fi
