# Lecture 6, session B: the cube balanced on its corner; stop only when exactly one corner is below the floor.
# Breakpoints inside a function are named by the code at the line (break-at FILE "TEXT", from
# lectures/gdb/stepwise.py), so they follow the code when lines move; run from the repository root.
#   interactive:  gdb -x lectures/gdb/06-corner.gdb --args build/debug/stepwise run config/lesson06_manifold.scene --steps 10
#   all at once:  gdb -q -batch -x lectures/gdb/06-corner.gdb --args build/debug/stepwise run config/lesson06_manifold.scene --steps 10
source lectures/gdb/stepwise.py
break-at box_plane.cpp "if (count > kMaxManifoldPoints) {" if count == 1
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
