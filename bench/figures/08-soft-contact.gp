# Lecture 8: a soft contact is a spring and a damper.
# Data: `stepwise plot --quantity position --component y --data` of a ball (r = 0.5 m, 1 kg) set down
# touching a floor, with ContactHertz=f and ContactDampingRatio=zeta (scripts/figures.sh writes the
# scene, and gives f and zeta to this script with -e):
# dir/soft-bare.csv with RelaxIterations=0 (the soft solve alone), dir/soft-relax.csv with the default
# relax pass. Lecture 8, section 4: the contact pulls its overlap back like a spring of stiffness
# k = m w^2 and a damper c = 2 zeta m w (w = 2 pi f), so from rest at the surface the ball sinks as
# y - r = -(g/w^2) (1 - e^(-zeta w t) (cos(w_d t) + zeta/sqrt(1 - zeta^2) sin(w_d t))),
# w_d = w sqrt(1 - zeta^2), and comes to rest g/w^2 deep.
load 'bench/figures/style.gp'
set terminal pngcairo size 800,450
set output out
set datafile separator ','
set datafile columnheaders
g = 9.81; r = 0.5
if (!exists('f')) f = 5.0
if (!exists('zeta')) zeta = 0.2
w = 2*pi*f; wd = w*sqrt(1 - zeta**2)
spring(t) = -(g/w**2)*(1 - exp(-zeta*w*t)*(cos(wd*t) + zeta/sqrt(1 - zeta**2)*sin(wd*t)))
set title sprintf("{/:Bold Lecture 8}: a ball set down on a soft contact of %g Hz, ζ = %g, rests g/ω^2 = %.2f mm deep", f, zeta, 1000*g/w**2)
set xlabel 'time t (s)'
set ylabel 'height of its lowest point, y - r (mm)'
set xrange [0:1]
set samples 500
set key below maxrows 2
plot dir.'/soft-bare.csv' using 1:(1000*($2 - r)) with points pt 7 ps 0.5 lc rgb blue title 'the engine, RelaxIterations=0: the soft solve alone', \
     1000*spring(x) with lines lc rgb 'black' dt 2 title 'mass, spring k = mω^2 and damper c = 2ζmω, exactly', \
     dir.'/soft-relax.csv' using 1:(1000*($2 - r)) with points pt 6 ps 0.5 lc rgb red title 'the engine, with the relax pass (the default)', \
     -1000*g/w**2 with lines lc rgb grey dt 3 title 'g/ω^2'
