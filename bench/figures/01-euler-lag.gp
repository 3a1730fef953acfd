# Lecture 1: explicit Euler lags the parabola by g*h*t/2.
# Data: `stepwise plot config/lesson01_explicit_euler.scene --quantity position --component y --data`
# in dir/euler-throw.csv (time, ball:y). The scene: y0 = 10 m, v0y = 4 m/s, h = 1/60 s.
load 'bench/figures/style.gp'
set terminal pngcairo size 800,520
set output out
set datafile separator ','
g = 9.81; y0 = 10.0; v0 = 4.0; h = 1.0/60
exact(t) = y0 + v0*t - 0.5*g*t**2
set multiplot layout 2,1 title "{/:Bold Lecture 1}: explicit Euler throws a ball, h = 1/60 s"
set ylabel 'height y (m)'
set format x ''
set key top right
plot dir.'/euler-throw.csv' every 4 using 1:2 with points pt 7 ps 0.6 lc rgb red title 'explicit Euler, every 4th step', \
     [0:2] exact(x) with lines lc rgb 'black' title 'exact: y_0 + v_0 t - g t^2/2'
set ylabel 'y_{Euler} - y_{exact} (mm)'
set xlabel 'time t (s)'
set format x '%g'
set key top left
plot dir.'/euler-throw.csv' using 1:(1000*($2 - exact($1))) with points pt 7 ps 0.5 lc rgb red title 'the engine''s error', \
     [0:2] 1000*0.5*g*h*x with lines dt 2 lc rgb 'black' title 'g h t / 2: the lag lecture 1 derives'
unset multiplot
