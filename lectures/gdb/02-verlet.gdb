# Lecture 2, session A: velocity Verlet and its second call of the force model.
# Breakpoints inside a function are named by the code at the line (break-at FILE "TEXT", from
# lectures/gdb/stepwise.py), so they follow the code when lines move; run from the repository root.
#   interactive:  gdb -x lectures/gdb/02-verlet.gdb --args build/debug/stepwise run config/lesson02_verlet.scene
#   all at once:  gdb -q -batch -x lectures/gdb/02-verlet.gdb --args build/debug/stepwise run config/lesson02_verlet.scene
source lectures/gdb/stepwise.py
# The first statement is the line `break stepwise::integrateVerlet` stops at in the debug build. Under
# AddressSanitizer (the asan preset, where the tests run this session) a breakpoint on the function's
# name stops before the function has stored its parameters in its frame, and `bodies` reads as empty.
break-at verlet.cpp "const Real halfHSquared = Real(0.5) * h * h;"
run
p h
p bodies._M_ptr[0].position
p bodies._M_ptr[0].velocity
p bodies._M_ptr[0].acceleration
break-at verlet.cpp "accelerations(bodies);"
continue
p halfHSquared
p bodies._M_ptr[0].position
p bodies._M_ptr[0].velocity
break stepwise::applyUniformForces
continue
bt
frame function stepwise::integrateVerlet
# integrateVerlet() returns into integrateBodies(), which picks the scene's integrator; the
# second finish reaches the integrate stage's lambda, where the World's dynamics_ is in scope.
finish
finish
p dynamics_[0].position
p dynamics_[0].velocity
p dynamics_[0].acceleration
continue
bt
continue
p bodies._M_ptr[0].position
p bodies._M_ptr[0].velocity
