# Breakpoints for config/lesson07_bowling.scene (lecture 7, lectures/07-friction-and-restitution.md).
# The same breakpoints as its entry in .vscode/launch.json, which sources this file.
# By function name, so they do not move when lines do; the lecture's own sessions (lectures/gdb/NN-*.gdb)
# go further, line by line. From the command line (after cmake --preset debug && cmake --build --preset debug):
#   gdb -x lectures/gdb/breakpoints/lesson07_bowling.gdb --args build/debug/stepwise run config/lesson07_bowling.scene
#   (or scripts/debug.sh config/lesson07_bowling.scene, which builds the debug preset first and runs that)
# then (gdb) run, and (gdb) continue from one stop to the next.
# Pending: VS Code sources this before the program is loaded.
set breakpoint pending on
# stage 6: a contact's lever arms, effective masses and tangent basis
break stepwise::(anonymous namespace)::prepare
# stage 6: one pass at one contact: the normal impulse, then friction clamped to mu j
break stepwise::(anonymous namespace)::solve
