# Breakpoints for config/lesson13_wind.scene (lecture 13, lectures/13-forces-from-the-world.md).
# The same breakpoints as its entry in .vscode/launch.json, which sources this file.
# By function name, so they do not move when lines do; the lecture's own session (lectures/gdb/13-*.gdb)
# goes further, line by line. From the command line (after cmake --preset debug && cmake --build --preset debug):
#   gdb -x lectures/gdb/breakpoints/lesson13_wind.gdb --args build/debug/stepwise run config/lesson13_wind.scene
#   (or scripts/debug.sh config/lesson13_wind.scene, which builds the debug preset first and runs that)
# then (gdb) run, and (gdb) continue from one stop to the next.
# Pending: VS Code sources this before the program is loaded.
set breakpoint pending on
# stage 1 (apply-forces), step 1b: who is inside each region, asked of the broadphase
break stepwise::World::findRegionMembers
# stage 1 (apply-forces): the wind's drag on the kite, relative to the moving air
break stepwise::addWind
# stage 1 (apply-forces): one random push, from a hash of (seed, step, body)
break stepwise::randomForce
# end of the step: bodies whose centres are in a Kill region leave the world
break stepwise::World::removeKilledBodies
