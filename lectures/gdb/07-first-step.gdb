# Lecture 7, session A: the first step of the bowling ball lane, in prepare(), in two passes of solve(), and after the passes (kinetic friction).
# Breakpoints inside a function are named by the code at the line (break-at FILE "TEXT", from
# lectures/gdb/stepwise.py), so they follow the code when lines move; run from the repository root.
#   interactive:  gdb -x lectures/gdb/07-first-step.gdb --args build/debug/stepwise run config/lesson07_bowling.scene --steps 1
#   all at once:  gdb -q -batch -x lectures/gdb/07-first-step.gdb --args build/debug/stepwise run config/lesson07_bowling.scene --steps 1
source lectures/gdb/stepwise.py
set trace-commands on
break-at impulse_resolver.cpp "c.targetSeparation = e * approachAtTouch;" if contact.a == 0
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
break-at impulse_resolver.cpp "applyImpulse(c, change);" if c.a == $lane
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
tbreak-at impulse_resolver.cpp "rememberImpulses(contacts, constraints, workspace);"
continue
p constraints[0].normalImpulse
p constraints[0].tangentImpulse
p constraints[0].friction * constraints[0].normalImpulse
p bodies.dynamics._M_ptr[0].velocity
p bodies.dynamics._M_ptr[0].angularVelocity
