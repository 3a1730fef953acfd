# Lecture 12: a capsule and a cylinder (r = 0.2 m, a 1 m segment or length) roll down a 20 degree ramp.
# Data: `stepwise plot config/lesson12_capsule_ramp.scene --quantity velocity --object capsule,cylinder
# --component norm --data` in dir/capsule-roll.csv (time, capsule:norm, cylinder:norm).
# The lines are a = g sin(theta) / (1 + I/(m r^2)) with the closed forms the lecture derives:
# I/(m r^2) = (h/2 + 8r/15)/(h + 4r/3) for the capsule, 1/2 for the cylinder, 2/5 for a ball.
load 'bench/figures/style.gp'
set terminal pngcairo size 800,560
set output out
set datafile separator ','
g = 9.81; theta = 20*pi/180; r = 0.2; h = 1.0
kCapsule = (h/2 + 8*r/15)/(h + 4*r/3); kCylinder = 0.5; kBall = 0.4
a(k) = g*sin(theta)/(1 + k)
set multiplot layout 2,1 title "{/:Bold Lecture 12}: rolling down a 20° ramp, h = 1/120 s"
set ylabel 'speed |v| (m/s)'
set format x ''
set key top left
plot dir.'/capsule-roll.csv' every 8 using 1:2 with points pt 7 ps 0.6 lc rgb orange title 'capsule (engine)', \
     dir.'/capsule-roll.csv' every 8 using 1:3 with points pt 5 ps 0.5 lc rgb blue title 'cylinder (engine)', \
     [0:2] a(kCapsule)*x with lines lc rgb orange title sprintf('capsule: a = g sin θ/(1 + %.4f) = %.4f m/s²', kCapsule, a(kCapsule)), \
     [0:2] a(kCylinder)*x with lines lc rgb blue title sprintf('cylinder: a = g sin θ/1.5 = %.4f m/s²', a(kCylinder))
set ylabel 'acceleration |v|/t (m/s²)'
set xlabel 'time t (s)'
set format x '%g'
set yrange [2.2:2.42]
set key bottom right
plot dir.'/capsule-roll.csv' every 4::4 using 1:($2/$1) with points pt 7 ps 0.5 lc rgb orange title 'capsule (engine)', \
     dir.'/capsule-roll.csv' every 4::4 using 1:($3/$1) with points pt 5 ps 0.4 lc rgb blue title 'cylinder (engine)', \
     [0:2] a(kCapsule) with lines lc rgb orange notitle, \
     [0:2] a(kCylinder) with lines lc rgb blue notitle, \
     [0:2] a(kBall) with lines dt 2 lc rgb grey title 'a ball of the same radius: g sin θ/1.4'
unset multiplot
