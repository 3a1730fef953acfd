# Breakpoints for config/lesson03_bounce.scene (lecture 3, lectures/03-sphere-plane-impulses.md, and its
# appendix, lectures/03a-appendix-contacts-over-steps.md).
# The same breakpoints as its entry in .vscode/launch.json, which sources this file.
# By function name, so they do not move when lines do; the lecture's own sessions (lectures/gdb/NN-*.gdb)
# go further, line by line. From the command line (after cmake --preset debug && cmake --build --preset debug):
#   gdb -x lectures/gdb/breakpoints/lesson03_bounce.gdb --args build/debug/stepwise run config/lesson03_bounce.scene
#   (or scripts/debug.sh config/lesson03_bounce.scene, which builds the debug preset first and runs that)
# then (gdb) run, and (gdb) continue from one stop to the next.
# Pending: VS Code sources this before the program is loaded.
set breakpoint pending on
# stage 5: the ball against the floor (a contact once it dips below)
break stepwise::collideSpherePlane
# stage 6: one contact's impact speed v_c, effective mass and restitution target
break stepwise::(anonymous namespace)::prepare
