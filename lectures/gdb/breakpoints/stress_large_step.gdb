# Breakpoints for config/stress_large_step.scene (lecture 9, lectures/09-accuracy-and-stability.md).
# The same breakpoints as its entry in .vscode/launch.json, which sources this file.
# By function name, so they do not move when lines do. From the command line:
#   scripts/debug.sh config/stress_large_step.scene
# (it builds the debug preset, then runs
#   gdb -x lectures/gdb/breakpoints/stress_large_step.gdb --args build/debug/stepwise run config/stress_large_step.scene)
# then (gdb) run, and (gdb) continue from one stop to the next.
# Pending: VS Code sources this before the program is loaded.
set breakpoint pending on
# stage 4: contacts of a 1/15 s step become constraints
break stepwise::prepareContacts
# stage 6, every substep: one soft pass over the contacts
break stepwise::solveContacts
