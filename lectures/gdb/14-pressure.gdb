# Lecture 14, session A: the gas of the icosahedron `ico`, at its first face in step 1 and once it has settled, in step 1200.
# Breakpoints inside a function are named by the code at the line (break-at FILE "TEXT", from
# lectures/gdb/stepwise.py), so they follow the code when lines move; run from the repository root.
#   interactive:  gdb -x lectures/gdb/14-pressure.gdb --args build/debug/stepwise run config/lesson14_inflate.scene --steps 1200
#   all at once:  gdb -q -batch -x lectures/gdb/14-pressure.gdb --args build/debug/stepwise run config/lesson14_inflate.scene --steps 1200
source lectures/gdb/stepwise.py
tbreak-at pressure_forces.cpp "force[f.a] += share;"
run
p body.name
p body.volume
p body.pressure
p f
p areaNormal
p share
break-at soft_step.cpp "requirePositiveVolume(body, where);" if where.step == 1200
continue
p body.name
p body.volume
p body.pressure
p body.nodePositions[0]
p body.position
