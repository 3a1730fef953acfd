# Lecture 9: a spring just inside and just past symplectic Euler's stability limit h w = 2.
# Data: `stepwise plot --quantity position --component x --data` of config/stress_spring_edge.scene
# (k = 13000 N/m: h w = 1.90) and config/stress_spring_past.scene (k = 16000 N/m: h w = 2.11):
# dir/spring-{edge,past}.csv (time, ball:x). Both: m = 1 kg, rest length 1 m, 0.05 m stretch, h = 1/60 s.
# Lecture 9, "Stability": past the limit one eigenvalue of the step is -(c + sqrt(c^2 - 1)) with
# c = (h w)^2/2 - 1, so the swing grows by |lambda| every step; inside it the swing stays on an
# ellipse whose largest stretch is 0.05 / sqrt(1 - (h w)^2/4). The analysis is linear: it holds while
# the stretch is small beside the rest length. Past 1 m the ball swings through the anchor (the spring's
# length is |x|) and the growth stalls, until the swing dwarfs the rest length and |lambda| returns:
# the second dashed line has that slope and passes through the last point.
load 'bench/figures/style.gp'
set terminal pngcairo size 800,450
set output out
set datafile separator ','
set datafile columnheaders
h = 1.0/60; u0 = 0.05
hw(k) = h*sqrt(k)
growth(k) = (hw(k)**2/2 - 1) + sqrt((hw(k)**2/2 - 1)**2 - 1)
largest(k) = u0/sqrt(1 - hw(k)**2/4)
stats dir.'/spring-past.csv' using (abs(abs($2) - 1)) name 'LAST' nooutput
last = LAST_max
set title sprintf("{/:Bold Lecture 9}: symplectic Euler on a spring, h = 1/60 s; past hω = 2 the swing grows ×%.3f a step", growth(16000))
set xlabel 'step n'
set ylabel '| length - rest length | of the spring (m)'
set logscale y
set format y '10^{%L}'
set xrange [0:60]
set yrange [1e-4:1e14]
set key top left
plot dir.'/spring-past.csv' using ($1/h):(abs(abs($2) - 1)) with linespoints pt 7 ps 0.5 lc rgb red title sprintf('k = 16000 N/m, hω = %.2f', hw(16000)), \
     u0*growth(16000)**x with lines dt 2 lc rgb 'black' title '0.05 m · |λ|^n', \
     last*growth(16000)**(x - 60) with lines dt 2 lc rgb 'black' notitle, \
     dir.'/spring-edge.csv' using ($1/h):(abs(abs($2) - 1)) with linespoints pt 7 ps 0.5 lc rgb blue title sprintf('k = 13000 N/m, hω = %.2f', hw(13000)), \
     largest(13000) with lines dt 3 lc rgb blue title '0.05 m / sqrt(1 - (hω)^2/4)'
