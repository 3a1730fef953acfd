# Lecture 10: GJK closes in on the distance from both sides. Data: `stepwise-figures gjk-bounds` in
# dir/gjk-bounds.dat, one block per pair of lesson10_gjk.scene at step 1 (spike|table, can|table):
# iteration, simplex points, upper bound |v| and lower bound v.w/|v| (m). The dashed line is the gap
# worked out by hand from the scene, 0.02 - g h^2 = 0.017275 m, the same for both pairs.
load 'bench/figures/style.gp'
set terminal pngcairo size 1000,450
set output out
f = dir.'/gjk-bounds.dat'
gap = 0.02 - 9.81/3600.0  # the spike's; the can's is 19 nm more (its Position is rounded)
set multiplot layout 1,2 title "{/:Bold Lecture 10}: GJK's bounds on the distance, iteration by iteration (lesson10\\_gjk.scene, step 1)"
set xlabel 'iteration (support queries)'
set ylabel 'distance bound (mm)'
set key top right
set title 'upper |v| and lower v·w/|v|, in mm (the first iterations are off the top)'
set yrange [0:60]
set xrange [0.5:*]
plot f index 0 using 1:(1000*$3) with linespoints pt 7 lc rgb orange title 'spike: |v|', \
     f index 0 using 1:(1000*$4) with linespoints pt 6 lc rgb orange dt 2 title 'spike: v·w/|v|', \
     f index 1 using 1:(1000*$3) with linespoints pt 7 lc rgb blue title 'can: |v|', \
     f index 1 using 1:(1000*$4) with linespoints pt 6 lc rgb blue dt 2 title 'can: v·w/|v|', \
     1000*gap with lines lc rgb grey dt 3 lw 2 title 'gap by hand, 17.275 mm'
set title 'how far apart the bounds still are (m, log scale)'
set ylabel 'upper − lower bound (m)'
set logscale y
set format y '10^{%T}'
set yrange [1e-13:1]
plot f index 0 using 1:($3 - $4 > 0 ? $3 - $4 : 1e-13) with linespoints pt 7 lc rgb orange title 'spike (a polytope: exact in a few)', \
     f index 1 using 1:($3 - $4 > 0 ? $3 - $4 : 1e-13) with linespoints pt 7 lc rgb blue title 'can (a curved rim: step by step)', \
     1e-10*gap with lines lc rgb red dt 2 title 'stop: kGjkRelativeTolerance·|v|'
unset multiplot
