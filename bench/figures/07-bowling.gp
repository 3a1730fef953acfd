# Lecture 7: the bowling balls of config/lesson07_bowling.scene skid, then roll, at 5/7 of their launch speed.
# Data: `stepwise run config/lesson07_bowling.scene --csv` in dir/bowling.csv
# (time,name,px,py,pz,vx,vy,vz,qw,qx,qy,qz,wx,wy,wz). Both balls: R = 0.5 m, v0 = 5 m/s, no spin;
# lane mu = 0.3, oiled mu = 0.1. Lecture 7, section 9: v = v0 - mu g t and wR = 5/2 mu g t until
# t* = 2 v0 / (7 mu g), then both 5/7 v0.
load 'bench/figures/style.gp'
set terminal pngcairo size 800,450
set output out
set datafile separator ','
g = 9.81; v0 = 5.0; R = 0.5
tstar(mu) = 2*v0/(7*mu*g)
v(t, mu) = t < tstar(mu) ? v0 - mu*g*t : 5.0/7*v0
wr(t, mu) = t < tstar(mu) ? 2.5*mu*g*t : 5.0/7*v0
ball(name) = sprintf("< awk -F, '$2 == \"%s\"' '%s/bowling.csv'", name, dir)
set title "{/:Bold Lecture 7}: skidding into rolling; both balls end at 5/7 · 5 m/s = 3.571 m/s"
set xlabel 'time t (s)'
set ylabel 'speed (m/s)'
set xrange [0:2]
set yrange [0:5.2]
set samples 1000
set key below maxrows 2
plot ball('lane') every 6 using 1:6 with points pt 7 ps 0.5 lc rgb blue title 'lane (μ = 0.3): v_x', \
     ball('lane') every 6 using 1:(-$15*R) with points pt 6 ps 0.6 lc rgb blue title 'lane: ωR', \
     ball('oiled') every 6 using 1:6 with points pt 7 ps 0.5 lc rgb purple title 'oiled (μ = 0.1): v_x', \
     ball('oiled') every 6 using 1:(-$15*R) with points pt 6 ps 0.6 lc rgb purple title 'oiled: ωR', \
     v(x, 0.3) with lines lc rgb 'black' dt 2 title 'v_0 - μgt, (5/2)μgt, then 5/7 v_0', \
     wr(x, 0.3) with lines lc rgb 'black' dt 2 notitle, v(x, 0.1) with lines lc rgb 'black' dt 2 notitle, \
     wr(x, 0.1) with lines lc rgb 'black' dt 2 notitle
