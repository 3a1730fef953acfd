# Lecture 13, session B: the post's torque in step 30 (t = 1/2 s), which turns it further over.
# Breakpoints inside a function are named by the code at the line (break-at FILE "TEXT", from
# lectures/gdb/stepwise.py), so they follow the code when lines move; run from the repository root.
#   interactive:  gdb -x lectures/gdb/13-capsize.gdb --args build/debug/stepwise run config/lesson13_capsize.scene --steps 30
#   all at once:  gdb -q -batch -x lectures/gdb/13-capsize.gdb --args build/debug/stepwise run config/lesson13_capsize.scene --steps 30
source lectures/gdb/stepwise.py
break-at world.cpp "findRegionMembers(plan_.runs(Stage::Broadphase));" if stepCount_ == 29
run
tbreak-at buoyancy.cpp "body.torque += glm::cross(part.centroid - body.position, push);"
continue
p body.orientation
p body.position
p part.volume
p part.centroid
p push
next
p body.torque
finish
p body.torque
p body.acceleration
