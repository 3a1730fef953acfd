# Lecture 3: the second impact, then the first contact the resting rule stops, and where it leaves the ball.
# Line numbers are those of the commit named in the lecture; check them if the file has changed.
#   interactive:  gdb -x lectures/gdb/03-resting.gdb --args build/debug/stepwise run config/lesson03_bounce.scene
#   all at once:  gdb -q -batch -x lectures/gdb/03-resting.gdb --args build/debug/stepwise run config/lesson03_bounce.scene
break impulse_resolver.cpp:89
run
continue
p vn
p depth
p approachAtTouch
p e
p e * approachAtTouch
delete 1
break impulse_resolver.cpp:89 if c.resting
continue
p vn
p depth
p approachAtTouch
p -2 * an * h
p e
frame function stepwise::World::step
p stepCount_
p time_
frame 0
tbreak world.cpp:96
continue
p contactWorkspace_.supportVelocityChange
p dynamics_[0].position
p dynamics_[0].velocity
continue
p vn
p depth
p approachAtTouch
