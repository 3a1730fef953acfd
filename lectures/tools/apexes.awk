# Prints each apex of a bouncing ball from a `stepwise run --csv` trajectory.
#
#   awk -F, -v r=0.1 -f lectures/tools/apexes.awk out.csv
#
# r is the ball's radius (default 0.1 m); the height printed is that of the
# ball's lowest point, y - r. Columns: time,name,px,py,pz,vx,vy,... (one ball).
# An apex is where vy turns from positive to zero or negative; the higher of
# the two samples either side of the turn is printed, so the value can be
# up to g*h^2/8 below the true top of the parabola.
BEGIN { if (r == "") r = 0.1 }
NR > 1 {
    if (previousVy > 0 && $7 <= 0) {
        top = (previousY > $4) ? previousY : $4
        printf "t = %.4f s   apex %.4f m\n", $1, top - r
    }
    previousVy = $7
    previousY = $4
}
