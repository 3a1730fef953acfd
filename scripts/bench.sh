#!/usr/bin/env bash
# Regenerates docs/benchmarks.md: runs the benchmarks on this machine, draws
# the plots with gnuplot, and writes the tables with the machine, date and
# exact command.
#
#   scripts/bench.sh                 the full sweep, 5 timed repetitions per point
#   scripts/bench.sh --repeats 11    more repetitions (a noisy machine)
#   scripts/bench.sh --scaling       also re-measure the Scaling section and its stage-by-stage table
#                                    (scripts/bench_scaling.sh; about 3 minutes on the page's 2-core machine)
#   scripts/bench.sh --bullet        also re-measure the Side by side with Bullet section (installs Bullet):
#                                    the scenario tables, the rain's run time against overlap, the verdicts
#
# Writes
#   docs/data/precision.csv          every measurement (stepwise-bench precision --csv)
#   docs/images/precision-*.png      one work-precision figure per reference problem, and the energy figure
#   docs/benchmarks.md               the page: how it was made, the figures, the tables,
#                                    the stress suite's table (stepwise-bench stress), and the
#                                    sections of docs/data/bench-*.txt (scripts/bench_scaling.sh).
#                                    The measurement history is docs/performance-history.md,
#                                    written by hand; this script does not touch it.
# Build: the `release` preset (build/release/), target stepwise-bench only.
# Takes under a minute once stepwise-bench is built, on the 2-core Xeon of the page
# (2026-11-26): the precision sweep 17 s (load average 2.5), the stress suite 10.5 s of
# wall and of CPU time (idle, load average 0.1-0.3). With --scaling --bullet, about 8 minutes
# there (12:08-12:15 UTC for the page of 2026-11-26). Setup and build messages go to stderr.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
build_dir=build/release
repeats=5
invocation="scripts/bench.sh${*:+ $*}"  # as typed, for the page's "command" line
extra_runs=()
while [[ $# -gt 0 ]]; do
    case $1 in
        --repeats) repeats=${2:?--repeats needs a number}; shift 2 ;;
        --scaling) extra_runs+=(scaling stage-costs); shift ;;
        --bullet) extra_runs+=(bullet); shift ;;
        -h|--help) sed -n '2,/^[^#]/{/^#/p}' "$0"; exit 0 ;;  # the header above, up to its first line of code
        *) echo "bench.sh: unknown option '$1' (see --help)" >&2; exit 2 ;;
    esac
done

bash scripts/setup.sh >&2
if [[ ! -f "$build_dir/build.ninja" || ! -f "$build_dir/CMakeCache.txt" \
      || CMakePresets.json -nt "$build_dir/CMakeCache.txt" ]]; then
    cmake --preset release >&2
fi
cmake --build --preset release -j "${STEPWISE_JOBS:-2}" --target stepwise-bench >&2

mkdir -p docs/data docs/images
for what in "${extra_runs[@]}"; do bash scripts/bench_scaling.sh --run "$what"; done
tables=$(mktemp)
trap 'rm -f "$tables"' EXIT
command=("$build_dir/bench/stepwise-bench" precision --repeats "$repeats" --csv docs/data/precision.csv
         --markdown "$tables")
echo "bench.sh: ${command[*]}" >&2
"${command[@]}" >&2
gnuplot -e "csv='docs/data/precision.csv'; outdir='docs/images'" bench/plot_precision.gp

# The stress suite: its exit status is 1 when a case fails, and the table says
# which; the page is written all the same, so a failure is published, not hidden.
stress_table=$(mktemp)
trap 'rm -f "$tables" "$stress_table"' EXIT
stress_command=("$build_dir/bench/stepwise-bench" stress --markdown "$stress_table")
echo "bench.sh: ${stress_command[*]}" >&2
stress_start=$SECONDS
stress_status=0
"${stress_command[@]}" >&2 || stress_status=$?
stress_seconds=$((SECONDS - stress_start))
if [[ $stress_status -gt 1 ]]; then echo "bench.sh: stepwise-bench stress could not run" >&2; exit 1; fi

# How it was made: enough to tell two machines' tables apart.
cpu=$(lscpu 2>/dev/null | sed -n 's/^Model name: *//p' | head -1)
cores=$(nproc)
load=$(cut -d' ' -f1-3 /proc/loadavg)
compiler=$(c++ --version | head -1)
commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
if [[ -n $(git status --porcelain -- src bench config 2>/dev/null) ]]; then commit+=" (with uncommitted changes)"; fi
date=$(date -u '+%Y-%m-%d %H:%M UTC')

{
    cat <<EOF
# Benchmarks {#benchmarks}

*This page is written by \`scripts/bench.sh\`; run it again to regenerate it
on your machine (do not edit it by hand). The numbers below are from one
machine on one day: the errors are the same everywhere (they are
deterministic), the nanoseconds are not.*

| | |
|---|---|
| machine | ${cpu:-unknown CPU}, ${cores} cores; load average ${load} at the start (a shared machine: hence medians) |
| date | ${date} |
| commit | ${commit} |
| compiler | ${compiler}, \`release\` preset (-O3, \`Real\` = double) |
| command | \`${invocation}\` (${repeats} timed repetitions per point), which runs \`${command[*]/$tables/TABLES.md}\` and \`gnuplot bench/plot_precision.gp\` |

## Precision: error against time step and work {#benchmarks-precision}

\`stepwise-bench precision\` runs each *reference problem* — a scene in
\`config/reference_*.scene\` with a known exact solution — with every
integrator at the time steps h = 1/30, 1/60, …, 1/1920 s, through the
engine's own \`World::step()\`, and compares the result with the exact
solution (bench/reference_problems.cpp says how each error is measured;
bench/exact_solutions.cpp computes the references). Only \`TimeStep\` and
\`Integrator\` are overridden; open a scene file to see the problem.

How to read a figure (lectures/09-accuracy-and-stability.md explains more):

- **Left, error against h.** Both axes are logarithmic, so an error that
  behaves like C·h^p is a straight line of slope p: the *order* of the
  method. The dashed and dotted guides have slopes 1 and 2. Halving h halves
  a first-order error and quarters a second-order one.
- **Right, error against work** (the work-precision diagram). The work is
  the cost of simulating one second, ns per step ÷ h. The lower-left a
  line runs, the more accuracy per nanosecond. One step costs about the
  same with every integrator here (the step is dominated by the pipeline,
  not by the integrator's few multiplications, although Verlet evaluates
  the forces twice), so the right panel is the left one mirrored: the work
  grows as 1/h, and what separates the integrators is their error.
- Points missing from a line are errors of exactly 0 or runs that could
  not be measured (see the notes under the tables).

Each error is measured once (runs are deterministic); the time per step is
the median of ${repeats} timed runs with nothing but \`World::step()\` in the
loop. Tables: one per quantity, a row per time step, a column per
integrator; \`—\` marks a quantity a run could not measure.

EOF
    # Each problem's figure goes right under its heading.
    awk '{
        print
        if (match($0, /^### [a-z-]+ \{#bench-/)) {
            name = substr($0, 5); sub(/ .*/, "", name)
            png = "docs/images/precision-" name ".png"
            if ((getline line < png) >= 0) {
                close(png)
                printf "\n<img src=\"images/precision-%s.png\" alt=\"%s: error against time step and against work, one line per integrator\" width=\"900\">\n", name, name
            }
        }
    }' "$tables"
    cat <<EOF
**The pendulum's three lines coincide**, and its period error does not
shrink steadily with h. Its rod is a \`DistanceJoint\`, so it runs under
\`Solver=SequentialImpulse\`, where a body that a constraint touches in a
substep ends it at x_n + h_s·v_{n+1} whatever the integrator
(src/integrators/velocity_change_drift.cpp says why). What the tables
measure is the soft joint's error. A soft joint is a spring of
\`JointHertz\` = 60 Hz, which the bob's tension (up to 2 m·g) holds off
its 1 m length (the \`length_error_max\` table above), and a rod ΔL off
has its period off by ΔT/T = ΔL/(2L), a few 10⁻⁵: a floor that smaller
steps do not lower. The period error crosses zero near h = 1/480 s, hence
its dip there (lectures/09-accuracy-and-stability.md, *The pendulum: when
the integrator does not matter*).

## Energy {#benchmarks-energy}

How far each integrator lets a conserved quantity stray: the spring's
amplitude after 10 periods, the largest energy error over 10 orbits, and
over the free box's 20 s. Explicit Euler gains energy on every problem;
its largest energy error is the largest of the three at every h and shrinks
slowly. On the spring it falls from 5·10⁷ times the starting energy at
h = 1/30 s to 0.39 of it at 1/1920 s, on the free box from 1.0 to 0.019,
the last halvings of h dividing it by 2.4 to 2.9 (first order would be 2).
On the circular and the eccentric orbit it is still 0.23 and 0.53 at
1/1920 s (0.87 and 1.2 at 1/30 s), 1.1 to 1.5 times smaller per halving,
and on the eccentric one it grows once (0.91 at 1/120 s, 0.95 at 1/240 s).
Symplectic Euler's energy error is bounded and halves with h on the spring
and the eccentric orbit (first order) but quarters on the circular orbit
and the free box; Verlet's quarters on the spring, the eccentric orbit and
the free box (second order) and falls 16 times per halving on the circular
orbit. On the free box the two symplectic methods share one rotation
scheme (src/integrators/free_rotation.cpp), so their lines coincide.

<img src="images/precision-energy.png" alt="Energy error against time step for the spring, both orbits and the free box" width="900">

The same numbers, and every other measurement, are in
[\`docs/data/precision.csv\`](data/precision.csv) (one row per problem,
integrator, time step and metric).

## Stress suite {#benchmarks-stress}

\`stepwise-bench stress\` pushes the engine where it is weakest and judges
each case against a criterion from physics, not against an earlier run:
deep stacks must stand, a perfectly elastic gas must not gain energy, a
fast ball must not pass through a thin wall, a spring at its stability
limit must stay on its invariant ellipse, a scene moved 10 km away or with
every mass scaled must move as the original does, and random scenes must
never produce a NaN or lose a body through a wall. The elastic gas passes
while losing most of its energy (72 % in 10 s when this was written; the
table has this run's figure) because its criterion, issue #7's, is that the
energy never grows by more than 1 %. It loses it where a sphere is struck by
two others in the same step: the contacts are solved one after the other
(Gauss–Seidel), and one restitution pass cannot give each its bounce at
once (two spheres closing on a third from both sides at 2 m/s lose 64 % of
their energy; lectures/09-accuracy-and-stability.md, *The stress suite*).
bench/stress.cpp lists
every case, its scene and why its criterion is what it is; the scenes are
in \`config/\` (\`stress_*.scene\`, \`lesson08_*.scene\`) except the elastic
gas and the random scenes, which are generated from a seed
(\`src/config/scene_generator.cpp\`, then changed as stress.cpp says).
\`ms/step\` is the wall time of \`World::step()\` per step in one run.

Command: \`${stress_command[*]/$stress_table/STRESS.md}\`; it took ${stress_seconds} s
and exited with status ${stress_status} (1: a case failed).
\`stepwise-bench stress --quick\` (shorter runs, fewer bodies, every case)
is the CTest test \`bench_stress_quick\`.

EOF
    cat "$stress_table"
    # Scaling and Bullet: the tables of their last measurement (docs/data/bench-*.txt).
    bash scripts/bench_scaling.sh --sections
} > docs/benchmarks.md
echo "bench.sh: wrote docs/benchmarks.md, docs/data/precision.csv and docs/images/precision-*.png" >&2
