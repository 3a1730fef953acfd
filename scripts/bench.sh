#!/usr/bin/env bash
# Regenerates docs/benchmarks.md, the page of current benchmark results, and its companion
# docs/data/benchmark-tables.md, which holds every table in full. It runs the precision, stress
# and narrowphase benchmarks on this machine, draws the plots with gnuplot, and lays out the sections
# that are measured apart (scripts/bench_scaling.sh, docs/data/bench-*.txt). The page's first
# table says on which machine, when, on which commit and with which command it was made, and
# how long each part took.
#
#   scripts/bench.sh                 precision (5 timed repetitions per point) and stress; the
#                                    other sections are laid out again from their last measurement
#   scripts/bench.sh --repeats 11    more repetitions (a noisy machine)
#   scripts/bench.sh --scaling       also re-measure the Scaling section, its stage-by-stage table
#                                    and the threads table (scripts/bench_scaling.sh --run ...)
#   scripts/bench.sh --bullet        also re-measure the side by side with Bullet (installs Bullet):
#                                    the scenario tables, the rain's run time against overlap, the verdicts
#
# Writes
#   docs/data/precision.csv          every precision measurement (stepwise-bench precision --csv)
#   docs/images/precision-*.png      one work-precision figure per reference problem, and the energy figure
#   docs/benchmarks.md               the page: what each benchmark shows, the plots, short tables, how to
#                                    reproduce; under 40 KB (the CTest test docs-benchmarks-page checks it)
#   docs/data/benchmark-tables.md    every table in full: precision, the broadphase tracker, the side by side
# and, with --scaling or --bullet, the docs/data/bench-*.txt files they re-measure.
# The measurement history is docs/performance-history.md, written by hand: this script neither
# reads nor changes it.
# Build: the `release` preset (build/release/), target stepwise-bench only. Setup and build
# messages go to stderr. How long a run takes on your machine: the page's first table says.
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
        --scaling) extra_runs+=(scaling stage-costs threads); shift ;;
        --bullet) extra_runs+=(bullet); shift ;;
        -h|--help) sed -n '2,/^[^#]/{/^#/p}' "$0"; exit 0 ;;  # the header above, up to its first line of code
        *) echo "bench.sh: unknown option '$1' (see --help)" >&2; exit 2 ;;
    esac
done

page=docs/benchmarks.md
companion=docs/data/benchmark-tables.md
csv=docs/data/precision.csv
# The summary table's two time steps (1/60 s: a display frame; 1/960 s: a fine step), as 1/h.
summary_steps="60 960"
# The energy figure's problems and quantities: the same as bench/plot_precision.gp's energyProblems.
energy_quantities="spring:amplitude_error kepler-circular:energy_error_max kepler-eccentric:energy_error_max free-box:energy_error_max"

bash scripts/setup.sh >&2
if [[ ! -f "$build_dir/build.ninja" || ! -f "$build_dir/CMakeCache.txt" \
      || CMakePresets.json -nt "$build_dir/CMakeCache.txt" ]]; then
    cmake --preset release >&2
fi
cmake --build --preset release -j "${STEPWISE_JOBS:-2}" --target stepwise-bench >&2

mkdir -p docs/data docs/images
for what in "${extra_runs[@]}"; do bash scripts/bench_scaling.sh --run "$what"; done
tables=$(mktemp)
stress_table=$(mktemp)
narrowphase_table=$(mktemp)
trap 'rm -f "$tables" "$stress_table" "$narrowphase_table"' EXIT
command=("$build_dir/bench/stepwise-bench" precision --repeats "$repeats" --csv "$csv" --markdown "$tables")
echo "bench.sh: ${command[*]}" >&2
precision_start=$SECONDS
"${command[@]}" >&2
precision_seconds=$((SECONDS - precision_start))
gnuplot -e "csv='$csv'; outdir='docs/images'" bench/plot_precision.gp

# The stress suite: its exit status is 1 when a case fails, and the table says
# which; the page is written all the same, so a failure is published, not hidden.
stress_command=("$build_dir/bench/stepwise-bench" stress --markdown "$stress_table")
echo "bench.sh: ${stress_command[*]}" >&2
stress_start=$SECONDS
stress_status=0
"${stress_command[@]}" >&2 || stress_status=$?
stress_seconds=$((SECONDS - stress_start))
if [[ $stress_status -gt 1 ]]; then echo "bench.sh: stepwise-bench stress could not run" >&2; exit 1; fi

# The narrowphase side by side: the same shape pairs through SAT, GJK+EPA and MPR (a few seconds).
narrowphase_command=("$build_dir/bench/stepwise-bench" narrowphase)
echo "bench.sh: ${narrowphase_command[*]}" >&2
narrowphase_start=$SECONDS
"${narrowphase_command[@]}" > "$narrowphase_table"
narrowphase_seconds=$((SECONDS - narrowphase_start))

# How it was made: enough to tell two machines' tables apart.
cpu=$(lscpu 2>/dev/null | sed -n 's/^Model name: *//p' | head -1)
cores=$(nproc)
load=$(cut -d' ' -f1-3 /proc/loadavg)
compiler=$(c++ --version | head -1)
commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
if [[ -n $(git status --porcelain -- src bench config 2>/dev/null) ]]; then commit+=" (with uncommitted changes)"; fi
date=$(date -u '+%Y-%m-%d %H:%M UTC')

# The headline error of each problem (its first quantity, the one its figure plots) at the
# summary's time steps, and the ns per step, from the CSV: a row per problem and step.
precision_summary() {
    awk -F, -v steps="$summary_steps" '
        function cell(v) { return (v == "" || v ~ /nan/) ? "—" : sprintf("%.2e", v) }
        NR == 1 { next }
        {
            n = sprintf("%.0f", 1 / $3)
            if (!($1 in metric)) { metric[$1] = $6; unit[$1] = $7; problems[++np] = $1 }
            if (!($2 in known)) { known[$2] = 1; integrators[++ni] = $2 }
            if ($6 == metric[$1]) value[$1, $2, n] = $8
            ns[$1, $2, n] = $5
        }
        END {
            printf "| problem | error | h (s) |"
            for (i = 1; i <= ni; ++i) printf " %s |", integrators[i]
            printf "\n|---|---|---|"
            for (i = 1; i <= ni; ++i) printf "---:|"
            printf "\n"
            split(steps, hs, " ")
            for (k = 1; k <= np; ++k) {
                p = problems[k]
                for (j = 1; j in hs; ++j) {
                    if (j == 1) printf "| [%s](#bench-%s) | `%s` (%s) |", p, p, metric[p], unit[p]
                    else printf "| | |"
                    printf " 1/%s |", hs[j]
                    for (i = 1; i <= ni; ++i) printf " %s |", cell(value[p, integrators[i], hs[j]])
                    printf "\n"
                }
                printf "| | ns per step | 1/%s |", hs[1]
                for (i = 1; i <= ni; ++i) {
                    v = ns[p, integrators[i], hs[1]]
                    printf " %s |", v == "" ? "—" : sprintf("%.0f", v)
                }
                printf "\n"
            }
        }' "$csv"
}

# The energy figure's numbers: each quantity at the coarsest and the finest step, and how
# many times smaller it got over the last halving of h.
energy_table() {
    awk -F, -v wanted="$energy_quantities" '
        function cell(v) { return (v == "" || v ~ /nan/) ? "—" : sprintf("%.2e", v) }
        function abs(v) { return v < 0 ? -v : v }
        BEGIN { nw = split(wanted, pairs, " "); for (k = 1; k <= nw; ++k) { split(pairs[k], pm, ":"); want[pm[1]] = pm[2]; order[k] = pm[1] } }
        NR == 1 { next }
        {
            n = sprintf("%.0f", 1 / $3)
            if (!(n in stepSeen)) { stepSeen[n] = 1; steps[++ns] = n + 0 }
            if (!($2 in known)) { known[$2] = 1; integrators[++ni] = $2 }
            if (want[$1] == $6) { value[$1, $2, n] = $8; unit[$1] = $7 }
        }
        END {
            coarse = steps[1]; fine = steps[1]; before = 0
            for (s = 1; s <= ns; ++s) { if (steps[s] < coarse) coarse = steps[s]; if (steps[s] > fine) fine = steps[s] }
            for (s = 1; s <= ns; ++s) if (steps[s] < fine && steps[s] > before) before = steps[s]
            printf "| problem | quantity | integrator | h = 1/%s s | h = 1/%s s | ÷ over the last halving |\n", coarse, fine
            printf "|---|---|---|---:|---:|---:|\n"
            for (k = 1; k <= nw; ++k) {
                p = order[k]
                for (i = 1; i <= ni; ++i) {
                    a = value[p, integrators[i], before]; b = value[p, integrators[i], fine]
                    ratio = (a == "" || b == "" || a ~ /nan/ || b ~ /nan/ || b + 0 == 0) ? "—" : sprintf("%.1f", abs(a) / abs(b))
                    printf "| %s | %s |", i == 1 ? p : "", i == 1 ? "`" want[p] "` (" unit[p] ")" : ""
                    printf " %s | %s | %s | %s |\n", integrators[i], cell(value[p, integrators[i], coarse]), cell(b), ratio
                }
            }
        }' "$csv"
}

# The time steps swept, from the CSV: "1/30 s to 1/1920 s".
step_range=$(awk -F, 'NR > 1 { n = sprintf("%.0f", 1 / $3); if (lo == "" || n + 0 < lo + 0) lo = n; if (n + 0 > hi + 0) hi = n }
                      END { printf "1/%s s to 1/%s s", lo, hi }' "$csv")
problem_count=$(awk -F, 'NR > 1 && !($1 in seen) { seen[$1] = 1; ++n } END { print n + 0 }' "$csv")
# The stress suite's cases that passed, of all.
stress_passed=$(awk -F'|' '/^\| `/ { ++all; gsub(/ /, "", $5); if ($5 == "pass") ++ok } END { printf "%d of %d", ok, all }' "$stress_table")
# The side by side's verdicts: how many of the targets of issues #7 and #33 were met, and which were not.
bullet_data=docs/data/bench-bullet.txt
bullet_verdicts=""
if [[ -f $bullet_data ]]; then
    bullet_verdicts=$(awk -F'|' '
        function judge(verdict, name) {
            gsub(/ /, "", verdict); sub(/^ /, "", name); sub(/ $/, "", name)
            if (verdict == "yes") ++met
            if (verdict == "yes" || verdict == "no") ++all
            if (verdict == "no") missed = missed (missed == "" ? "" : "; ") name
        }
        /^\*\*Against the targets/ { inside = 1; next }
        /^\*\*/ { inside = 0 }
        # Issue #7: | target | measured | met? |. Issue #33: a row per scene,
        # | scene | time | at least 2x? | figure | Stepwise / Bullet | better? | where the step goes |.
        inside && /^\| / && !/^\| (target|scene) / {
            if (NF == 9) { judge($4, $2 ": speed"); judge($7, $2 ": accuracy") }
            else judge($4, $2)
        }
        END { if (all) printf "%d of %d met%s", met, all, missed == "" ? "" : "; not met: " missed }' "$bullet_data")
fi
made_apart=$(bash scripts/bench_scaling.sh --made)
total_seconds=$SECONDS

{
    cat <<EOF
# Benchmarks {#benchmarks}

*This page is written by \`scripts/bench.sh\`: do not edit it by hand, run
the script again. It shows the current results only. Every table in full
is in [data/benchmark-tables.md](data/benchmark-tables.md), and every
precision measurement in [data/precision.csv](data/precision.csv). What was
tried and measured before, with its own dates, is in the
[performance history](performance-history.md). The errors are the same on
every machine (the runs are deterministic); the times are not.*

At a glance:

- [Precision](#benchmarks-precision): ${problem_count} reference problems with known exact
  solutions, each run with every integrator at time steps from ${step_range}.
- [Energy](#benchmarks-energy): how far each integrator lets a conserved quantity stray.
- [Stress suite](#benchmarks-stress): ${stress_passed} cases pass in this run.
- [Narrowphase](#benchmarks-narrowphase): SAT, GJK+EPA and MPR on the same shape pairs, time and iterations.
- [Scaling](#benchmarks-scaling) and [stage by stage](#benchmarks-stage-costs): the cost
  of a step per body from a thousand bodies to tens of thousands.
- [Side by side with Bullet](#benchmarks-bullet): the targets of issues #7 and #33, ${bullet_verdicts:-not measured yet}.
- [Threads and continuous collision](#threads-and-continuous-collision).
- [How to reproduce](#benchmarks-reproduce).

## How this page was made {#benchmarks-made}

| | |
|---|---|
| machine | ${cpu:-unknown CPU}, ${cores} cores; load average ${load} at the start (a shared machine: hence medians) |
| date | ${date} |
| commit | ${commit} |
| compiler | ${compiler}, \`release\` preset (-O3, \`Real\` = double) |
| command | \`${invocation}\` (${repeats} timed repetitions per point) |
| time taken | precision sweep ${precision_seconds} s, stress suite ${stress_seconds} s, narrowphase ${narrowphase_seconds} s; the whole script ${total_seconds} s, setup and build included |

The other sections are measured apart, and re-measured only by
\`scripts/bench.sh --scaling\` and \`--bullet\`; each repeats how it was
made above its tables:

${made_apart}

## Precision: error against time step and work {#benchmarks-precision}

**What it shows.** How accurate each integrator is, and what its accuracy
costs. \`stepwise-bench precision\` runs each *reference problem*, a scene
in \`config/reference_*.scene\` with a known exact solution, with every
integrator at time steps from ${step_range}, through the engine's own
\`World::step()\`, and compares the result with the exact solution
(bench/reference_problems.cpp says how each error is measured;
bench/exact_solutions.cpp computes the exact solutions). Only \`TimeStep\`
and \`Integrator\` are changed; open a scene file to see the problem. Each
error is measured once, since the runs are deterministic; the time per step
is the median of ${repeats} timed runs with nothing but \`World::step()\` in the
loop.

**How to read a figure** (lecture 9, *Accuracy and stability*, explains more):

- **Left, error against h.** Both axes are logarithmic, so an error that
  behaves like C·h^p is a straight line of slope p: the *order* of the
  method. The dashed and dotted guides have slopes 1 and 2. Halving h
  halves a first-order error and quarters a second-order one.
- **Right, error against work**: the cost of simulating one second, ns per
  step ÷ h (the work-precision diagram). The further down and left a line
  runs, the more accuracy per nanosecond. Where every integrator costs
  about the same per step (the *ns per step* rows below), this panel is
  the left one mirrored, and only the errors tell the integrators apart.
- A point missing from a line is an error of exactly 0, or a run that
  could not be measured (\`—\` in the tables).

**The headline error of each problem**, the one its figure plots, at two
time steps, and the cost of a step. Each problem's other quantities, at
every time step, are in the [full tables](data/benchmark-tables.md#tables-precision).

EOF
    precision_summary
    echo
    # Each problem: its heading, what it is (the line under the heading in the tables), its figure.
    awk '
        /^### / {
            print; print ""
            name = substr($0, 5); sub(/ .*/, "", name)
            while ((getline line) > 0 && line == "") {}
            print line; print ""
            png = "docs/images/precision-" name ".png"
            if ((getline probe < png) >= 0) {
                close(png)
                printf "<img src=\"images/precision-%s.png\" alt=\"%s: error against time step and against work, one line per integrator\" width=\"900\">\n\n", name, name
            }
        }' "$tables"
    cat <<EOF
**The pendulum's three lines coincide.** Its rod is a \`DistanceJoint\`, so
it runs under \`Solver=SequentialImpulse\`, where a body that a constraint
touches in a substep ends it at x_n + h_s·v_{n+1} whatever the integrator
(src/dynamics/velocity_change_drift.hpp says why). What it measures is
the soft joint's error: a soft joint is a stiff spring (\`JointHertz\`),
which the bob's tension stretches a little (\`length_error_max\` in the
full tables), and a rod ΔL too long has its period off by ΔT/T = ΔL/(2L).
Smaller steps do not lower that floor, and where the period error changes
sign its line dips (lecture 9, *The pendulum: when the integrator does not
matter*).

## Energy {#benchmarks-energy}

**What it shows.** How far each integrator lets a conserved quantity
stray over a long run: the spring's amplitude after 10 periods, and the
largest energy error over 10 orbits and over the free box's tumbling.

**How to read it.** The figure plots each quantity against h. In the
table, the last column is the error at the second-finest step divided by
the error at the finest: about 2 is first order, about 4 second order, and
less than 2 an error that shrinks more slowly than h. Explicit Euler is not
symplectic: nothing bounds its energy error, which grows with the length
of the run. Symplectic Euler and Verlet keep it bounded. On the free box
the two symplectic methods share one rotation scheme
(src/integrators/free_rotation.cpp), so their rows agree.

<img src="images/precision-energy.png" alt="Energy error against time step for the spring, both orbits and the free box" width="900">

EOF
    energy_table
    cat <<EOF

## Stress suite {#benchmarks-stress}

**What it shows.** Whether the engine holds where it is weakest.
\`stepwise-bench stress\` judges each case against a criterion from
physics, not against an earlier run: deep stacks must stand, a perfectly
elastic gas must keep its energy, a fast ball must not pass through a thin
wall, a spring at its stability limit must stay on its invariant ellipse,
a scene moved far from the origin or with every mass scaled must move as
the original does, and random scenes must never produce a NaN or lose a
body through a wall. bench/stress.cpp lists every case, its scene and why
its criterion is what it is; the scenes are in \`config/\`
(\`stress_*.scene\`, \`lesson08_*.scene\`), except the elastic gas and the
random scenes, which are generated from a seed.

**How to read it.** *measured* is the figure the criterion judges;
*ms/step* is the wall time of \`World::step()\` per step in one run. The
elastic gas's row also gives the Kolmogorov–Smirnov distance of its
energies from Maxwell–Boltzmann's at the end, against the 1 % critical
value: collisions must have spread the start's uniform velocities into
the equilibrium distribution (lecture 9, *The stress suite*).

Command: \`${stress_command[*]/$stress_table/STRESS.md}\`; it exited with
status ${stress_status} (1: a case failed). \`stepwise-bench stress --quick\`
(shorter runs, fewer bodies, every case) is the CTest test
\`bench_stress_quick\`.

EOF
    cat "$stress_table"
    cat <<EOF

## Narrowphase: SAT, GJK+EPA and MPR side by side {#benchmarks-narrowphase}

**What it shows.** What each way of colliding two convex shapes costs on
the same pairs. Boxes can be collided three ways: by the separating axes
of lecture 5 (SAT), by GJK and EPA on their support functions, or by MPR
(lectures 10 and 11); a capsule pair also has its closed form, the
closest points of two segments. Every algorithm gets the same random
poses from one seed, and the contacts column counts the points each
produced (the \`[narrowphase]\` tests hold the three to the same normal,
depth and points).

**How to read it.** *ns/pair* is the median over the timed passes of one
pair test, manifold included; the iteration columns count support queries
(GJK, MPR) and EPA's expansions after its first tetrahedron, mean and
largest. It shows why engines keep SAT for boxes: a box has three face
normals and nine edge crossings to try, and no loop that may run long.

Command: \`${narrowphase_command[*]}\`. \`stepwise-bench narrowphase --quick\`
is the CTest test \`bench_narrowphase_quick\`.

EOF
    grep '^|' "$narrowphase_table"
    echo
    sed -n '/^Iterations/,$p' "$narrowphase_table"
    echo
    bash scripts/bench_scaling.sh --sections
    cat <<'EOF'

## How to reproduce {#benchmarks-reproduce}

```sh
scripts/bench.sh                # precision and stress; the other sections from docs/data/bench-*.txt
scripts/bench.sh --scaling      # also re-measures Scaling, stage by stage, and threads
scripts/bench.sh --bullet       # also re-measures the side by side (installs Bullet, builds build/bullet)
scripts/bench.sh --repeats 11   # more timed repetitions per point, on a noisy machine
```

The table at the top of this page says how long each part took. One part
alone, after a first `scripts/bench.sh` has built `build/release`:

```sh
build/release/bench/stepwise-bench precision --quick --problems spring
build/release/bench/stepwise-bench stress --cases tower,elastic-gas
build/release/bench/stepwise-bench stage-costs --sizes 1000,2000,4000,8000
scripts/bench_scaling.sh --run threads
```

`stepwise-bench --help` lists every option. The script writes this page,
[data/benchmark-tables.md](data/benchmark-tables.md),
[data/precision.csv](data/precision.csv) and the figures in `docs/images/`;
with `--scaling` or `--bullet` it also rewrites the `docs/data/bench-*.txt`
files those sections are laid out from. Commit them together, from one
run. The CTest test `docs-benchmarks-page` (label `docs`) keeps this page
under 40 KB and free of history: what was tried and measured before goes
to [the performance history](performance-history.md).
EOF
} > "$page"

{
    cat <<EOF
# Benchmarks: every table {#benchmark-tables}

*Written by \`scripts/bench.sh\` with [the benchmarks page](../benchmarks.md),
from the same run and the same data files (${date}; commit ${commit}).
Do not edit it by hand. The page says what each benchmark shows and how
to read it.*

## Precision, every quantity at every time step {#tables-precision}

One table per quantity: a row per time step, a column per integrator; \`—\`
marks a quantity a run could not measure. The same numbers are in
[precision.csv](precision.csv), one row per problem, integrator, time step
and quantity.

EOF
    # The page has the #bench-NAME anchors; here each problem is #tables-NAME.
    sed 's/ {#bench-\([a-z-]*\)}$/ {#tables-\1}/' "$tables"
    bash scripts/bench_scaling.sh --full-tables
} > "$companion"
echo "bench.sh: wrote $page ($(wc -c < "$page") bytes), $companion, $csv and docs/images/precision-*.png" >&2
