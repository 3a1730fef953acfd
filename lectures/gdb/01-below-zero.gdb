# Lecture 1, exercise 4: the first step that starts below y = 0.
# Line numbers are those of the commit named in the lecture; check them if the file has changed.
#   interactive:  gdb -x lectures/gdb/01-below-zero.gdb --args build/debug/stepwise run config/lesson01_explicit_euler.scene
#   all at once:  gdb -q -batch -x lectures/gdb/01-below-zero.gdb --args build/debug/stepwise run config/lesson01_explicit_euler.scene
break explicit_euler.cpp:51 if body.position.y < 0
run
p body.position
p body.velocity
frame function stepwise::World::step
p stepCount_
p time_
