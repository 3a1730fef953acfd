# Lecture 3: an off-centre impact, 1 kg against 3 kg, with friction.
# Breakpoints inside a function are named by the code at the line (break-at FILE "TEXT", from
# lectures/gdb/stepwise.py), so they follow the code when lines move; run from the repository root.
#   interactive:  gdb -x lectures/gdb/03-oblique.gdb --args build/debug/stepwise run config/lesson03_collisions.scene
#   all at once:  gdb -q -batch -x lectures/gdb/03-oblique.gdb --args build/debug/stepwise run config/lesson03_collisions.scene
source lectures/gdb/stepwise.py
break-at impulse_resolver.cpp "c.targetSeparation = e * approachAtTouch;" if contact.a == 2
run
p c.b->name
p c.normal
p vn
p e
p c.normalMass
p c.friction
p c.tangentMass
delete 1
tbreak-at impulse_resolver.cpp "for (ContactConstraint& c : constraints) {"
continue
p constraints[0].normalImpulse
p constraints[0].tangentImpulse
p constraints[0].friction * constraints[0].normalImpulse
p bodies.dynamics._M_ptr[2].velocity
p bodies.dynamics._M_ptr[3].velocity
p bodies.dynamics._M_ptr[2].angularVelocity
p bodies.dynamics._M_ptr[3].angularVelocity
