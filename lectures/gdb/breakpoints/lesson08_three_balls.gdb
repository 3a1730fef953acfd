# Breakpoints for config/lesson08_three_balls.scene (lecture 8, lectures/08-constraint-solver.md).
# The same breakpoints as its entry in .vscode/launch.json, which sources this file.
# By function name, so they do not move when lines do. From the command line
# (after cmake --preset debug && cmake --build --preset debug):
#   gdb -x lectures/gdb/breakpoints/lesson08_three_balls.gdb --args build/debug/stepwise run config/lesson08_three_balls.scene --steps 10
#   (or scripts/debug.sh config/lesson08_three_balls.scene -- --steps 10, which builds the debug preset first and runs that)
# then (gdb) run, and (gdb) continue from one stop to the next.
# Pending: VS Code sources this before the program is loaded.
set breakpoint pending on
# stages 6 and 7, every substep: a solve pass (useBias = true), then a relax pass (false),
# which solves these balls' normal rows only; compare workspace.contacts[i].tangentImpulse
# before and after each. solveContacts is the plain path's pass: the debug build takes the
# plain path; on another build add FastPath=false to the scene's World line, or this is not hit
# (lectures/08-constraint-solver.md, section 2).
break stepwise::solveContacts
# stage 8: the step's impulses kept for the next step's warm start
break stepwise::storeContactImpulses
