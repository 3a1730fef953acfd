# Lecture 14, session A: the gas of the icosahedron `ico`, at its first substep and once it has settled.
# Breakpoints inside a function are named by the code at the line (break-at FILE "TEXT", from
# lectures/gdb/stepwise.py), so they follow the code when lines move; run from the repository root.
#   interactive:  gdb -x lectures/gdb/14-pressure.gdb --args build/debug/stepwise run config/lesson14_inflate.scene --steps 1200
#   all at once:  gdb -q -batch -x lectures/gdb/14-pressure.gdb --args build/debug/stepwise run config/lesson14_inflate.scene --steps 1200
source lectures/gdb/stepwise.py
tbreak-at pressure_forces.cpp "if (body.nRT == 0) return;"
run
p body.name
p body.volume
p body.pressure
p body.faces.size()
break-at soft_step.cpp "addPressureForces(body);" if where.step == 1200 && substep == 7
continue
p body.name
tbreak-at pressure_forces.cpp "if (body.nRT == 0) return;"
continue
p body.volume
p body.pressure
p glm::length(body.nodePositions[0] - body.position)
