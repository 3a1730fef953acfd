# Draws the plots of docs/benchmarks.md from the CSV of `stepwise-bench precision --csv`.
#
#   gnuplot -e "csv='precision.csv'; outdir='docs/images'" bench/plot_precision.gp
#
# (scripts/bench.sh does this.) For each reference problem, one PNG with two
# panels, one line per integrator, both axes logarithmic:
#   left   the problem's primary error against the time step h. On log-log
#          axes an error C*h^p is a straight line of slope p, the order of the
#          method; dashed guides show slopes 1 and 2.
#   right  the same error against the work of simulating one second,
#          ns per step / h (ns per simulated second): the work-precision
#          diagram. A line further down-left is more accurate for the same work.
# And precision-energy.png: how far the energy (or the spring's amplitude)
# strays, against h, for the four problems that conserve it.
# Errors of exactly 0, or NaN (a run that blew up, a flip that never came),
# have no place on a log axis and are left out.

if (!exists("csv")) csv = 'precision.csv'
if (!exists("outdir")) outdir = 'docs/images'

set datafile separator ','
set terminal pngcairo size 1100,500 enhanced font 'DejaVu Sans,11' linewidth 1.5
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set grid xtics ytics mxtics mytics lc rgb '#dddddd'
# The key goes under each panel, so it never hides a line.
set key outside below center horizontal maxrows 2 font ',10'

integrators = 'Euler SymplecticEuler Verlet'
colour(i) = word('#d62728 #1f77b4 #2ca02c', i)
point(i) = word('7 5 9', i) + 0

# Rows of one problem, metric and integrator; the columns are
# problem,integrator,timestep_s,steps,ns_per_step,metric,unit,value.
rows(p, m, i) = sprintf("< awk -F, '$1==\"%s\" && $6==\"%s\" && $2==\"%s\" && $8+0 != 0 && $8 != \"nan\" && $8 != \"-nan\"' '%s'", p, m, i, csv)

# problem, primary metric, what the y axis shows
problems = 'projectile spring kepler-circular kepler-eccentric free-box bounce pendulum'
metric(k) = word('position_error phase_error position_error position_error flip_time_error apex_error_max period_error', k)
ylabel(k) = word('"position error at t = 2 s (m)" "phase error after 10 periods (rad)" "position error after 10 orbits (m)" "position error after 10 orbits (m)" "largest flip-time error (s)" "largest relative apex error" "relative period error over 10 swings"', k)

do for [k = 1:words(problems)] {
    p = word(problems, k)
    set output sprintf('%s/precision-%s.png', outdir, p)
    set multiplot layout 1,2 title sprintf('{/:Bold %s}: error against time step, and against work', p)

    set xlabel 'time step h (s)'
    set ylabel ylabel(k)
    # Slope guides C*h and C*h^2, both through twice symplectic Euler's error at
    # h = 1/30 s (its largest; symplectic Euler is never exact), fanning out to the left.
    stats rows(p, metric(k), 'SymplecticEuler') using 3:(abs($8)) nooutput
    a1 = 2 * STATS_max_y / (1.0/30)
    a2 = 2 * STATS_max_y / (1.0/30)**2
    plot for [i = 1:3] rows(p, metric(k), word(integrators, i)) using 3:(abs($8)) \
             with linespoints lc rgb colour(i) pt point(i) title word(integrators, i), \
         [1.0/1920:1.0/30] a1 * x with lines dt 2 lc rgb '#888888' title 'slope 1 (order 1)', \
         [1.0/1920:1.0/30] a2 * x**2 with lines dt 3 lc rgb '#444444' title 'slope 2 (order 2)'

    set xlabel 'work: ns per simulated second (ns/step / h)'
    plot for [i = 1:3] rows(p, metric(k), word(integrators, i)) using ($5/$3):(abs($8)) \
             with linespoints lc rgb colour(i) pt point(i) title word(integrators, i)
    unset multiplot
}

# Energy: the four problems that conserve it.
set terminal pngcairo size 1100,900 enhanced font 'DejaVu Sans,11' linewidth 1.5
set output sprintf('%s/precision-energy.png', outdir)
energyProblems = 'spring kepler-circular kepler-eccentric free-box'
energyMetric(k) = word('amplitude_error energy_error_max energy_error_max energy_error_max', k)
energyLabel(k) = word('"|amplitude error| after 10 periods" "largest |E - E_0|/|E_0|" "largest |E - E_0|/|E_0|" "largest |E - E_0|/E_0"', k)
set multiplot layout 2,2 title '{/:Bold Energy}: how far each integrator lets a conserved quantity stray'
set xlabel 'time step h (s)'
do for [k = 1:4] {
    p = word(energyProblems, k)
    set title p
    set ylabel energyLabel(k)
    plot for [i = 1:3] rows(p, energyMetric(k), word(integrators, i)) using 3:(abs($8)) \
             with linespoints lc rgb colour(i) pt point(i) title word(integrators, i)
}
unset multiplot
