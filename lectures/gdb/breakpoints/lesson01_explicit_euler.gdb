# Breakpoints for config/lesson01_explicit_euler.scene (lecture 1, lectures/01-explicit-euler.md).
# The same breakpoints as its entry in .vscode/launch.json, which sources this file.
# By function name, so they do not move when lines do; the lecture's own sessions (lectures/gdb/NN-*.gdb)
# go further, line by line. From the command line (after cmake --preset debug && cmake --build --preset debug):
#   gdb -x lectures/gdb/breakpoints/lesson01_explicit_euler.gdb --args build/debug/stepwise run config/lesson01_explicit_euler.scene
#   (or scripts/debug.sh config/lesson01_explicit_euler.scene, which builds the debug preset first and runs that)
# then (gdb) run, and (gdb) continue from one stop to the next.
# Pending: VS Code sources this before the program is loaded.
set breakpoint pending on
# stage 1: gravity and each body's own acceleration into body.acceleration
break stepwise::applyUniformForces
# stage 2: x += h v, v += h a, both from the old state
break stepwise::integrateExplicitEuler
