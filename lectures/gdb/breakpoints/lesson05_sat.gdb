# Breakpoints for config/lesson05_sat.scene (lecture 5, lectures/05-separating-axis-theorem.md).
# The same breakpoints as its entry in .vscode/launch.json, which sources this file.
# By function name, so they do not move when lines do; the lecture's own sessions (lectures/gdb/NN-*.gdb)
# go further, line by line. From the command line (after cmake --preset debug && cmake --build --preset debug):
#   gdb -x lectures/gdb/breakpoints/lesson05_sat.gdb --args build/debug/stepwise run config/lesson05_sat.scene --steps 10
#   (or scripts/debug.sh config/lesson05_sat.scene -- --steps 10, which builds the debug preset first and runs that)
# then (gdb) run, and (gdb) continue from one stop to the next.
# Pending: VS Code sources this before the program is loaded.
set breakpoint pending on
# stage 5: the 15 axes of the separating-axis test, then face or edge contact
break stepwise::collideBoxBox
# stage 5: one side plane of the reference face clipping the incident face (lecture 6, session C)
break stepwise::clipPolygon
