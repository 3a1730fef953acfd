# Breakpoints for config/lesson11_convex_contacts.scene (lecture 11, lectures/11-epa-mpr-and-convex-contacts.md).
# The same breakpoints as its entry in .vscode/launch.json, which sources this file.
# By function name, so they do not move when lines do; the lecture's own sessions (lectures/gdb/11-epa.gdb,
# 11-mpr.gdb) go further, line by line. From the command line (after cmake --preset debug && cmake --build --preset debug):
#   gdb -x lectures/gdb/breakpoints/lesson11_convex_contacts.gdb --args build/debug/stepwise run config/lesson11_convex_contacts.scene --steps 10
#   (or scripts/debug.sh config/lesson11_convex_contacts.scene -- --steps 10, which builds the debug preset first and runs that)
# then (gdb) run, and (gdb) continue from one stop to the next.
# Pending: VS Code sources this before the program is loaded.
set breakpoint pending on
# stage narrowphase: the penetration depth and normal once GJK finds the cores overlapping
break stepwise::epa
# stage narrowphase: the same by portal refinement (a copy of the scene with Narrowphase=Mpr)
break stepwise::mpr
# stage narrowphase: the normal to a manifold of up to 4 clipped points
break stepwise::convexManifold
