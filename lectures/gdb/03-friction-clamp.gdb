# Lecture 3, exercise 5: is the friction impulse clamped to mu*j at the first impact?
# Breakpoints inside a function are named by the code at the line (break-at FILE "TEXT", from
# lectures/gdb/stepwise.py), so they follow the code when lines move; run from the repository root.
#   scene copy:  sed 's#0, 1.1, 0,  0, 0, 0,#0, 1.1, 0,  2, 0, 0,#; s#Name=ball#Name=ball, Friction=0.05#' config/lesson03_bounce.scene > /tmp/slide.scene
#   interactive:  gdb -x lectures/gdb/03-friction-clamp.gdb --args build/debug/stepwise run /tmp/slide.scene
#   all at once:  gdb -q -batch -x lectures/gdb/03-friction-clamp.gdb --args build/debug/stepwise run /tmp/slide.scene
source lectures/gdb/stepwise.py
break-at impulse_resolver.cpp "c.targetSeparation = e * approachAtTouch;"
run
p c.rA
p c.tangentMass
p c.friction
delete 1
tbreak-at impulse_resolver.cpp "for (ContactConstraint& c : constraints) {"
continue
p constraints[0].normalImpulse
p constraints[0].tangentImpulse
p constraints[0].friction * constraints[0].normalImpulse
p bodies.dynamics._M_ptr[0].velocity
p bodies.dynamics._M_ptr[0].angularVelocity
