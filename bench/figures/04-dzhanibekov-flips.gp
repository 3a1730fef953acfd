# Lecture 4: the Dzhanibekov flips of config/lesson04_dzhanibekov.scene, against the exact flip times.
# Data: `stepwise run config/lesson04_dzhanibekov.scene --csv` in dir/dzhanibekov.csv
# (time,name,px,py,pz,vx,vy,vz,qw,qx,qy,qz,wx,wy,wz). The box: 1 x 2 x 3 m, 1 kg, spun at
# w = (0.01, 5, 0) rad/s. The exact flips (lecture 4, "The exact flip times") come from Jacobi's
# elliptic functions: t_n = (2n - 1) K(k)/s; gnuplot's EllipticK takes the modulus k.
load 'bench/figures/style.gp'
set terminal pngcairo size 900,500
set output out
set datafile separator ','
Ix = 13.0/12; Iy = 10.0/12; Iz = 5.0/12; wx = 0.01; wy = 5.0
Lx = Ix*wx; Ly = Iy*wy; L = sqrt(Lx**2 + Ly**2)
E = 0.5*(Ix*wx**2 + Iy*wy**2)
I1 = Iz; I2 = Iy; I3 = Ix   # Landau's labelling, I1 < I2 < I3
s = sqrt((I3 - I2)*(L**2 - 2*E*I1)/(I1*I2*I3))
k = sqrt((I2 - I1)*(2*E*I3 - L**2)/((I3 - I2)*(L**2 - 2*E*I1)))
flip(n) = (2*n - 1)*EllipticK(k)/s
# The body's y axis in the world, R e_y, from the orientation (w, x, y, z) in columns 9-12, along L.
along(qw, qx, qy, qz) = (2*(qx*qy - qw*qz)*Lx + (1 - 2*(qx**2 + qz**2))*Ly)/L
# The angular velocity in the body's frame, R^T w: each body axis (a column of R) dotted with w (columns 13-15).
bodyX(qw, qx, qy, qz, a, b, c) = (1 - 2*(qy**2 + qz**2))*a + 2*(qx*qy + qw*qz)*b + 2*(qx*qz - qw*qy)*c
bodyY(qw, qx, qy, qz, a, b, c) = 2*(qx*qy - qw*qz)*a + (1 - 2*(qx**2 + qz**2))*b + 2*(qy*qz + qw*qx)*c
bodyZ(qw, qx, qy, qz, a, b, c) = 2*(qx*qz + qw*qy)*a + 2*(qy*qz - qw*qx)*b + (1 - 2*(qx**2 + qy**2))*c
set xrange [0:20]
set lmargin 12
set multiplot layout 2,1 title sprintf("{/:Bold Lecture 4}: a box spun about its middle axis turns over (symplectic Euler, h = 1/60 s); exact flips at %.3f, %.3f, %.3f s", flip(1), flip(2), flip(3))
do for [n=1:3] { set arrow n from flip(n), graph 0 to flip(n), graph 1 nohead dt 2 lc rgb 'black' }
set ylabel 'body y axis · L/|L|'
set format x ''
set yrange [-1.15:1.15]
set key at 14.6, -0.3 right samplen 2
plot dir.'/dzhanibekov.csv' using 1:(along($9, $10, $11, $12)) every ::1 with lines lc rgb orange title 'the engine', \
     NaN with lines dt 2 lc rgb 'black' title 'exact flips'
set ylabel 'ω in the body (rad/s)'
set xlabel 'time t (s)'
set format x '%g'
set yrange [-6:6]
set key at 14.6, -1.5 right samplen 2 font ",9"
plot dir.'/dzhanibekov.csv' using 1:(bodyX($9, $10, $11, $12, $13, $14, $15)) every ::1 with lines lc rgb red title 'ω_x (1 m edge)', \
     '' using 1:(bodyY($9, $10, $11, $12, $13, $14, $15)) every ::1 with lines lc rgb green title 'ω_y (middle axis)', \
     '' using 1:(bodyZ($9, $10, $11, $12, $13, $14, $15)) every ::1 with lines lc rgb blue title 'ω_z (3 m edge)'
unset multiplot
