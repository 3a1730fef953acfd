#!/usr/bin/env bash
# The "Scaling" and "Side by side with Bullet" sections of docs/benchmarks.md (issues #6 and #7).
#
#   scripts/bench_scaling.sh --run scaling   runs `stepwise-bench scaling` (build/release; about 2 minutes on the
#                                            page's 2-core machine, one thread) into docs/data/bench-scaling.txt
#   scripts/bench_scaling.sh --run stage-costs  runs `stepwise-bench stage-costs` (build/release; about 1 minute
#                                            there: the 64k rain must settle first) into docs/data/bench-stage-costs.txt
#   scripts/bench_scaling.sh --run bullet    runs `stepwise-bench bullet` (installs Bullet with
#                                            `scripts/setup.sh --with-bullet`, builds build/bullet with
#                                            -DSTEPWISE_WITH_BULLET=ON) into docs/data/bench-bullet.txt
#   scripts/bench_scaling.sh --sections      prints both sections as Markdown, from those three files
#
# `scripts/bench.sh --scaling --bullet` runs all three and rewrites the page; plain
# `scripts/bench.sh` keeps the last measured tables. The data files are Markdown
# kept as .txt so that Doxygen (which reads docs/**/*.md) does not make pages of them.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
scaling_data=docs/data/bench-scaling.txt
bullet_data=docs/data/bench-bullet.txt
stage_costs_data=docs/data/bench-stage-costs.txt
jobs=${STEPWISE_JOBS:-2}

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
    local what=$1 build_dir tables
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
    cmake --build "$build_dir" -j "$jobs" --target stepwise-bench >&2
    local command=("$build_dir/bench/stepwise-bench" "$what" --markdown "$tables")
    # The rain's work-precision sweep also goes to a CSV, for its figure.
    if [[ $what == bullet ]]; then command+=(--sweep-csv docs/data/rain-sweep.csv); fi
    echo "bench_scaling.sh: ${command[*]}" >&2
    local header
    header=$(provenance "${command[*]/$tables/TABLES}")
    "${command[@]}" >&2
    { echo "$header"; echo; cat "$tables"; } > "docs/data/bench-$what.txt"
    if [[ $what == bullet ]]; then
        gnuplot -e "csv='docs/data/rain-sweep.csv'; out='docs/images/rain-work-precision.png'" bench/plot_rain_sweep.gp
    fi
    echo "bench_scaling.sh: wrote docs/data/bench-$what.txt" >&2
}

sections() {
    cat <<'EOF'
## Scaling {#benchmarks-scaling}

`stepwise-bench scaling` (issue #6) runs Stepwise alone on three scenes of
growing size and times `World::step()` step by step:

- **sphere rain**: N spheres of radius 0.5 m (524 kg, elasticity 0.3,
  friction 0.5) dropped from a jittered lattice of 16 layers into a box of
  five planes open at the top, whose floor grows with N (so the pile is as
  deep at 1k as at 64k); bench/sphere_rain_scene.cpp writes it from a seed,
  and `config/bench_sphere_rain_1k.scene` is the 1000-sphere one
  (`stepwise-bench rain-scene --count N --out FILE` writes any other). By
  default a rain runs 240 steps (4 s: the fall and the first settling), not
  the 600 of the side-by-side, so that 64k spheres take minutes of CPU, not
  an hour; the *steps* column says how many each row ran;
- **box-pile** and **pyramids**: the scenes of `stepwise generate`
  (src/config/scene_generator.cpp), 120 steps (2 s, as bench/broadphase).

A step of a good engine costs O(n), so *CPU µs per body per step* should
stay flat as n grows. The time is the process's CPU time per step (median
over the run, the World on one thread: `Threads=1`): the machine is shared, and on it a step's wall-clock time
counts the time other people's compilers held the core (the wall-clock median
is in the table too). The worst overlap is the deepest sphere–sphere or
sphere–plane overlap at any step; *escaped* counts the spheres whose centre
ended behind a plane. First come the broadphase tracker's tables, one per
run as it finishes (`stepwise bench broadphase`, docs/broadphase.md, observed
on one step in 10); then the table of all runs, and under it the cost per
body of each scene from its smallest size to its largest, which is the
issue's question (a scene that falls asleep, like the pyramids, has a median
far below its mean: the mean is then the fair figure).

EOF
    if [[ -f $scaling_data ]]; then cat "$scaling_data"; else
        echo "Not measured yet: run \`scripts/bench_scaling.sh --run scaling\`."; fi
    cat <<'EOF'

### Cost per body, stage by stage {#benchmarks-stage-costs}

The table above times each size in its own run, over the rain's fall and
first settling. `stepwise-bench stage-costs` asks where a growth comes
from, in the state the side-by-side's 600 steps spend most of their time
in: it lets every size fall and settle first (untimed), then steps the
sizes *in turn*, round after round in one process, so that a shared
machine's slow minutes fall on all of them alike, and splits each step by
stage (`World::stageRecords()`, wall clock; the whole step's CPU time is
the last timed row). A ratio near 1 is a stage whose cost per body is flat.
Under it, *arrays* says where the step's data lives: the megabytes of the
bodies, of the narrowphase's contacts and of the contact solver's arrays
(`World::solverFootprint()`; *read by each pass* is the body records and
the batches that every pass walks: with the defaults, 32 a step, a solve
and a relax in each of 16 substeps), beside the processor's caches. The
work per body is the same at every size (contacts per body); what is not
the same is where it is read from. At 1k the arrays a pass reads are half
a megabyte, less than a core's own L2 cache on current processors (1 to
2 MB); from 16k on they are several times more, and every walk fetches
them from the L3 cache shared by the cores, slower per byte and, on a
shared machine, shared with its other users too. That is the growth in
the ratio column, not the algorithm: docs/performance-history.md measures
it for the passes (the fourteenth and seventeenth rounds: the 64k pass with
its records folded into the first 4 096, which then stay in the L2, runs as
fast as the 1k pass), and the other stages are walks of the same kind,
a few operations per body or contact over arrays of the sizes below.

EOF
    if [[ -f $stage_costs_data ]]; then cat "$stage_costs_data"; else
        echo "Not measured yet: run \`scripts/bench_scaling.sh --run stage-costs\`."; fi
    cat <<'EOF'

## Side by side with Bullet {#benchmarks-bullet}

`stepwise-bench bullet` (issue #7; built only with
`-DSTEPWISE_WITH_BULLET=ON`, after `scripts/setup.sh --with-bullet`) loads
each scene file once, builds a Stepwise `World` and a Bullet 3
`btDiscreteDynamicsWorld` from the same `Scene` (bench/bullet/bullet_world.cpp
maps spheres, boxes, planes, mass, inertia, elasticity and friction, springs
and attractors, and a pendulum's rod), steps both with the same h, and
measures both with the same code from their body states
(bench/scenario_metrics.cpp, and for the reference problems the judges of
bench/reference_problems.cpp). The expected values are physics: apexes
e^(2n)·h₀, incline accelerations g·sinθ/(1+k) or g·(sinθ − μ·cosθ), a
constant angular momentum, and the exact solutions of the precision
benchmark's reference problems. The last column is Bullet's figure divided by
Stepwise's, for figures where smaller is better: above 1, Stepwise does better.

The settings on both sides, so that the comparison is fair:

| | Stepwise | Bullet 3.24 (Debian `libbullet-dev`, `btScalar` = float) |
|---|---|---|
| solver | the scene's: `SequentialImpulse` by default (16 substeps, 1 velocity and 1 relax iteration each, the relax solving a ball contact's normal row only (`RelaxBallFriction=false`), soft contacts at 240 Hz, warm starting); the free box, bounce and incline scenes say `Solver=Impulse` (10 iterations); the rain tables add rows for `Substeps=12` (soft contacts then capped at 180 Hz), against the same Bullet run | `btSequentialImpulseConstraintSolver`, 10 iterations, warm starting, split impulse (below 4 cm of penetration), ERP 0.2 |
| step | `World::step()`, h from the scene | `stepSimulation(h, 1, h)`: exactly one step of h |
| broadphase | `Auto` (chooses from the scene) | `btDbvtBroadphase` |
| sleeping | the scene's `Sleep` (default on: still under 0.05 m/s and 0.05 rad/s for 0.5 s); tower and pyramid say `Sleep=false` | `Sleep=false`: `DISABLE_DEACTIVATION` on every body; otherwise Bullet's default (under 0.8 m/s and 1 rad/s for 2 s) |
| restitution | product e_A·e_B; a contact that arrives slower than gravity gives it in a few steps does not bounce | product (`btManifoldResult`); no bounce under `m_restitutionVelocityThreshold`, 0.2 m/s |
| friction | product μ_A·μ_B, two tangent directions | product, clamped to 10; one friction direction, along the sliding velocity (the default solver mode has no second one) |
| inertia | from the shape (hollow spheres ⅔·m·r²) | Stepwise's principal moments, given to `setMassProps` (so hollow spheres match) |
| rotation | angular momentum L is the state: torque-free L is exact | ω is the state, implicit gyroscopic term (Bullet's default since 2.83) |
| continuous collision | speculative contacts (the sweep of each body) | none (Bullet's default) |
| springs, attractors | force generators, integrated by the scene's integrator (SymplecticEuler in the reference tables) | the same force laws, applied before each step in Bullet's pre-tick callback (`setInternalTickCallback`): Bullet has no force generators; it integrates them as SymplecticEuler does, v += h·F/m, then x += h·v |
| pendulum rod | `DistanceJoint` holding the bob's centre: one row, the bob never turns | Bullet has no distance joint: a `btPoint2PointConstraint` at the pivot, so the bob turns with the rod (a compound pendulum, judged against its own period, that of a rod L + I/(m·L) long) |
| threads | one: the benchmark sets `Threads=1` (`onOneThread()`, bench/scenario_metrics.hpp), where a scene's default would give the narrowphase a thread per core | one (the default `btDiscreteDynamicsWorld`) |

Both engines run single-threaded here, and the times are the process's CPU time.

**Run time against error on the rain.** A speed ratio alone compares two
engines at whatever accuracy their defaults buy. The *rain sweep* runs the
1000-sphere rain again with each engine's accuracy knob turned: Stepwise's
`Substeps` (1 to 16; the default 16 is what the tower and the 100:1 stack
need, src/world/world_settings.hpp) and Bullet's solver iterations (5 to 40;
its default is 10). The error is the worst overlap at any step. Read the
figure along a vertical line for accuracy at equal cost, along a horizontal
one for cost at equal accuracy. More iterations do not make Bullet's
overlaps smaller: Bullet lets bodies sink into each other and pushes them
apart afterwards (split impulse, ERP 0.2 of the depth per step), so its
overlap is set by that, not by how well its solver converges. Stepwise's
contacts look ahead (speculative, within 1 cm) and are held through every
substep, so its overlap falls as the substeps grow.

<img src="images/rain-work-precision.png" alt="Sphere rain: CPU time per step against worst overlap, one line per engine, a point per setting" width="800">

**The reference problems in both engines.** The precision benchmark's seven
problems (projectile, spring, both orbits, free box, bounce, pendulum) run in
Bullet too, at h = 1/60, 1/240 and 1/960 s, judged by the same code as the
precision tables. Stepwise runs them with `SymplecticEuler`, the method Bullet
integrates every body with, so that where the two columns differ it is the
engine and not the method; a row per step adds Stepwise's `Verlet`. Where
nothing but the integrator is at work (projectile, spring, orbits) the two
columns agree, as far as Bullet's single precision lets them: at 1/960 s its
rounding over thousands of steps shows in the orbits' energy drift. The free
box tells the two rotations apart: Bullet keeps ω and loses angular momentum
and energy, Stepwise keeps L. The bounce with `SymplecticEuler` is first order
in Stepwise (its own scene uses `Verlet`, whose apexes are exact); Bullet's
apex errors do not shrink with h. The pendulum is where Bullet
is both faster and far less accurate: its pin couples the three rows of the
constraint through the bob's own small inertia (0.001 kg·m² against m·L² =
1 kg·m²), which its 10 iterations do not converge, so the rod stretches and
the swing loses energy; Stepwise's rod is one row, solved in each of its 16
substeps, which is also why its step costs several times Bullet's there.

The scenario tables, the sweep's among them, and the verdicts on the
issue's targets, all from one run:

EOF
    if [[ -f $bullet_data ]]; then cat "$bullet_data"; else
        echo "Not measured yet: run \`scripts/bench_scaling.sh --run bullet\`."; fi
}

case ${1:-} in
    --run)
        case ${2:-} in
            scaling|stage-costs|bullet) run "$2" ;;
            *) echo "bench_scaling.sh: --run needs scaling, stage-costs or bullet" >&2; exit 2 ;;
        esac ;;
    --sections) sections ;;
    *) sed -n '2,/^[^#]/{/^#/p}' "$0"; exit 2 ;;  # the header above, up to its first line of code
esac
