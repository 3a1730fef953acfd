# Breakpoints for config/lesson14_inflate.scene (lecture 14, lectures/14-soft-bodies-under-pressure.md).
# The same breakpoints as its entry in .vscode/launch.json, which sources this file.
# By function name, so they do not move when lines do; the lecture's own session (lectures/gdb/14-*.gdb)
# goes further, line by line. From the command line (after cmake --preset debug && cmake --build --preset debug):
#   gdb -x lectures/gdb/breakpoints/lesson14_inflate.gdb --args build/debug/stepwise run config/lesson14_inflate.scene
#   (or scripts/debug.sh config/lesson14_inflate.scene, which builds the debug preset first and runs that)
# then (gdb) run, and (gdb) continue from one stop to the next.
# Pending: VS Code sources this before the program is loaded.
set breakpoint pending on
# stage soft-bodies: one step of every soft body, substep by substep
break stepwise::stepSoftBodies
# soft step 2: the enclosed volume, (1/6) sum a.(b x c)
break stepwise::enclosedVolume
# soft step 3: P = nRT / V, and P A n / 3 on each corner of each face
break stepwise::addPressureForces
