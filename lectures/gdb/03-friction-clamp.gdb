# Lecture 3, exercise 5: is the friction impulse clamped to mu*j at the first impact?
# Line numbers are those of the commit named in the lecture; check them if the file has changed.
#   interactive:  gdb -x lectures/gdb/03-friction-clamp.gdb --args build/debug/stepwise run /tmp/slide.scene
#   all at once:  gdb -q -batch -x lectures/gdb/03-friction-clamp.gdb --args build/debug/stepwise run /tmp/slide.scene
break impulse_resolver.cpp:93
run
p c.rA
p c.tangentMass
p c.friction
delete 1
tbreak impulse_resolver.cpp:187
continue
p constraints[0].normalImpulse
p constraints[0].tangentImpulse
p constraints[0].friction * constraints[0].normalImpulse
p bodies.dynamics._M_ptr[0].velocity
p bodies.dynamics._M_ptr[0].angularVelocity
