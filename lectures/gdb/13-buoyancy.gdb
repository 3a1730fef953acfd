# Lecture 13, session A: Archimedes' push and torque on the raft, in step 20 (t = 1/3 s), as it rights itself.
# Breakpoints inside a function are named by the code at the line (break-at FILE "TEXT", from
# lectures/gdb/stepwise.py), so they follow the code when lines move; run from the repository root.
#   interactive:  gdb -x lectures/gdb/13-buoyancy.gdb --args build/debug/stepwise run config/lesson13_boat.scene --steps 20
#   all at once:  gdb -q -batch -x lectures/gdb/13-buoyancy.gdb --args build/debug/stepwise run config/lesson13_boat.scene --steps 20
source lectures/gdb/stepwise.py
break-at world.cpp "findRegionMembers(plan_.runs(Stage::Broadphase));" if stepCount_ == 19
run
tbreak-at buoyancy.cpp "body.torque += glm::cross(part.centroid - body.position, push);"
continue
p body.name
p body.position
p part.volume
p part.centroid
p push
next
p body.torque
finish
p body.torque
p body.acceleration
