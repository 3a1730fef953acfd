# Lecture 5: the shadows of two boxes on each of the 15 candidate axes, on the first step they overlap.
# Data: `stepwise-figures sat-axes` in dir/sat-axes.dat, one block per pair (crate on table, wedge on
# ridge): row "label" lowA highA lowB highB separation chosen. Each shadow is the smallest and largest
# projection of the box's 8 corners on the axis, measured from A's centre (m); the separation is the
# gap between the shadows (negative: their overlap); chosen = 2 on the axis the narrowphase chose (its
# contact's feature id names it), 1 on the other axes along the same line.
load 'bench/figures/style.gp'
set terminal pngcairo size 1000,560
set output out
f = dir.'/sat-axes.dat'
set multiplot layout 1,2 title "{/:Bold Lecture 5}: each box's shadow on the 15 axes (A above, B below); the red dot marks the contact's axis"
set yrange [14.7:-0.7]
set xrange [-2.5:4.1]
set xtics -2,1,2
set xlabel 'projection on the axis, from the centre of A (m)'
set grid noytics
set key below horizontal maxcols 2 width -4
do for [pair = 0:1] {
    set title word('"crate (A) on table (B): step 6" "wedge (A) on ridge (B): step 9"', pair + 1)
    plot f index pair using 3:($1 - 0.18):($4 - $3):(0):ytic(2) with vectors nohead lw 6 lc rgb orange title 'A', \
         f index pair using 5:($1 + 0.18):($6 - $5):(0) with vectors nohead lw 6 lc rgb blue title 'B', \
         f index pair using (2.3):1:($8 == 2 ? '' : strcol(7) eq 'nan' ? 'no axis' : sprintf('%+.1f mm', 1000*$7)) with labels left font ',9' notitle, \
         f index pair using ($8 == 2 ? 2.3 : NaN):1:(sprintf('{/:Bold %+.1f mm}', 1000*$7)) with labels left font ',9' textcolor rgb red notitle, \
         f index pair using ($8 == 2 ? -2.35 : NaN):1 with points pt 7 ps 1.2 lc rgb red title 'the axis the narrowphase chose', \
         f index pair using ($8 == 1 ? -2.35 : NaN):1 with points pt 6 ps 1.2 lc rgb red title 'another axis along the same line'
}
unset multiplot
