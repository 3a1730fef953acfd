# Lecture 7, session B: step 200 of the bowling scene, lane rolling (static), oiled still sliding (kinetic).
# Line numbers are those of the commit named in the lecture; check them if the file has changed.
#   interactive:  gdb -x lectures/gdb/07-rolling.gdb --args build/debug/stepwise run config/lesson07_bowling.scene --steps 200
#   all at once:  gdb -q -batch -x lectures/gdb/07-rolling.gdb --args build/debug/stepwise run config/lesson07_bowling.scene --steps 200
set trace-commands on
break world.cpp:89 if stepCount_ == 199
run
p time_
delete 1
tbreak impulse_resolver.cpp:186
continue
p constraints[0].a->name
p constraints[0].normalImpulse
p constraints[0].tangentImpulse
p constraints[0].friction * constraints[0].normalImpulse
p constraints[1].a->name
p constraints[1].normalImpulse
p constraints[1].tangentImpulse
p constraints[1].friction * constraints[1].normalImpulse
p bodies.dynamics._M_ptr[0].velocity
p bodies.dynamics._M_ptr[0].angularVelocity
p bodies.dynamics._M_ptr[1].velocity
p bodies.dynamics._M_ptr[1].angularVelocity
