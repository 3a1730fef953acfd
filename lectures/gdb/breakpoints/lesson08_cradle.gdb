# Breakpoints for config/lesson08_cradle.scene (lecture 8, lectures/08-constraint-solver.md).
# The same breakpoints as its entry in .vscode/launch.json, which sources this file.
# By function name, so they do not move when lines do. From the command line
# (after cmake --preset debug && cmake --build --preset debug):
#   gdb -x lectures/gdb/breakpoints/lesson08_cradle.gdb --args build/debug/stepwise run config/lesson08_cradle.scene --steps 10
#   (or scripts/debug.sh config/lesson08_cradle.scene -- --steps 10, which builds the debug preset first and runs that)
# then (gdb) run, and (gdb) continue from one stop to the next.
# Pending: VS Code sources this before the program is loaded.
set breakpoint pending on
# stage 4: contacts between the balls, with their bounce
break stepwise::prepareContacts
# after the substeps: the bounce passes from ball to ball
break stepwise::applyRestitution
