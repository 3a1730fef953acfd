# Appendix 8a: the engine's waves against a greedy colouring of the same contacts, in four scenes.
# Data: `stepwise-figures colours` in dir/colours.dat. Block 0, one line per scene: name, round and
# box contacts, waves, greedy colours, contacts in waves and in greedy colours wide enough to split
# between threads (64 batches of 4), box contacts per wave, whether the box contacts go in lanes.
# Blocks 1 to 4, one per scene: colour, contacts in that wave, contacts in that greedy colour.
# The waves come from the engine's scheduleWaves(); the greedy colouring is the figure program's own.
load 'bench/figures/style.gp'
set terminal pngcairo size 1000,700
set output out
f = dir.'/colours.dat'
names = "'the 210-box pyramid' 'the tower of 20 boxes' 'the 1000-box pile' 'the 1000-ball rain'"
split = 256  # kParallelWaveBatches batches of four lanes
set multiplot layout 2,2 spacing 0.1,0.14 title "{/:Bold Appendix 8a}: contacts per colour at step 300, when the piles have landed: the engine's waves against a greedy colouring"
set style fill solid 0.7 noborder
set yrange [0:*]
set offsets 0, 0, graph 0.12, 0
set xlabel 'colour (wave)'
set ylabel 'contacts'
set key top right font ',9'
do for [s=1:4] {
    stats f index 0 every ::(s-1)::(s-1) using 4 nooutput; waves = STATS_max
    stats f index 0 every ::(s-1)::(s-1) using 5 nooutput; greedy = STATS_max
    stats f index 0 every ::(s-1)::(s-1) using 6 nooutput; inWaves = STATS_max
    stats f index 0 every ::(s-1)::(s-1) using 7 nooutput; inGreedy = STATS_max
    stats f index 0 every ::(s-1)::(s-1) using ($2 + $3) nooutput; contacts = STATS_max
    stats f index s using 2 nooutput; top = STATS_max
    stats f index s using 3 nooutput; top = STATS_max > top ? STATS_max : top
    unset arrow
    if (top > 0.5*split) { set arrow from graph 0, first split to graph 1, first split nohead dt 2 lc rgb red }
    set title sprintf("%s, %d contacts\n%d waves: %d contacts in a split wave; %d greedy colours: %d", \
                      word(names, s), contacts, waves, inWaves, greedy, inGreedy) font ',10'
    set xrange [-1:(waves > greedy ? waves : greedy)]
    plot f index s using 1:3 with boxes fs solid 0.35 noborder lc rgb green title 'greedy colours', \
         f index s using 1:2 with boxes lc rgb blue title 'waves (scheduleWaves)', \
         NaN with lines dt 2 lc rgb red title (top > 0.5*split ? '256 contacts: a wave is split' : '')
}
unset multiplot
