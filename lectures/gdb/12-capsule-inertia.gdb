# Lecture 12, session C: the capsule's moments, a cylinder and two hemispheres, and the parallel-axis step.
# Breakpoints inside a function are named by the code at the line (break-at FILE "TEXT", from
# lectures/gdb/stepwise.py), so they follow the code when lines move; run from the repository root.
#   interactive:  gdb -x lectures/gdb/12-capsule-inertia.gdb --args build/debug/stepwise run config/lesson12_capsule_ramp.scene --steps 1
#   all at once:  gdb -q -batch -x lectures/gdb/12-capsule-inertia.gdb --args build/debug/stepwise run config/lesson12_capsule_ramp.scene --steps 1
source lectures/gdb/stepwise.py
break-at mass_properties.cpp "const Real transverse = cylinderMass * kCylinderTransverseFactor * (3 * r2 + height * height) +"
run
p density
p cylinderMass
p hemisphereMass
p axial
p toOwnCentre
p toCapsuleCentre
p hemisphere
finish
