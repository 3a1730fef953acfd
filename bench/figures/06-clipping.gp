# Lecture 6: Sutherland-Hodgman clipping of the incident face by the reference face's four side planes.
# Data: `stepwise-figures clipping` in dir/clipping.dat (lesson05_sat.scene, the crate on the table at
# step 6): blocks 0-4 the incident face and what is left of it after each side plane (closed polygons),
# block 5 the reference face, block 6 the narrowphase's contact points (u v depth). Coordinates (m) along
# the reference face's two axes u and v, from its centre.
load 'bench/figures/style.gp'
set terminal pngcairo size 1100,330
set output out
f = dir.'/clipping.dat'
e = 0.5   # the crate's half edge: the reference face's side planes are u = ±e, v = ±e
set multiplot layout 1,5 title "{/:Bold Lecture 6}: the table's top face (incident) clipped by the crate's bottom face (reference), one side plane at a time"
set size ratio -1
set xrange [-1.9:1.9]
set yrange [-1.9:1.9]
set xtics -1,1,1
set ytics -1,1,1
unset key
set xlabel 'u (m)'
set ylabel 'v (m)' offset 1,0
titles = '"the incident face" "1. cut by u ≤ +e" "2. cut by u ≥ -e" "3. cut by v ≤ +e" "4. cut by v ≥ -e"'
do for [k = 0:4] {
    set title word(titles, k + 1)
    unset arrow
    if (k == 1) { set arrow from  e, -1.9 to  e, 1.9 nohead lc rgb red lw 2 }
    if (k == 2) { set arrow from -e, -1.9 to -e, 1.9 nohead lc rgb red lw 2 }
    if (k == 3) { set arrow from -1.9,  e to 1.9,  e nohead lc rgb red lw 2 }
    if (k == 4) { set arrow from -1.9, -e to 1.9, -e nohead lc rgb red lw 2 }
    if (k == 0) {
        plot f index 5 using 1:2 with lines dt 2 lc rgb orange, \
             f index 0 using 1:2 with filledcurves closed fs transparent solid 0.25 lc rgb blue, \
             f index 0 using 1:2 with linespoints pt 7 ps 0.5 lc rgb blue
    } else {
        if (k < 4) {
            plot f index 5 using 1:2 with lines dt 2 lc rgb orange, \
                 f index k-1 using 1:2 with lines dt 3 lc rgb grey, \
                 f index k using 1:2 with filledcurves closed fs transparent solid 0.25 lc rgb blue, \
                 f index k using 1:2 with linespoints pt 7 ps 0.5 lc rgb blue
        } else {
            plot f index 5 using 1:2 with lines dt 2 lc rgb orange, \
                 f index k-1 using 1:2 with lines dt 3 lc rgb grey, \
                 f index k using 1:2 with filledcurves closed fs transparent solid 0.25 lc rgb blue, \
                 f index k using 1:2 with linespoints pt 7 ps 0.5 lc rgb blue, \
                 f index 6 using 1:2 with points pt 6 ps 1.6 lw 2 lc rgb 'black'
        }
    }
}
unset multiplot
