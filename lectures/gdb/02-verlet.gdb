# Lecture 2, session A: velocity Verlet and its second call of the force model.
# Line numbers are those of the commit named in the lecture; check them if the file has changed.
#   interactive:  gdb -x lectures/gdb/02-verlet.gdb --args build/debug/stepwise run config/lesson02_verlet.scene
#   all at once:  gdb -q -batch -x lectures/gdb/02-verlet.gdb --args build/debug/stepwise run config/lesson02_verlet.scene
break stepwise::integrateVerlet
run
p h
p bodies._M_ptr[0].position
p bodies._M_ptr[0].velocity
p bodies._M_ptr[0].acceleration
break verlet.cpp:50
continue
p halfHSquared
p bodies._M_ptr[0].position
p bodies._M_ptr[0].velocity
break stepwise::applyUniformForces
continue
bt
frame function stepwise::integrateVerlet
finish
p dynamics_[0].position
p dynamics_[0].velocity
p dynamics_[0].acceleration
continue
bt
continue
p bodies._M_ptr[0].position
p bodies._M_ptr[0].velocity
