# Breakpoints for config/reference_pendulum.scene (lecture 9, lectures/09-accuracy-and-stability.md).
# The same breakpoints as its entry in .vscode/launch.json, which sources this file.
# By function name, so they do not move when lines do. From the command line:
#   scripts/debug.sh config/reference_pendulum.scene
# (it builds the debug preset, then runs
#   gdb -x lectures/gdb/breakpoints/reference_pendulum.gdb --args build/debug/stepwise run config/reference_pendulum.scene)
# then (gdb) run, and (gdb) continue from one stop to the next.
# Pending: VS Code sources this before the program is loaded.
set breakpoint pending on
# stage 4: the rod becomes a constraint
break stepwise::prepareJoints
# stage 6, every substep: one soft pass over the rod
break stepwise::solveJoints
