# Breakpoints for config/lesson10_gjk.scene (lecture 10, lectures/10-gjk-and-the-minkowski-difference.md).
# The same breakpoints as its entry in .vscode/launch.json, which sources this file.
# By function name, so they do not move when lines do; the lecture's own session (lectures/gdb/10-gjk-simplex.gdb)
# goes further, line by line. From the command line (after cmake --preset debug && cmake --build --preset debug):
#   gdb -x lectures/gdb/breakpoints/lesson10_gjk.gdb --args build/debug/stepwise run config/lesson10_gjk.scene --steps 4
#   (or scripts/debug.sh config/lesson10_gjk.scene -- --steps 4, which builds the debug preset first and runs that)
# then (gdb) run, and (gdb) continue from one stop to the next.
# Pending: VS Code sources this before the program is loaded.
set breakpoint pending on
# stage narrowphase: a convex pair, to the algorithm the scene's Narrowphase picks
break stepwise::collideConvex
# stage narrowphase: GJK's distance, or its overlap, from support points
break stepwise::gjk
