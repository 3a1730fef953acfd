# Lecture 1, session A: two whole explicit Euler steps.
# Breakpoints by function name, so they do not move when lines do.
#   interactive:  gdb -x lectures/gdb/01-explicit-euler.gdb --args build/debug/stepwise run config/lesson01_explicit_euler.scene
#   all at once:  gdb -q -batch -x lectures/gdb/01-explicit-euler.gdb --args build/debug/stepwise run config/lesson01_explicit_euler.scene
break stepwise::integrateExplicitEuler
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
