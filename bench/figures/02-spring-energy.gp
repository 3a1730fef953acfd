# Lecture 2: energy against time for the three integrators on the spring.
# Data: `stepwise plot config/reference_spring.scene --quantity energy --component total --data` for
# copies with Integrator=Euler, SymplecticEuler, Verlet: dir/spring-energy-{Euler,SymplecticEuler,Verlet}.csv
# (time, mass:total). The scene: k = 100 N/m, m = 1 kg (w = 10 rad/s), 0.1 m stretch: E0 = 0.5 J; h = 1/60 s.
load 'bench/figures/style.gp'
set terminal pngcairo size 900,460
set output out
set datafile separator ','
w = 10.0; h = 1.0/60; e0 = 0.5
file(i) = sprintf('%s/spring-energy-%s.csv', dir, word('Euler SymplecticEuler Verlet', i))
name(i) = word('"explicit Euler" "symplectic Euler" "velocity Verlet"', i)
colour(i) = word(red.' '.blue.' '.green, i)
set multiplot layout 1,2 title "{/:Bold Lecture 2}: the spring's energy, h = 1/60 s (hω = 1/6)"
set xlabel "time t (s)"
set xrange [0:1.885]
set ylabel 'E / E_0'
set logscale y
set key below maxrows 2
plot for [i=1:3] file(i) using 1:($2/e0) with lines lc rgb colour(i) title name(i), \
     (1 + (h*w)**2)**(x/h) with lines dt 2 lc rgb 'black' title '(1 + h^2ω^2)^{t/h}'
unset logscale y
# Symplectic Euler keeps v^2 + w^2 x^2 + h w^2 x v constant, so E/E0 stays between 1/(1 + hw/2)
# and 1/(1 - hw/2); velocity Verlet's stays between 1 - (hw)^2/4 and 1.
set ylabel 'E / E_0 - 1'
set key below maxrows 2
set yrange [-0.12:0.12]
plot for [i=2:3] file(i) using 1:($2/e0 - 1) with lines lc rgb colour(i) title name(i), \
     1/(1 - 0.5*h*w) - 1 with lines dt 2 lc rgb blue title '1/(1 ± hω/2) - 1', \
     1/(1 + 0.5*h*w) - 1 with lines dt 2 lc rgb blue notitle, \
     -(h*w)**2/4 with lines dt 2 lc rgb green title '-(hω)^2/4'
unset multiplot
