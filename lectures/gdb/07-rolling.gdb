# Lecture 7, session B: step 200 of the bowling scene, lane rolling (static), oiled still sliding (kinetic).
# Breakpoints inside a function are named by the code at the line (break-at FILE "TEXT", from
# lectures/gdb/stepwise.py), so they follow the code when lines move; run from the repository root.
#   interactive:  gdb -x lectures/gdb/07-rolling.gdb --args build/debug/stepwise run config/lesson07_bowling.scene --steps 200
#   all at once:  gdb -q -batch -x lectures/gdb/07-rolling.gdb --args build/debug/stepwise run config/lesson07_bowling.scene --steps 200
source lectures/gdb/stepwise.py
set trace-commands on
break-at world.cpp "resolveImpulses(bodies(), contacts_, h, settings_.impulseIterations" if stepCount_ == 199
run
p time_
delete 1
tbreak-at impulse_resolver.cpp "rememberImpulses(contacts, constraints, workspace);"
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
