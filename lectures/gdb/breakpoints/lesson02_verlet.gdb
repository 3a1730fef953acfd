# Breakpoints for config/lesson02_verlet.scene (lecture 2, lectures/02-verlet-and-symplectic-euler.md).
# The same breakpoints as its entry in .vscode/launch.json, which sources this file.
# By function name, so they do not move when lines do; the lecture's own sessions (lectures/gdb/NN-*.gdb)
# go further, line by line. From the command line (after cmake --preset debug && cmake --build --preset debug):
#   gdb -x lectures/gdb/breakpoints/lesson02_verlet.gdb --args build/debug/stepwise run config/lesson02_verlet.scene
#   (or scripts/debug.sh config/lesson02_verlet.scene, which builds the debug preset first and runs that)
# then (gdb) run, and (gdb) continue from one stop to the next.
# Pending: VS Code sources this before the program is loaded.
set breakpoint pending on
# stage 2: velocity Verlet, and its second call of the force model
break stepwise::integrateVerlet
