# Appendix 8a: the fast path's waves of the same contacts in the two orders a pass can take them, in four scenes.
# Data: `stepwise-figures colours` in dir/colours.dat. Block 0, one line per scene: name, round and box
# contacts, waves in the order found (ContactOrder=Found) and in colour order (ContactOrder=Colours),
# contacts in waves wide enough to split between threads (64 batches of 4) in each order, box contacts
# per wave in each order, whether the box contacts go in lanes in each order.
# Blocks 1 to 4, one per scene: wave, its contacts in the order found, its contacts in colour order.
# Both are the engine's scheduleWaves() on the engine's lists; the colour order is its orderByColour(),
# and the program checks that those waves are the colours.
load 'bench/figures/style.gp'
set terminal pngcairo size 1000,700
set output out
f = dir.'/colours.dat'
names = "'the 210-box pyramid' 'the tower of 20 boxes' 'the 1000-box pile' 'the 1000-ball rain'"
split = 256  # kParallelWaveBatches batches of four lanes
set multiplot layout 2,2 spacing 0.1,0.14 title "{/:Bold Appendix 8a}: the fast path's waves at step 300, the same contacts in the two orders of a pass"
set style fill solid 0.7 noborder
set yrange [0:*]
set offsets 0, 0, graph 0.12, 0
set xlabel 'wave (in colour order: colour)'
set ylabel 'contacts'
set key top right font ',9'
do for [s=1:4] {
    stats f index 0 every ::(s-1)::(s-1) using 4 nooutput; found = STATS_max
    stats f index 0 every ::(s-1)::(s-1) using 5 nooutput; colours = STATS_max
    stats f index 0 every ::(s-1)::(s-1) using 6 nooutput; inFound = STATS_max
    stats f index 0 every ::(s-1)::(s-1) using 7 nooutput; inColours = STATS_max
    stats f index 0 every ::(s-1)::(s-1) using ($2 + $3) nooutput; contacts = STATS_max
    stats f index s using 2 nooutput; top = STATS_max
    stats f index s using 3 nooutput; top = STATS_max > top ? STATS_max : top
    unset arrow
    if (top > 0.5*split) { set arrow from graph 0, first split to graph 1, first split nohead dt 2 lc rgb red }
    set title sprintf("%s, %d contacts; in a wave the threads split:\nFound: %d waves, %d contacts; Colours: %d waves, %d", \
                      word(names, s), contacts, found, inFound, colours, inColours) font ',10'
    set xrange [-1:(found > colours ? found : colours)]
    plot f index s using 1:3 with boxes fs solid 0.35 noborder lc rgb green title 'ContactOrder=Colours (waves = colours)', \
         f index s using 1:2 with boxes lc rgb blue title 'ContactOrder=Found', \
         NaN with lines dt 2 lc rgb red title (top > 0.5*split ? '256 contacts: a wave is split' : '')
}
unset multiplot
