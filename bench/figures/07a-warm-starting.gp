# Appendix 7a: the sticky box of config/lesson07_incline.scene, with and without warm starting.
# Data: `stepwise plot --object sticky --data` of the scene and of a copy with WarmStarting=false:
# dir/sticky-{warm,cold}-speed.csv (time, sticky:norm) and dir/sticky-{warm,cold}-position.csv
# (time, sticky:x, sticky:y, sticky:z).
load 'bench/figures/style.gp'
set terminal pngcairo size 900,420
set output out
set datafile separator ','
set datafile columnheaders
file(kind, what) = sprintf('%s/sticky-%s-%s.csv', dir, kind, what)
# The distance from where the box started: the first row's position, read by stats (X0_min, …).
start(kind, column) = sprintf('stats "%s" every ::0::0 using %d name "S" nooutput', file(kind, 'position'), column)
eval start('warm', 2); wx0 = S_min
eval start('warm', 3); wy0 = S_min
eval start('warm', 4); wz0 = S_min
eval start('cold', 2); cx0 = S_min
eval start('cold', 3); cy0 = S_min
eval start('cold', 4); cz0 = S_min
set multiplot layout 1,2 title "{/:Bold Appendix 7a}: a box that should stick on a 30° slope (μ = 0.8), ten passes a step"
set logscale y
set format y '10^{%L}'
set xlabel 'time t (s)'
set xrange [0:1]
set key below
set ylabel 'speed at the end of the step (m/s)'
set yrange [1e-19:1e-3]
plot file('warm', 'speed') using 1:($2 > 0 ? $2 : NaN) with linespoints pt 7 ps 0.4 lc rgb green title 'warm started (the default)', \
     file('cold', 'speed') using 1:($2 > 0 ? $2 : NaN) with linespoints pt 7 ps 0.4 lc rgb red title 'WarmStarting=false'
set ylabel 'distance from where it started (m)'
set yrange [1e-7:1e-3]
set xrange [0:3]
plot file('warm', 'position') using 1:(d = sqrt(($2-wx0)**2 + ($3-wy0)**2 + ($4-wz0)**2), d > 0 ? d : NaN) with lines lc rgb green title 'warm started', \
     file('cold', 'position') using 1:(d = sqrt(($2-cx0)**2 + ($3-cy0)**2 + ($4-cz0)**2), d > 0 ? d : NaN) with lines lc rgb red title 'WarmStarting=false'
unset multiplot
