# Breakpoints for config/stress_fast_box_wall.scene (lecture 9, lectures/09-accuracy-and-stability.md).
# The same breakpoints as its entry in .vscode/launch.json, which sources this file.
# By function name, so they do not move when lines do. From the command line:
#   scripts/debug.sh config/stress_fast_box_wall.scene
# (it builds the debug preset, then runs
#   gdb -x lectures/gdb/breakpoints/stress_fast_box_wall.gdb --args build/debug/stepwise run config/stress_fast_box_wall.scene)
# then (gdb) run, and (gdb) continue from one stop to the next.
# Pending: VS Code sources this before the program is loaded.
set breakpoint pending on
# stage 7b: a body that moved farther than its half-thickness goes back to where its path first touched the wall
break stepwise::stopFastBodiesAtImpact
# conservative advancement: the time of first touch along the step's path
break stepwise::timeOfImpact
