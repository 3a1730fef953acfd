# Lecture 3, exercise: bounce with -v_n instead of v_c, without recompiling (add --csv out.csv to see the apexes).
# Breakpoints inside a function are named by the code at the line (break-at FILE "TEXT", from
# lectures/gdb/stepwise.py), so they follow the code when lines move; run from the repository root.
#   your copy:  /tmp/my_bounce.scene, from lecture 3's exercises (cp config/lesson03_bounce.scene /tmp/my_bounce.scene, elasticity 1)
#   interactive:  gdb -x lectures/gdb/03-minus-vn.gdb --args build/debug/stepwise run /tmp/my_bounce.scene
#   all at once:  gdb -q -batch -x lectures/gdb/03-minus-vn.gdb --args build/debug/stepwise run /tmp/my_bounce.scene
source lectures/gdb/stepwise.py
break-at impulse_resolver.cpp "c.resting = approachAtTouch <=" if vn < 0
commands
silent
set var approachAtTouch = -vn
continue
end
run
