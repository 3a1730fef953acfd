# Lecture 9: one spring force, evaluated twice per step by velocity Verlet.
# Breakpoints inside a function are named by the code at the line (break-at FILE "TEXT", from
# lectures/gdb/stepwise.py), so they follow the code when lines move; run from the repository root.
# It runs on a copy of the spring scene with Integrator=Verlet (the scene's own integrator, symplectic
# Euler, calls the force model once a step, and has no integrateVerlet() frame to select):
#   scene copy:  sed 's|Integrator=SymplecticEuler|Integrator=Verlet|' config/reference_spring.scene > /tmp/spring_verlet.scene
#   interactive:  gdb -x lectures/gdb/09-spring-forces.gdb --args build/debug/stepwise run /tmp/spring_verlet.scene --steps 2
#   all at once:  gdb -q -batch -x lectures/gdb/09-spring-forces.gdb --args build/debug/stepwise run /tmp/spring_verlet.scene --steps 2
source lectures/gdb/stepwise.py
break-at spring.cpp "a.acceleration += forceOnA * a.inverseMass;"
run
p length
p spring.restLength
p stretchRate
p forceOnA
frame function stepwise::World::step
frame 0
continue
p length
p stretchRate
p forceOnA
frame function stepwise::integrateVerlet
p bodies._M_ptr[0].velocity
frame 0
finish
p bodies._M_ptr[0].position
p bodies._M_ptr[0].velocity
continue
p length
p forceOnA
