#!/usr/bin/env bash
# The sections of docs/benchmarks.md that are measured apart from the precision and stress
# runs: Scaling and its stage-by-stage table (issue #6), threads and continuous collision,
# and the side by side with Bullet (issue #7).
#
#   scripts/bench_scaling.sh --run scaling      runs `stepwise-bench scaling` (build/release, one thread)
#                                               into docs/data/bench-scaling.txt
#   scripts/bench_scaling.sh --run stage-costs  runs `stepwise-bench stage-costs` (build/release; the
#                                               largest rain must settle first) into docs/data/bench-stage-costs.txt
#   scripts/bench_scaling.sh --run threads      runs `stepwise_bench_threads` (build/release; a 4096-sphere
#                                               pile and the pyramid on 1 and 2 threads, and the continuous
#                                               stage alone) into docs/data/bench-threads.txt
#   scripts/bench_scaling.sh --run bullet       runs `stepwise-bench bullet` (installs Bullet with
#                                               `scripts/setup.sh --with-bullet`, builds build/bullet with
#                                               -DSTEPWISE_WITH_BULLET=ON) into docs/data/bench-bullet.txt
#   scripts/bench_scaling.sh --sections         prints the page's sections, short, from those files
#   scripts/bench_scaling.sh --full-tables      prints every table of those files, for the companion
#                                               page docs/data/benchmark-tables.md
#   scripts/bench_scaling.sh --made             prints a table row per data file: when, where, on which
#                                               commit, and how long its run took (for the page's top)
#
# Each data file starts with how it was made: machine, date, commit, command, and how long
# the run took (wall clock), so the time a run takes is measured, not guessed.
# `scripts/bench.sh --scaling` runs scaling, stage-costs and threads, `--bullet` runs bullet,
# and both rewrite the page; plain `scripts/bench.sh` lays out the last measured tables again.
# The data files are Markdown kept as .txt so that Doxygen (which reads docs/**/*.md) does not
# make pages of them.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
scaling_data=docs/data/bench-scaling.txt
stage_costs_data=docs/data/bench-stage-costs.txt
threads_data=docs/data/bench-threads.txt
bullet_data=docs/data/bench-bullet.txt
jobs=${STEPWISE_JOBS:-2}
# The threads run: one pile of 4096 spheres timed while it lands (steps 61-90), 1 and 2 threads,
# then the continuous stage alone among 1k and 4k resting spheres. Its data file says how long it took.
threads_args=(--counts 4096 --threads 1,2 --settle 60 --steps 30 --ccd-counts 1024,4096)

# How a table was made: enough to tell two machines' tables apart.
provenance() {
    local cpu commit
    cpu=$(lscpu 2>/dev/null | sed -n 's/^Model name: *//p' | head -1)
    commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
    if [[ -n $(git status --porcelain -- src bench config 2>/dev/null) ]]; then commit+=" (with uncommitted changes)"; fi
    echo "Measured on ${cpu:-unknown CPU}, $(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg) at the start;"
    echo "$(date -u '+%Y-%m-%d %H:%M UTC'), commit ${commit}, $(c++ --version | head -1), Release (-O3, \`Real\` = double)."
    echo "Command: \`$1\`."
}

run() {
    local what=$1 build_dir tables target
    tables=$(mktemp)
    trap 'rm -f "$tables"' RETURN
    if [[ $what == bullet ]]; then
        bash scripts/setup.sh --with-bullet >&2
        build_dir=build/bullet
        cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release -DSTEPWISE_WITH_BULLET=ON \
              -DSTEPWISE_BUILD_TESTS=OFF -DSTEPWISE_VIEWER=OFF >&2
    else
        bash scripts/setup.sh >&2
        build_dir=build/release
        [[ -f $build_dir/build.ninja ]] || cmake --preset release >&2
    fi
    local command
    if [[ $what == threads ]]; then
        target=stepwise_bench_threads
        command=("$build_dir/bench/threads/stepwise_bench_threads" "${threads_args[@]}")
    else
        target=stepwise-bench
        command=("$build_dir/bench/stepwise-bench" "$what" --markdown "$tables")
        # The rain's work-precision sweep also goes to a CSV, for its figure; so do the
        # per-scene speed ratios and accuracy figures (issue #33), for the lectures' figure.
        if [[ $what == bullet ]]; then
            command+=(--sweep-csv docs/data/rain-sweep.csv --ratios-csv docs/data/bullet-ratios.csv)
        fi
    fi
    cmake --build "$build_dir" -j "$jobs" --target "$target" >&2
    echo "bench_scaling.sh: ${command[*]}" >&2
    local header start
    header=$(provenance "${command[*]/$tables/TABLES}")
    start=$SECONDS
    if [[ $what == threads ]]; then "${command[@]}" > "$tables"; else "${command[@]}" >&2; fi
    { echo "$header"; echo "The run took $((SECONDS - start)) s (wall clock)."; echo; cat "$tables"; } > "docs/data/bench-$what.txt"
    if [[ $what == bullet ]]; then
        gnuplot -e "csv='docs/data/rain-sweep.csv'; out='docs/images/rain-work-precision.png'" bench/plot_rain_sweep.gp
    fi
    echo "bench_scaling.sh: wrote docs/data/bench-$what.txt" >&2
}

# The lines of a data file up to its first blank line: how it was made.
made_of() { sed '/^$/q' "$1"; }

# The blocks of a data file whose bold title (a line starting with **) matches the awk
# regular expression $2; a block runs to the next bold title. With $2 = ALL, everything
# after how the file was made, the text before the first title included.
blocks() {
    awk -v want="$2" '
        !started { if ($0 == "") started = 1; next }   # skip how it was made
        /^\*\*/ { title = $0 }
        want == "ALL" || (title != "" && title ~ want) { print }
    ' "$1"
}

# A row of the page's table of sections measured apart: when, where, on which commit, how long.
made_row() {
    local name=$1 file=$2 cpu when commit took
    if [[ ! -f $file ]]; then echo "| $name | not measured yet | | | |"; return; fi
    cpu=$(sed -n '1s/^Measured on \(.*\), [0-9]* cores,.*/\1/p' "$file")
    when=$(sed -n '2s/^\(.* UTC\), commit .*/\1/p' "$file")
    commit=$(sed -n '2s/^.* UTC, commit \([^,]*\),.*/\1/p' "$file")
    took=$(sed -n 's/^The run took \([0-9]*\) s.*/\1 s/p' "$file")
    echo "| $name | ${when:-—} | ${cpu:-—} | ${commit:-—} | ${took:-—} |"
}

missing() { echo "Not measured yet: run \`scripts/bench_scaling.sh --run $1\`."; }

# The verdict table of the side by side says "the tables above"; on the page they are in
# the companion page instead.
verdicts_here() { sed 's/(computed from the tables above, same run)/(computed from the tables of the same run)/;
                       s/from the tables above;/from the tables of the same run;/'; }

sections() {
    cat <<'EOF'
## Scaling {#benchmarks-scaling}

**What it shows.** Whether the cost of a step per body stays flat as a
scene grows. `stepwise-bench scaling` (issue #6) runs Stepwise alone, on
one thread (`Threads=1`), on three scenes at growing sizes:

- **sphere rain**: spheres dropped from a jittered lattice into a box open
  at the top, whose floor grows with the count, so that the pile is as
  deep at every size (bench/sphere_rain_scene.cpp;
  `config/bench_sphere_rain_1k.scene` is the 1000-sphere one, and
  `stepwise-bench rain-scene --count N --out FILE` writes any other). It
  runs through the fall and the first settling (the *steps* column),
  shorter than the side by side's run so that the largest size takes
  minutes, not an hour;
- **box-pile** and **pyramids**: the scenes of `stepwise generate`
  (src/config/scene_generator.cpp).

**How to read it.** *CPU µs per body per step* should stay flat as the
bodies grow. Times are the process's CPU time per step, the median over
the run: on a shared machine, wall-clock time also counts the time other
programs held the core (the wall-clock median is in the table too). A
scene that falls asleep, like the pyramids, has a median far below its
mean; the mean is then the fair figure. *worst overlap* is the deepest
sphere–sphere or sphere–plane overlap at any step; *escaped* counts the
spheres whose centre ended behind a plane. The broadphase tracker's table
of each run (docs/broadphase.md) is in the
[full tables](data/benchmark-tables.md#tables-broadphase).

EOF
    if [[ -f $scaling_data ]]; then
        made_of "$scaling_data"
        blocks "$scaling_data" '^\*\*(Scaling|Cost per body)\*\*'
    else missing scaling; fi
    cat <<'EOF'

### Cost per body, stage by stage {#benchmarks-stage-costs}

**What it shows.** Where a growth in the cost per body comes from.
`stepwise-bench stage-costs` lets every size of the rain fall and settle
first (untimed), then steps the sizes *in turn*, round after round in one
process, so that a shared machine's slow minutes fall on all sizes alike.
It splits each step by stage (`World::stageRecords()`, wall clock); the
whole step's CPU time is the last timed row.

**How to read it.** A ratio near 1 is a stage whose cost per body is
flat; *contacts per body* is the work per body. The *arrays* table gives
the megabytes of each size's data (`World::solverFootprint()`; *read by
each pass*: the body records and the batches that every pass of the
contact solver walks; *a substep walks*: those, and the records'
arrays that the moves between the passes walk), beside the processor's
caches. Once the arrays a pass reads outgrow a core's own L2 cache, every
pass fetches them again from the slower L3 cache that the cores share: the
cost per body then grows although the work per body does not. Once what a
substep walks outgrows the L3 as well, every substep fetches it again from
main memory, and the solve and relax stages grow most. The
[fourteenth](performance-history.md#history-round-14) and
[seventeenth](performance-history.md#history-round-17) rounds of the
performance history, and [the cost per body on the EPYC](performance-history.md#history-per-body-2026-11-27),
measure this.

EOF
    if [[ -f $stage_costs_data ]]; then cat "$stage_costs_data"; else missing stage-costs; fi
    cat <<'EOF'

## Side by side with Bullet {#benchmarks-bullet}

**What it shows.** How Stepwise compares with a production engine on the
same scenes, judged by physics rather than by an earlier run.
`stepwise-bench bullet` (issue #7) loads each scene file once, builds a
Stepwise `World` and a Bullet 3 `btDiscreteDynamicsWorld` from the same
`Scene` (bench/bullet/bullet_world.cpp), steps both with the same h on one
thread, and measures both with the same code (bench/scenario_metrics.cpp,
and for the reference problems the judges of bench/reference_problems.cpp).
The expected values are physics: the apexes of a bounce, the acceleration
down an incline, a constant angular momentum, and the exact solutions of
the precision problems. It is built only with `-DSTEPWISE_WITH_BULLET=ON`,
after `scripts/setup.sh --with-bullet`; Bullet is never linked into the
engine.

**The verdicts.** Issue #7 set targets for Stepwise against Bullet; the
benchmark computes each verdict from its own run. Every table of that run,
scene by scene, is in the
[full tables](data/benchmark-tables.md#tables-bullet), with the precision
benchmark's reference problems run in both engines.

**The scenes of issue #33**, built as users build levels (default solver
settings), each with its accuracy beside its speed, measured by the same
code in both engines (bench/overlap_depth.cpp, bench/pile_metrics.cpp,
bench/joint_metrics.cpp): the *wall rain* (1k, 4k, 16k spheres into a floor
and walls of static boxes; worst overlap, escapes), the *box pile* (1000
boxes of 0.8 to 1.2 m, turned at random, into static walls; worst box–box
and box–wall overlap by the separating-axis test, escapes, largest speed at
the end), the *chain* (config/bench_chain.scene, 100 links on BallJoints
released horizontal; worst gap between a joint's anchors, stretch, energy)
and the *ragdoll* (config/bench_ragdoll.scene, 20 boxes on Ball and limited
Hinge joints; anchor gap, angle between a hinge's axes, floor overlap, rest).
Static boxes become Bullet static `btBoxShape` bodies, BallJoint a
`btPoint2PointConstraint`, HingeJoint a `btHingeConstraint` with the
scene's limits. The verdicts: every scene at least 2× Bullet's speed and
more accurate on its main figure, and `Threads=2` at least 1.7× as fast as
one on the 16k wall rain and the pile (stepped in turn, wall clock).
`--ratios-csv PATH` writes the per-scene ratios as CSV.

EOF
    if [[ -f $bullet_data ]]; then
        made_of "$bullet_data"
        blocks "$bullet_data" '^\*\*Against the targets' | verdicts_here
    else missing bullet; fi
    cat <<'EOF'

**Run time against error on the rain.** A speed ratio alone compares two
engines at whatever accuracy their defaults buy. The *rain sweep* runs the
1000-sphere rain again with each engine's accuracy knob turned: Stepwise's
`Substeps` and Bullet's solver iterations. The error is the worst overlap
at any step. Read the figure along a vertical line for accuracy at equal
cost, and along a horizontal line for cost at equal accuracy. Stepwise's
contacts look ahead (speculative contacts) and are solved again in every
substep, so its overlap falls as the substeps grow. Bullet lets bodies sink
into each other and pushes them apart afterwards (split impulse), so its
overlap is set by that push, not by how well its solver converges.

<img src="images/rain-work-precision.png" alt="Sphere rain: CPU time per step against worst overlap, one line per engine, a point per setting" width="800">

EOF
    if [[ -f $bullet_data ]]; then blocks "$bullet_data" 'run time against worst overlap'; fi
    cat <<'EOF'

**The settings on both sides**, so that the comparison is fair:

| | Stepwise | Bullet 3 (Debian `libbullet-dev`, `btScalar` = float) |
|---|---|---|
| solver | the scene's: `SequentialImpulse` with the defaults of src/world/world_settings.hpp (substeps, soft contacts, warm starting) unless the scene says otherwise; the free box, bounce and incline scenes say `Solver=Impulse`; the rain tables add rows with fewer substeps against the same Bullet run | `btSequentialImpulseConstraintSolver` with Bullet's defaults: 10 iterations, warm starting, split impulse, ERP 0.2 |
| step | `World::step()`, h from the scene | `stepSimulation(h, 1, h)`: exactly one step of h |
| broadphase | `Auto` (chosen from the scene) | `btDbvtBroadphase` |
| sleeping | the scene's `Sleep`; the tower and the pyramid say `Sleep=false` | off where the scene says `Sleep=false` (`DISABLE_DEACTIVATION`); otherwise Bullet's own |
| restitution, friction | products e_A·e_B and μ_A·μ_B; two friction directions | products; one friction direction, along the sliding velocity |
| inertia | from the shape | Stepwise's principal moments, given to `setMassProps` |
| rotation | angular momentum L is the state: torque-free L is exact | ω is the state, with an implicit gyroscopic term |
| continuous collision | speculative contacts | none (Bullet's default) |
| springs, attractors | force generators, integrated by the scene's integrator | the same force laws, applied before each step in Bullet's pre-tick callback |
| pendulum rod | `DistanceJoint` on the bob's centre: the bob never turns | a `btPoint2PointConstraint` at the pivot (Bullet has no distance joint): the bob turns with the rod, a compound pendulum judged against its own period |
| threads | one (`Threads=1`, `onOneThread()` in bench/scenario_metrics.hpp) | one |

## Threads and continuous collision {#threads-and-continuous-collision}

**What it shows.** What running the narrowphase and the contact passes on several threads gains,
that it does not change the result, and what the continuous-collision
stage costs. `stepwise_bench_threads` (bench/threads/main.cpp) lets a pile
of spheres land and the pyramid of `config/lesson08_pyramid.scene` stand,
then times their steps
with 1 and 2 threads (`Threads=N`; wall clock, medians). A second table
times the continuous stage alone, with fast spheres arriving on a resting
layer: each fast body tested against all others (the old stage, brute
force) against the candidate index (src/collision/continuous_candidates.hpp).

**How to read it.** *identical* says whether the final state is the same,
bit for bit, as with one thread (the tests tagged `[threads]` check it
too). *narrow x* and *step x* are the speed-ups over one thread. *ccd ms*
is the continuous stage's time per step. The `ContinuousCollision=false`
rows time the same scene without that stage: that is another trajectory
(spheres land differently), so *identical* may say NO there. On a shared
machine other programs' load changes the speed-ups more than the code
does; the first measurement, by hand, is in the
[performance history](performance-history.md#history-threads-2026-11-22).

EOF
    if [[ -f $threads_data ]]; then cat "$threads_data"; else missing threads; fi
}

# Every table of the data files, for docs/data/benchmark-tables.md (links from there are relative to docs/data/).
full_tables() {
    cat <<'EOF'
## Scaling: the broadphase tracker, run by run {#tables-broadphase}

Each run of `stepwise-bench scaling` ends with the broadphase tracker's
table (`stepwise bench broadphase`, [docs/broadphase.md](../broadphase.md)),
observed on one step in 10: how many pairs each broadphase tested to find
the same candidates.

EOF
    if [[ -f $scaling_data ]]; then
        made_of "$scaling_data"
        blocks "$scaling_data" '^\*\*Broadphase tracker'
    else missing scaling; fi
    cat <<'EOF'

## Side by side with Bullet: every table {#tables-bullet}

The scenario tables of `stepwise-bench bullet`, the sweep's among them,
and the verdicts, all from one run ([the page](../benchmarks.md#benchmarks-bullet)
says how it is made).

The reference problems of the precision benchmark run in Bullet too.
Stepwise runs them with `SymplecticEuler`, the method Bullet integrates
every body with, so where the two columns differ it is the engine, not the
method; a row per step adds Stepwise's `Verlet`. The free box tells apart
two ways to keep a rotation (Bullet keeps ω, Stepwise keeps L). The
pendulum tells apart two constraints: Stepwise's rod is one row on the
bob's centre, Bullet's pin at the pivot has three rows that meet in the
bob's own small inertia. Lecture 9 (*The same problems in a production
engine*) reads these tables.

EOF
    if [[ -f $bullet_data ]]; then
        made_of "$bullet_data"
        blocks "$bullet_data" ALL
    else missing bullet; fi
}

made() {
    echo "| section | measured | machine | commit | the run took |"
    echo "|---|---|---|---|---:|"
    made_row "[Scaling](#benchmarks-scaling)" "$scaling_data"
    made_row "[stage by stage](#benchmarks-stage-costs)" "$stage_costs_data"
    made_row "[threads](#threads-and-continuous-collision)" "$threads_data"
    made_row "[side by side with Bullet](#benchmarks-bullet)" "$bullet_data"
}

case ${1:-} in
    --run)
        case ${2:-} in
            scaling|stage-costs|threads|bullet) run "$2" ;;
            *) echo "bench_scaling.sh: --run needs scaling, stage-costs, threads or bullet" >&2; exit 2 ;;
        esac ;;
    --sections) sections ;;
    --full-tables) full_tables ;;
    --made) made ;;
    *) sed -n '2,/^[^#]/{/^#/p}' "$0"; exit 2 ;;  # the header above, up to its first line of code
esac
