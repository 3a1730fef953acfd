# Lecture 3: an off-centre impact, 1 kg against 3 kg, with friction.
# Line numbers are those of the commit named in the lecture; check them if the file has changed.
#   interactive:  gdb -x lectures/gdb/03-oblique.gdb --args build/debug/stepwise run config/lesson03_collisions.scene
#   all at once:  gdb -q -batch -x lectures/gdb/03-oblique.gdb --args build/debug/stepwise run config/lesson03_collisions.scene
break impulse_resolver.cpp:93 if contact.a == 2
run
p c.b->name
p c.normal
p vn
p e
p c.normalMass
p c.friction
p c.tangentMass
delete 1
tbreak impulse_resolver.cpp:187
continue
p constraints[0].normalImpulse
p constraints[0].tangentImpulse
p constraints[0].friction * constraints[0].normalImpulse
p bodies.dynamics._M_ptr[2].velocity
p bodies.dynamics._M_ptr[3].velocity
p bodies.dynamics._M_ptr[2].angularVelocity
p bodies.dynamics._M_ptr[3].angularVelocity
