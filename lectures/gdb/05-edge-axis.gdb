# Lecture 5, session B: the first time an edge-edge axis wins (the wedge on the ridge).
# Breakpoints inside a function are named by the code at the line (break-at FILE "TEXT", from
# lectures/gdb/stepwise.py), so they follow the code when lines move; run from the repository root.
#   interactive:  gdb -x lectures/gdb/05-edge-axis.gdb --args build/debug/stepwise run config/lesson05_sat.scene --steps 10
#   all at once:  gdb -q -batch -x lectures/gdb/05-edge-axis.gdb --args build/debug/stepwise run config/lesson05_sat.scene --steps 10
source lectures/gdb/stepwise.py
break-at box_box.cpp "return edgeContact(a, b, edge, out);"
run
p boxA.centre
p faceA
p faceB
p edge
p tolerance
p kFaceBiasRelative * face.separation + tolerance
step
next 4
p edgeOfA
p edgeOfB
p fromA
p toA
p fromB
p toB
finish
finish
finish
p found
frame function stepwise::World::step
p stepCount_
