# Lecture 6, session A: the corners of the falling slab below the floor, on the first contact step.
# Line numbers are those of the commit named in the lecture; check them if the file has changed.
#   interactive:  gdb -x lectures/gdb/06-box-plane.gdb --args build/debug/stepwise run config/lesson06_manifold.scene --steps 10
#   all at once:  gdb -q -batch -x lectures/gdb/06-box-plane.gdb --args build/debug/stepwise run config/lesson06_manifold.scene --steps 10
break box_plane.cpp:53
run
p box.centre
p count
p below[0]@count
finish
p found
frame function stepwise::World::step
p stepCount_
