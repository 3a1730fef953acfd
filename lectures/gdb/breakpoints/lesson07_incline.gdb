# Breakpoints for config/lesson07_incline.scene (lecture 7, lectures/07-friction-and-restitution.md, and its
# appendix, lectures/07a-appendix-holding-still.md).
# The same breakpoints as its entry in .vscode/launch.json, which sources this file.
# By function name, so they do not move when lines do; the lecture's own sessions (lectures/gdb/NN-*.gdb)
# go further, line by line. From the command line (after cmake --preset debug && cmake --build --preset debug):
#   gdb -x lectures/gdb/breakpoints/lesson07_incline.gdb --args build/debug/stepwise run config/lesson07_incline.scene
#   (or scripts/debug.sh config/lesson07_incline.scene, which builds the debug preset first and runs that)
# then (gdb) run, and (gdb) continue from one stop to the next.
# Pending: VS Code sources this before the program is loaded.
set breakpoint pending on
# stage 6: each body's contact with the slope (static or kinetic friction?)
break stepwise::(anonymous namespace)::prepare
# stage 7: the support displacement s h dv (appendix 7a), then the position passes
break stepwise::correctPositions
