# Lecture 1, session A: two whole explicit Euler steps.
# Breakpoints inside a function are named by the code at the line (break-at FILE "TEXT", from
# lectures/gdb/stepwise.py), so they follow the code when lines move; run from the repository root.
#   interactive:  gdb -x lectures/gdb/01-explicit-euler.gdb --args build/debug/stepwise run config/lesson01_explicit_euler.scene
#   all at once:  gdb -q -batch -x lectures/gdb/01-explicit-euler.gdb --args build/debug/stepwise run config/lesson01_explicit_euler.scene
source lectures/gdb/stepwise.py
# The loop is the line `break stepwise::integrateExplicitEuler` stops at in the debug build. Under
# AddressSanitizer (the asan preset, where the tests run this session) a breakpoint on the function's
# name stops before the function has stored its parameter in its frame, and `bodies` reads as empty.
break-at explicit_euler.cpp "for (DynamicObject& body : bodies) {"
run
p h
p bodies._M_ptr[0].position
p bodies._M_ptr[0].velocity
p bodies._M_ptr[0].acceleration
# integrateExplicitEuler() returns into integrateBodies(), which picks the scene's integrator; the
# second finish reaches the integrate stage's lambda, where the World's dynamics_ is in scope.
finish
finish
p dynamics_[0].position
p dynamics_[0].velocity
continue
p bodies._M_ptr[0].position
p bodies._M_ptr[0].velocity
finish
finish
p dynamics_[0].position
p dynamics_[0].velocity
