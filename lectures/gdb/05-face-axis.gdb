# Lecture 5, session A: the first box-box test that finds no separating axis (the crate on the table).
# Line numbers are those of the commit named in the lecture; check them if the file has changed.
#   interactive:  gdb -x lectures/gdb/05-face-axis.gdb --args build/debug/stepwise run config/lesson05_sat.scene --steps 10
#   all at once:  gdb -q -batch -x lectures/gdb/05-face-axis.gdb --args build/debug/stepwise run config/lesson05_sat.scene --steps 10
break box_box.cpp:349
run
p boxA.centre
p boxB.centre
p faceA
p faceB
p edge
p faceA.separation - faceB.separation
finish
p found.normal
p found.pointCount
p found.points
frame function stepwise::World::step
p stepCount_
