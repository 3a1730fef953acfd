# Lecture 1, exercise 4: the first step that starts below y = 0.
# Breakpoints inside a function are named by the code at the line (break-at FILE "TEXT", from
# lectures/gdb/stepwise.py), so they follow the code when lines move; run from the repository root.
#   interactive:  gdb -x lectures/gdb/01-below-zero.gdb --args build/debug/stepwise run config/lesson01_explicit_euler.scene
#   all at once:  gdb -q -batch -x lectures/gdb/01-below-zero.gdb --args build/debug/stepwise run config/lesson01_explicit_euler.scene
source lectures/gdb/stepwise.py
break-at explicit_euler.cpp "body.position += h * body.velocity;" if body.position.y < 0
run
p body.position
p body.velocity
frame function stepwise::World::step
p stepCount_
p time_
