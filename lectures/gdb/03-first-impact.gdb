# Lecture 3: the first impact of the bouncing ball, from prepare() to correctPositions().
# Breakpoints inside a function are named by the code at the line (break-at FILE "TEXT", from
# lectures/gdb/stepwise.py), so they follow the code when lines move; run from the repository root.
#   interactive:  gdb -x lectures/gdb/03-first-impact.gdb --args build/debug/stepwise run config/lesson03_bounce.scene
#   all at once:  gdb -q -batch -x lectures/gdb/03-first-impact.gdb --args build/debug/stepwise run config/lesson03_bounce.scene
source lectures/gdb/stepwise.py
break-at impulse_resolver.cpp "c.targetSeparation = e * approachAtTouch;"
run
p contact
p a.velocity
p vn
p an
p depth
p approachAtTouch
p c.resting
p e
frame function stepwise::World::step
p stepCount_
p time_
frame 0
delete 1
break-at impulse_resolver.cpp "applyImpulse(c, (c.normalImpulse - previous) * c.normal);"
continue
p vn
p c.targetSeparation
p c.normalMass
p c.normalImpulse
continue
p vn
p c.normalImpulse
delete 2
break stepwise::correctPositions
continue
p contacts._M_ptr[0].depth
p bodies.dynamics._M_ptr[0].position
p bodies.dynamics._M_ptr[0].velocity
finish
p contactWorkspace_.supportVelocityChange
p contactWorkspace_.shift
p contactWorkspace_.turn
p dynamics_[0].position
p dynamics_[0].velocity
p impulses_[0]
