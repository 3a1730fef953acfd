# Draws docs/images/rain-work-precision.png from the CSV of
# `stepwise-bench bullet --scenarios rain-sweep --sweep-csv PATH`.
#
#   gnuplot -e "csv='docs/data/rain-sweep.csv'; out='docs/images/rain-work-precision.png'" bench/plot_rain_sweep.gp
#
# (scripts/bench_scaling.sh --run bullet does this.) Run time against error for
# the 1000-sphere rain: x is the CPU time of a step, y the worst overlap of two
# spheres (or a sphere and a wall) at any step, both logarithmic. One line per
# engine, one point per setting of the knob that is meant to buy accuracy with
# time (Stepwise's Substeps, Bullet's solver iterations), each point labelled
# with its setting. A point further down-left is more accurate for the same
# time; the dashed line is the issue's target of 5 mm.

if (!exists("csv")) csv = 'docs/data/rain-sweep.csv'
if (!exists("out")) out = 'docs/images/rain-work-precision.png'

set datafile separator ','
set terminal pngcairo size 900,560 enhanced font 'DejaVu Sans,11' linewidth 1.5
set output out
set logscale xy
set grid xtics ytics mxtics mytics lc rgb '#dddddd'
set xlabel 'CPU time per step (ms), median of the run'
set ylabel 'worst overlap at any step (mm)'
set title 'Sphere rain, 1000 spheres: run time against worst overlap'
set key top right
set offsets graph 0.08, graph 0.08, graph 0.15, graph 0.15

# Column 1 is the engine, 2 the setting ("Substeps=4"), 3 ms/step, 4 overlap in mm, 5 default (1/0).
engine(name) = sprintf('< grep "^%s," %s', name, csv)
plot engine('Stepwise') using 3:4 with linespoints pt 7 ps 1.2 lc rgb '#1f77b4' title 'Stepwise (Substeps 1, 2, 4, 8, 10, 12, 16)', \
     ''                 using 3:4:(strcol(2)[10:]) with labels offset char 1.2,char 0.8 font ',9' tc rgb '#1f77b4' notitle, \
     engine('Bullet')   using 3:4 with linespoints pt 5 ps 1.2 lc rgb '#d62728' title 'Bullet 3.24 (iterations 5, 10, 20, 40)', \
     ''                 using 3:4:(strcol(2)[12:]) with labels offset char 0,char 1.0 font ',9' tc rgb '#d62728' notitle, \
     5 with lines dt 2 lc rgb '#555555' title 'target: 5 mm'
