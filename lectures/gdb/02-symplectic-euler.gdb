# Lecture 2, session B: symplectic Euler, line by line (needs the copy of the scene with Integrator=SymplecticEuler).
# Breakpoints inside a function are named by the code at the line (break-at FILE "TEXT", from
# lectures/gdb/stepwise.py), so they follow the code when lines move; run from the repository root.
#   scene copy:  sed 's/Integrator=Verlet/Integrator=SymplecticEuler/' config/lesson02_verlet.scene > /tmp/lesson02_symplectic.scene
#   interactive:  gdb -x lectures/gdb/02-symplectic-euler.gdb --args build/debug/stepwise run /tmp/lesson02_symplectic.scene
#   all at once:  gdb -q -batch -x lectures/gdb/02-symplectic-euler.gdb --args build/debug/stepwise run /tmp/lesson02_symplectic.scene
source lectures/gdb/stepwise.py
break-at symplectic_euler.cpp "body.velocity += h * body.acceleration;"
run
display body.position
display body.velocity
next
next
continue
next
next
