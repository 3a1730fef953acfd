# Lecture 1, session B: the two lines of explicit Euler, one at a time.
# Line numbers are those of the commit named in the lecture; check them if the file has changed.
#   interactive:  gdb -x lectures/gdb/01-line-by-line.gdb --args build/debug/stepwise run config/lesson01_explicit_euler.scene
#   all at once:  gdb -q -batch -x lectures/gdb/01-line-by-line.gdb --args build/debug/stepwise run config/lesson01_explicit_euler.scene
break explicit_euler.cpp:51
run
display body.position
display body.velocity
next
next
