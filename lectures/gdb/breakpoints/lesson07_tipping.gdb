# Breakpoints for config/lesson07_tipping.scene (lecture 7, lectures/07-friction-and-restitution.md, and its
# appendix, lectures/07a-appendix-holding-still.md).
# The same breakpoints as its entry in .vscode/launch.json, which sources this file.
# By function name, so they do not move when lines do; the lecture's own sessions (lectures/gdb/NN-*.gdb)
# go further, line by line. From the command line (after cmake --preset debug && cmake --build --preset debug):
#   gdb -x lectures/gdb/breakpoints/lesson07_tipping.gdb --args build/debug/stepwise run config/lesson07_tipping.scene
#   (or scripts/debug.sh config/lesson07_tipping.scene, which builds the debug preset first and runs that)
# then (gdb) run, and (gdb) continue from one stop to the next.
# Pending: VS Code sources this before the program is loaded.
set breakpoint pending on
# stage 5: a box on the table, its manifold shrinking as it tips
break stepwise::collideBoxBox
# stage 7: the resting contacts hold the boxes up
break stepwise::correctPositions
