# Lecture 12, session A: the L's mass properties, its principal axes by Jacobi, and its parts moved into them.
# Breakpoints inside a function are named by the code at the line (break-at FILE "TEXT", from
# lectures/gdb/stepwise.py), so they follow the code when lines move; run from the repository root.
#   interactive:  gdb -x lectures/gdb/12-principal-frame.gdb --args build/debug/stepwise run config/lesson12_parts.scene --steps 1
#   all at once:  gdb -q -batch -x lectures/gdb/12-principal-frame.gdb --args build/debug/stepwise run config/lesson12_parts.scene --steps 1
source lectures/gdb/stepwise.py
break-at mass_properties.cpp "frame.axes = principalAxes(mass.inertia).rotation;"
run
p mass.mass
p mass.centre
p mass.inertia
break-at mass_properties.cpp "a = glm::transpose(j) * a * j;"
continue
p p
p q
p apq
p t
p c
p s
next
p a
finish
break-at mass_properties.cpp "compound.boundingRadius = std::max(compound.boundingRadius, partReach(part));"
continue
p part.position
p part.orientation
continue
p part.position
p part.orientation
