# Lecture 11: where MPR's answer differs from the least overlap. Data: `stepwise-figures mpr-depth`
# in dir/mpr-depth.dat: a 0.4 x 0.2 x 0.4 m box sunk 5 cm into a 2 x 1 x 2 m table, slid along x;
# columns x, least overlap by hand, SAT depth and normal y, EPA depth and normal y, MPR depth and
# normal y, and MPR's depth by hand (the face its ray from the centres leaves A - B by).
load 'bench/figures/style.gp'
set terminal pngcairo size 1000,450
set output out
f = dir.'/mpr-depth.dat'
set multiplot layout 1,2 title "{/:Bold Lecture 11}: a box sunk 5 cm into a table and slid past its edge (x = 1 m)"
set xlabel 'centre of the box, x (m)'
set xrange [0.8:1.2]
set key bottom left
set title 'depth (mm)'
set ylabel 'depth (mm)'
set yrange [0:110]
plot f using 1:(1000*$2) with lines lw 6 lc rgb '#cccccc' title 'least overlap by hand', \
     f using 1:(1000*$3) with lines lw 2 lc rgb green title 'SAT', \
     f using 1:(1000*$5) with lines lw 2 lc rgb orange dt 2 title 'GJK+EPA', \
     f using 1:(1000*$7) with lines lw 2 lc rgb red title 'MPR', \
     f using 1:(1000*$9) every 8 with points pt 6 lc rgb red title 'MPR by hand (the face its ray leaves by)'
set title 'the normal: its y component (−1 = straight down into the table)'
set key left center
set ylabel 'normal y'
set yrange [-1.1:0.1]
plot f using 1:4 with lines lw 6 lc rgb '#cccccc' title 'SAT', \
     f using 1:6 with lines lw 2 lc rgb orange dt 2 title 'GJK+EPA', \
     f using 1:8 with lines lw 2 lc rgb red title 'MPR'
unset multiplot
