# Lecture 7, session C: step 60 of the incline, prepare() for the solid ball, then both balls' totals after the passes (static friction).
# Breakpoints inside a function are named by the code at the line (break-at FILE "TEXT", from
# lectures/gdb/stepwise.py), so they follow the code when lines move; run from the repository root.
#   interactive:  gdb -x lectures/gdb/07-incline.gdb --args build/debug/stepwise run config/lesson07_incline.scene --steps 60
#   all at once:  gdb -q -batch -x lectures/gdb/07-incline.gdb --args build/debug/stepwise run config/lesson07_incline.scene --steps 60
source lectures/gdb/stepwise.py
set trace-commands on
break-at world.cpp "resolveImpulses(bodies(), contacts_, h, settings_.impulseIterations" if stepCount_ == 59
run
delete 1
break-at impulse_resolver.cpp "c.targetSeparation = e * approachAtTouch;" if contact.a == 0
continue
p c.normal
p c.rA
p vn
p approachAtTouch
p c.resting
p c.normalMass
p c.tangentMass
p c.tangent
delete 2
tbreak-at impulse_resolver.cpp "rememberImpulses(contacts, constraints, workspace);"
continue
p constraints._M_impl._M_finish - constraints._M_impl._M_start
p constraints[0].a->name
p constraints[0].normalImpulse
p constraints[0].tangentImpulse
p constraints[0].friction * constraints[0].normalImpulse
p constraints[1].a->name
p constraints[1].normalImpulse
p constraints[1].tangentImpulse
p constraints[1].friction * constraints[1].normalImpulse
