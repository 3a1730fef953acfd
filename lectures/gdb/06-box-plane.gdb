# Lecture 6, session A: the corners of the falling slab below the floor, on the first contact step.
# Breakpoints inside a function are named by the code at the line (break-at FILE "TEXT", from
# lectures/gdb/stepwise.py), so they follow the code when lines move; run from the repository root.
#   interactive:  gdb -x lectures/gdb/06-box-plane.gdb --args build/debug/stepwise run config/lesson06_manifold.scene --steps 10
#   all at once:  gdb -q -batch -x lectures/gdb/06-box-plane.gdb --args build/debug/stepwise run config/lesson06_manifold.scene --steps 10
source lectures/gdb/stepwise.py
break-at box_plane.cpp "if (count > kMaxManifoldPoints) {"
run
p box.centre
p count
p below[0]@count
finish
p found
frame function stepwise::World::step
p stepCount_
