# Lecture 3: the impulse at the off-centre impact of `small` and `big` (config/lesson03_collisions.scene).
# Data: `stepwise-figures impulse-geometry` in dir/impulse-geometry.dat: block 0 the two circles
# (x y radius name), block 1 the arrows (x y dx dy what: velocities from the centres in m/s, impulses
# from the contact point in N*s), block 2 the contact point and its normal n (from A to B).
load 'bench/figures/style.gp'
set terminal pngcairo size 800,500
set output out
f = dir.'/impulse-geometry.dat'
sv = 0.25   # metres of arrow per m/s
sj = 0.3    # metres of arrow per N*s
set title "{/:Bold Lecture 3}: the off-centre impact of small (1 kg) and big (3 kg), seen along z"
set size ratio -1
set xrange [-2.0:1.6]
set yrange [-0.75:1.0]
set xlabel 'x (m)'
set ylabel 'y (m)'
set key top right font ',9' opaque samplen 2
set style arrow 1 head filled size 0.08,20 lw 2 dt 2 lc rgb blue
set style arrow 2 head filled size 0.08,20 lw 2 lc rgb blue
set style arrow 3 head filled size 0.08,20 lw 2 lc rgb red
set style arrow 4 head filled size 0.08,20 lw 2 lc rgb orange
set style arrow 5 head filled size 0.08,20 lw 2 dt 3 lc rgb red
set style arrow 6 nohead lw 1.5 dt 4 lc rgb 'black'
plot f index 0 using 1:2:3 with circles lc rgb grey fs transparent solid 0.12 notitle, \
     f index 0 using 1:($2 + 0.3):4 with labels notitle, \
     f index 1 every ::0::1 using 1:2:($3*sv):($4*sv) with vectors arrowstyle 1 title 'v before', \
     f index 1 every ::2::3 using 1:2:($3*sv):($4*sv) with vectors arrowstyle 2 title 'v after', \
     f index 1 every ::4::4 using 1:2:($3*sj):($4*sj) with vectors arrowstyle 3 title 'j n: normal impulse on B', \
     f index 1 every ::5::5 using 1:2:($3*sj):($4*sj) with vectors arrowstyle 4 title 'friction impulse on B', \
     f index 1 every ::6::6 using 1:2:($3*sj):($4*sj) with vectors arrowstyle 5 title '-J: the same impulse on A', \
     f index 2 using 1:2:($3*0.6):($4*0.6) with vectors arrowstyle 6 title 'normal n, from A to B', \
     f index 2 using 1:2 with points pt 7 ps 1 lc rgb 'black' title 'contact point'
