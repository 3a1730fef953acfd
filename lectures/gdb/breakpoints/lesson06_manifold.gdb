# Breakpoints for config/lesson06_manifold.scene (lecture 6, lectures/06-contact-points-and-manifolds.md).
# The same breakpoints as its entry in .vscode/launch.json, which sources this file.
# By function name, so they do not move when lines do; the lecture's own sessions (lectures/gdb/NN-*.gdb)
# go further, line by line. From the command line (after cmake --preset debug && cmake --build --preset debug):
#   gdb -x lectures/gdb/breakpoints/lesson06_manifold.gdb --args build/debug/stepwise run config/lesson06_manifold.scene --steps 10
#   (or scripts/debug.sh config/lesson06_manifold.scene -- --steps 10, which builds the debug preset first and runs that)
# then (gdb) run, and (gdb) continue from one stop to the next.
# Pending: VS Code sources this before the program is loaded.
set breakpoint pending on
# stage 5: the corners of a box below the floor
break stepwise::collideBoxPlane
