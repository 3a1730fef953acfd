# Appendix 3a, session A: the second impact, then the first contact the resting rule stops: the capped
# support, the overlap removal, and the warm start of the steps after it.
# Breakpoints inside a function are named by the code at the line (break-at FILE "TEXT", from
# lectures/gdb/stepwise.py), so they follow the code when lines move; run from the repository root.
#   interactive:  gdb -x lectures/gdb/03a-resting.gdb --args build/debug/stepwise run config/lesson03_bounce.scene
#   all at once:  gdb -q -batch -x lectures/gdb/03a-resting.gdb --args build/debug/stepwise run config/lesson03_bounce.scene
source lectures/gdb/stepwise.py
break-at impulse_resolver.cpp "c.targetSeparation = e * approachAtTouch;"
run
continue
p vn
p depth
p approachAtTouch
p e
p e * approachAtTouch
delete 1
break-at impulse_resolver.cpp "c.targetSeparation = e * approachAtTouch;" if c.resting
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
tbreak-at impulse_resolver.cpp "const std::vector<ContactConstraint>& constraints = workspace.constraints;"
continue
p workspace.supportVelocityChange[0]
p shift[0]
tbreak-at world.cpp "case SolverKind::SequentialImpulse: stepWithSequentialImpulses();" +2
continue
p contactWorkspace_.shift
p dynamics_[0].position
p dynamics_[0].velocity
p contactWorkspace_.previousImpulses
continue
p vn
p depth
p approachAtTouch
tbreak-at impulse_resolver.cpp "for (int pass = 0; pass < iterations; ++pass)"
continue
p constraints[0].normalImpulse
p bodies.dynamics._M_ptr[0].velocity
tbreak-at world.cpp "case SolverKind::SequentialImpulse: stepWithSequentialImpulses();" +2
continue
p contactWorkspace_.previousImpulses
p contactWorkspace_.shift
p dynamics_[0].position
continue
tbreak-at impulse_resolver.cpp "for (int pass = 0; pass < iterations; ++pass)"
continue
p constraints[0].normalImpulse
p bodies.dynamics._M_ptr[0].velocity
