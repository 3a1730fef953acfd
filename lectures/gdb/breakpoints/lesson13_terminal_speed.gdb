# Breakpoints for config/lesson13_terminal_speed.scene (lecture 13, lectures/13-forces-from-the-world.md).
# The same breakpoints as its entry in .vscode/launch.json, which sources this file.
# By function name, so they do not move when lines do; the lecture's own session (lectures/gdb/13-*.gdb)
# goes further, line by line. From the command line (after cmake --preset debug && cmake --build --preset debug):
#   gdb -x lectures/gdb/breakpoints/lesson13_terminal_speed.gdb --args build/debug/stepwise run config/lesson13_terminal_speed.scene
#   (or scripts/debug.sh config/lesson13_terminal_speed.scene, which builds the debug preset first and runs that)
# then (gdb) run, and (gdb) continue from one stop to the next.
# Pending: VS Code sources this before the program is loaded.
set breakpoint pending on
# stage 1 (apply-forces), step 1b: who is inside each region, asked of the broadphase
break stepwise::World::findRegionMembers
# stage 1 (apply-forces): the drag of one column on its ball, capped at what stops it in a substep
break stepwise::addDrag
