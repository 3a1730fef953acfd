# Lecture 3: the head-on pair touches to round-off at t = 1 s; the broadphase's grown boxes still see it.
# Line numbers are those of the commit named in the lecture; check them if the file has changed.
#   interactive:  gdb -x lectures/gdb/03-broadphase.gdb --args build/debug/stepwise run config/lesson03_collisions.scene
#   all at once:  gdb -q -batch -x lectures/gdb/03-broadphase.gdb --args build/debug/stepwise run config/lesson03_collisions.scene
break world.cpp:84 if stepCount_ == 119
run
p pairs_
p dynamics_[1].position.x - dynamics_[0].position.x
p broadphase_.boxes_[0].max.x
p broadphase_.boxes_[1].min.x
