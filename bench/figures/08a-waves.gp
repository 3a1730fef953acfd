# Appendix 8a: the waves of the fast path, in the 1000-ball rain (config/bench_sphere_rain_1k.scene).
# Data: `stepwise-figures waves` in dir/waves.dat: wave, contacts, batches, full batches. The engine's
# batchRoundContacts() takes the round contacts in the order the pass does (colour by colour, the
# default ContactOrder), puts each in the first wave after every earlier contact of either of its
# balls (so each wave is a colour), and packs each wave four contacts to a batch.
load 'bench/figures/style.gp'
set terminal pngcairo size 800,420
set output out
f = dir.'/waves.dat'
stats f using 2 name 'C' nooutput
stats f using 3 name 'B' nooutput
set title sprintf("{/:Bold Appendix 8a}: one step of the 1000-ball rain, %d round contacts\n%d waves, %d batches of 4 lanes, %.0f %% of the lanes used", C_sum, C_records, B_sum, 100.0*C_sum/(4*B_sum))
set xlabel 'wave (in the colour order: colour)'
set ylabel 'contacts in the wave'
set style fill solid 0.6 border -1
set boxwidth 0.8
set yrange [0:*]
set offsets 0, 0, graph 0.25, 0
set xrange [-1:C_records]
set key top right
plot f using 1:(4*$3) with boxes fs solid 0.3 lc rgb red title 'lanes of its batches, their number above (4 a batch): the red tip is empty', \
     f using 1:2 with boxes lc rgb blue title 'contacts', \
     f using 1:(4*$3):(sprintf('%d', $3)) with labels offset 0,0.8 font ',9' notitle
