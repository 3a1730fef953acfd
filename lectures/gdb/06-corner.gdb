# Lecture 6, session B: the cube balanced on its corner; stop only when exactly one corner is below the floor.
# Line numbers are those of the commit named in the lecture; check them if the file has changed.
#   interactive:  gdb -x lectures/gdb/06-corner.gdb --args build/debug/stepwise run config/lesson06_manifold.scene --steps 10
#   all at once:  gdb -q -batch -x lectures/gdb/06-corner.gdb --args build/debug/stepwise run config/lesson06_manifold.scene --steps 10
break box_plane.cpp:53 if count == 1
run
p box.centre
p below[0]
p oriented.axes
finish
p found.normal
p found.pointCount
p found.points[0]
frame function stepwise::World::step
p stepCount_
