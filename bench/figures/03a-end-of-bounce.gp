# Appendix 3a: the end of the bouncing of config/lesson03_bounce.scene, step by step.
# Data: `stepwise-figures bounce-impulses` in dir/bounce-impulses.dat:
# t (end of the step, s), y (m), j (the floor's normal impulse in that step, N*s), resting (1/0).
# The ball: r = 0.1 m, 1 kg, e = 0.8; h = 1/60 s. A resting contact needs m g h a step: the impulse
# that stops one step of falling.
load 'bench/figures/style.gp'
set terminal pngcairo size 800,560
set output out
f = dir.'/bounce-impulses.dat'
m = 1.0; g = 9.81; h = 1.0/60; r = 0.1
set multiplot layout 2,1 title "{/:Bold Appendix 3a}: the last bounces of a ball (e = 0.8), one point per step"
set lmargin 12
set xrange [2.4:4.4]
set ylabel 'lowest point y - r (mm)'
set format x ''
set key top right
plot f using 1:(1000*($2 - r)) with linespoints pt 7 ps 0.4 lc rgb blue title 'height at the end of each step'
set ylabel 'floor impulse j (N·s)'
set xlabel 'time t (s)'
set format x '%g'
set logscale y
set yrange [0.05:3]
plot f using 1:($3 > 0 && $4 == 0 ? $3 : NaN) with impulses lw 3 lc rgb red title 'impact: bounce with e·v_c', \
     f using 1:($3 > 0 && $4 == 1 ? $3 : NaN) with points pt 7 ps 0.5 lc rgb green title 'resting: no bounce', \
     m*g*h with lines dt 2 lc rgb 'black' title sprintf('m g h = %.4f N·s: one step of gravity', m*g*h)
unset multiplot
