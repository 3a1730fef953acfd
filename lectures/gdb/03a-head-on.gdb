# Appendix 3a, session B: two equal elastic spheres head on. They touch exactly at t = 1 s, on a step boundary; the depth
# is a hair below zero (round-off), which counts as touching, so the velocities swap in that step.
# Breakpoints inside a function are named by the code at the line (break-at FILE "TEXT", from
# lectures/gdb/stepwise.py), so they follow the code when lines move; run from the repository root.
#   interactive:  gdb -x lectures/gdb/03a-head-on.gdb --args build/debug/stepwise run config/lesson03_collisions.scene
#   all at once:  gdb -q -batch -x lectures/gdb/03a-head-on.gdb --args build/debug/stepwise run config/lesson03_collisions.scene
source lectures/gdb/stepwise.py
break-at impulse_resolver.cpp "c.targetSeparation = e * approachAtTouch;" if contact.b.kind == stepwise::BodyKind::Dynamic && contact.a == 0
run
p contact
p a.name
p c.b->name
p a.velocity
p c.b->velocity
p vn
p an
p approachAtTouch
p e
p c.normalMass
frame function stepwise::World::step
p stepCount_
p time_
p dynamics_[0].position
p dynamics_[1].position
frame 0
p contact.depth < -1e-6
delete 1
finish
until-at impulse_resolver.cpp "for (ContactConstraint& c : constraints) {"
p constraints[0].normalImpulse
p bodies.dynamics._M_ptr[0].velocity
p bodies.dynamics._M_ptr[1].velocity
tbreak-at world.cpp "case SolverKind::SequentialImpulse: stepWithSequentialImpulses();" +2
continue
p contactWorkspace_.shift
p dynamics_[0].position
p dynamics_[1].position
