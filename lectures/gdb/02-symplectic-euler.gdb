# Lecture 2, session B: symplectic Euler, line by line (needs the copy of the scene with Integrator=SymplecticEuler).
# Line numbers are those of the commit named in the lecture; check them if the file has changed.
#   interactive:  gdb -x lectures/gdb/02-symplectic-euler.gdb --args build/debug/stepwise run /tmp/lesson02_symplectic.scene
#   all at once:  gdb -q -batch -x lectures/gdb/02-symplectic-euler.gdb --args build/debug/stepwise run /tmp/lesson02_symplectic.scene
break symplectic_euler.cpp:39
run
display body.position
display body.velocity
next
next
continue
next
next
