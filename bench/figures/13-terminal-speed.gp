# Lecture 13: two balls of 1 kg fall from rest through still fluid, one under linear drag
# (c = 2 N s/m), one under quadratic drag (c = 0.1 kg/m), config/lesson13_terminal_speed.scene.
# Data: `stepwise plot config/lesson13_terminal_speed.scene --quantity velocity --object stokes,newton
# --component norm --data` in dir/terminal-speed.csv (time, stokes:norm, newton:norm).
# The lines are the closed forms of m dv/dt = m g - F_drag from rest:
# v_t (1 - exp(-c t/m)) with v_t = m g/c, and v_t tanh(g t/v_t) with v_t = sqrt(m g/c).
load 'bench/figures/style.gp'
set terminal pngcairo size 800,560
set output out
set datafile separator ','
g = 9.81; m = 1.0; cLin = 2.0; cQuad = 0.1
vLin = m*g/cLin; vQuad = sqrt(m*g/cQuad)
linear(t) = vLin*(1 - exp(-cLin*t/m))
quadratic(t) = vQuad*tanh(g*t/vQuad)
set multiplot layout 2,1 title "{/:Bold Lecture 13}: falling from rest through a fluid, h = 1/60 s"
set ylabel 'speed |v| (m/s)'
set format x ''
set key bottom right
plot dir.'/terminal-speed.csv' every 6 using 1:2 with points pt 7 ps 0.6 lc rgb orange title 'linear drag (engine)', \
     dir.'/terminal-speed.csv' every 6 using 1:3 with points pt 5 ps 0.5 lc rgb blue title 'quadratic drag (engine)', \
     [0:4] linear(x) with lines lc rgb orange title sprintf('v_t (1 - e^{-ct/m}), v_t = mg/c = %.3f m/s', vLin), \
     [0:4] quadratic(x) with lines lc rgb blue title sprintf('v_t tanh(gt/v_t), v_t = sqrt(mg/c) = %.3f m/s', vQuad), \
     [0:4] vLin with lines dt 2 lc rgb grey notitle, \
     [0:4] vQuad with lines dt 2 lc rgb grey notitle
set ylabel 'engine / closed form - 1'
set xlabel 'time t (s)'
set format x '%g'
set format y '%.0e'
set key top right
plot dir.'/terminal-speed.csv' every 2::2 using 1:($2/linear($1) - 1) with points pt 7 ps 0.4 lc rgb orange title 'linear', \
     dir.'/terminal-speed.csv' every 2::2 using 1:($3/quadratic($1) - 1) with points pt 5 ps 0.4 lc rgb blue title 'quadratic', \
     [0:4] 0 with lines lc rgb grey notitle
unset multiplot
