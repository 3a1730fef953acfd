# Lecture 7, session A: the first step of the bowling ball lane, in prepare(), in two passes of solve(), and after the passes (kinetic friction).
# Line numbers are those of the commit named in the lecture; check them if the file has changed.
#   interactive:  gdb -x lectures/gdb/07-first-step.gdb --args build/debug/stepwise run config/lesson07_bowling.scene --steps 1
#   all at once:  gdb -q -batch -x lectures/gdb/07-first-step.gdb --args build/debug/stepwise run config/lesson07_bowling.scene --steps 1
set trace-commands on
break impulse_resolver.cpp:95 if contact.a == 0
run
p c.a->name
p c.rA
p vn
p an
p depth
p approachAtTouch
p c.resting
p e
p c.normalMass
p c.tangentMass
p c.friction
set $lane = c.a
delete 1
break impulse_resolver.cpp:135 if c.a == $lane
continue
p relative
p c.normalImpulse
p limit
p magnitude
p c.tangentImpulse
p c.tangent
continue
p relative
p c.normalImpulse
p magnitude
p c.tangentImpulse
delete 2
tbreak impulse_resolver.cpp:186
continue
p constraints[0].normalImpulse
p constraints[0].tangentImpulse
p constraints[0].friction * constraints[0].normalImpulse
p bodies.dynamics._M_ptr[0].velocity
p bodies.dynamics._M_ptr[0].angularVelocity
