# Lecture 14: two soft balls of 1 kg inflate in empty space, config/lesson14_inflate.scene: the
# icosahedron (12 nodes) and the icosphere of 162 nodes, both of radius 0.5 m, k = 100 N/m, nRT = 40 J.
# Data: `stepwise run config/lesson14_inflate.scene --csv`, its rows of each ball in
# dir/inflation-ico.csv and dir/inflation-ball.csv (time, name, ..., volume in column 16, pressure in 17).
# The dashed lines are where the gas balances the springs under a uniform inflation s:
# 3 nRT = k (s - 1) s sum(L0^2), V = s^3 V0 (lectures/14-soft-bodies-under-pressure.md, section 4),
# with sum(L0^2) and V0 of each mesh.
load 'bench/figures/style.gp'
set terminal pngcairo size 800,450
set output out
set datafile separator ','
k = 100.0; nRT = 40.0
scale(sum) = (1 + sqrt(1 + 12*nRT/(k*sum)))/2
vIco = scale(8.291796)**3 * 0.3170188
vBall = scale(10.796711)**3 * 0.5058806
set title "{/:Bold Lecture 14}: the volume of two soft balls inflating without gravity, h = 1/60 s in 8 substeps"
set xlabel 'time t (s)'
set ylabel 'enclosed volume V (m^3)'
set key bottom right
set xrange [0:20]
plot dir.'/inflation-ico.csv' using 1:16 with lines lc rgb orange title 'icosahedron, 12 nodes (engine)', \
     dir.'/inflation-ball.csv' using 1:16 with lines lc rgb blue title 'icosphere, 162 nodes (engine)', \
     [0:20] vIco with lines dt 2 lc rgb orange title sprintf('s^3 V_0 = %.4f m^3', vIco), \
     [0:20] vBall with lines dt 2 lc rgb blue title sprintf('s^3 V_0 = %.4f m^3', vBall)
