# Lecture 5, session A: the first box-box test that finds no separating axis (the crate on the table).
# Breakpoints inside a function are named by the code at the line (break-at FILE "TEXT", from
# lectures/gdb/stepwise.py), so they follow the code when lines move; run from the repository root.
#   interactive:  gdb -x lectures/gdb/05-face-axis.gdb --args build/debug/stepwise run config/lesson05_sat.scene --steps 10
#   all at once:  gdb -q -batch -x lectures/gdb/05-face-axis.gdb --args build/debug/stepwise run config/lesson05_sat.scene --steps 10
source lectures/gdb/stepwise.py
break-at box_box.cpp "const Real tolerance = kFaceBiasAbsolute"
run
p boxA.centre
p boxB.centre
p faceA
p faceB
p edge
p faceA.separation - faceB.separation
finish
finish
p found.normal
p found.pointCount
p found.points
frame function stepwise::World::step
p stepCount_
