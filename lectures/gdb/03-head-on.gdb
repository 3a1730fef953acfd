# Lecture 3: two equal elastic spheres head on. They touch exactly at t = 1 s, on a step boundary; the depth
# is a hair below zero (round-off), which counts as touching, so the velocities swap in that step.
# Line numbers are those of the commit named in the lecture; check them if the file has changed.
#   interactive:  gdb -x lectures/gdb/03-head-on.gdb --args build/debug/stepwise run config/lesson03_collisions.scene
#   all at once:  gdb -q -batch -x lectures/gdb/03-head-on.gdb --args build/debug/stepwise run config/lesson03_collisions.scene
break impulse_resolver.cpp:93 if contact.b.kind == stepwise::BodyKind::Dynamic && contact.a == 0
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
until 187
p constraints[0].normalImpulse
p bodies.dynamics._M_ptr[0].velocity
p bodies.dynamics._M_ptr[1].velocity
tbreak world.cpp:97
continue
p contactWorkspace_.shift
p dynamics_[0].position
p dynamics_[1].position
