# Lecture 1, session B: the two lines of explicit Euler, one at a time.
# Breakpoints inside a function are named by the code at the line (break-at FILE "TEXT", from
# lectures/gdb/stepwise.py), so they follow the code when lines move; run from the repository root.
#   interactive:  gdb -x lectures/gdb/01-line-by-line.gdb --args build/debug/stepwise run config/lesson01_explicit_euler.scene
#   all at once:  gdb -q -batch -x lectures/gdb/01-line-by-line.gdb --args build/debug/stepwise run config/lesson01_explicit_euler.scene
source lectures/gdb/stepwise.py
break-at explicit_euler.cpp "body.position += h * body.velocity;"
run
display body.position
display body.velocity
next
next
