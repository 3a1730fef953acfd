# Appendix 3a, "Check it against physics": the head-on pair touches to round-off at t = 1 s; the broadphase's
# grown boxes still see it.
# Breakpoints inside a function are named by the code at the line (break-at FILE "TEXT", from
# lectures/gdb/stepwise.py), so they follow the code when lines move; run from the repository root.
#   interactive:  gdb -x lectures/gdb/03a-broadphase.gdb --args build/debug/stepwise run config/lesson03_collisions.scene
#   all at once:  gdb -q -batch -x lectures/gdb/03a-broadphase.gdb --args build/debug/stepwise run config/lesson03_collisions.scene
source lectures/gdb/stepwise.py
break-at world.cpp "// 5. Which of them do, where, and how deep?" if stepCount_ == 119
run
p pairs_
p dynamics_[1].position.x - dynamics_[0].position.x
p broadphase_.boxes_[0].max.x
p broadphase_.boxes_[1].min.x
