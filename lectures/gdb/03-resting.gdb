# Lecture 3: the second impact, then the first contact the resting rule stops: the capped support,
# the overlap removal, and the warm start of the steps after it.
# Line numbers are those of the commit named in the lecture; check them if the file has changed.
#   interactive:  gdb -x lectures/gdb/03-resting.gdb --args build/debug/stepwise run config/lesson03_bounce.scene
#   all at once:  gdb -q -batch -x lectures/gdb/03-resting.gdb --args build/debug/stepwise run config/lesson03_bounce.scene
break impulse_resolver.cpp:93
run
continue
p vn
p depth
p approachAtTouch
p e
p e * approachAtTouch
delete 1
break impulse_resolver.cpp:93 if c.resting
continue
p vn
p depth
p approachAtTouch
p stepAcceleration
p 2 * stepAcceleration * h
p e
frame function stepwise::World::step
p stepCount_
p time_
frame 0
tbreak impulse_resolver.cpp:262
continue
p workspace.supportVelocityChange[0]
p shift[0]
tbreak world.cpp:97
continue
p contactWorkspace_.shift
p dynamics_[0].position
p dynamics_[0].velocity
p contactWorkspace_.previousImpulses
continue
p vn
p depth
p approachAtTouch
tbreak impulse_resolver.cpp:181
continue
p constraints[0].normalImpulse
p bodies.dynamics._M_ptr[0].velocity
tbreak world.cpp:97
continue
p contactWorkspace_.previousImpulses
p contactWorkspace_.shift
p dynamics_[0].position
continue
tbreak impulse_resolver.cpp:181
continue
p constraints[0].normalImpulse
p bodies.dynamics._M_ptr[0].velocity
