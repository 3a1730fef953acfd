# Lecture 5, session B: the first time an edge-edge axis wins (the wedge on the ridge).
# Line numbers are those of the commit named in the lecture; check them if the file has changed.
#   interactive:  gdb -x lectures/gdb/05-edge-axis.gdb --args build/debug/stepwise run config/lesson05_sat.scene --steps 10
#   all at once:  gdb -q -batch -x lectures/gdb/05-edge-axis.gdb --args build/debug/stepwise run config/lesson05_sat.scene --steps 10
break box_box.cpp:353
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
p found
frame function stepwise::World::step
p stepCount_
