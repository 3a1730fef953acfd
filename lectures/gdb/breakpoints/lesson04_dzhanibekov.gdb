# Breakpoints for config/lesson04_dzhanibekov.scene (lecture 4, lectures/04-inertia-and-rotation.md).
# The same breakpoints as its entry in .vscode/launch.json, which sources this file.
# By function name, so they do not move when lines do; the lecture's own sessions (lectures/gdb/NN-*.gdb)
# go further, line by line. From the command line (after cmake --preset debug && cmake --build --preset debug):
#   gdb -x lectures/gdb/breakpoints/lesson04_dzhanibekov.gdb --args build/debug/stepwise run config/lesson04_dzhanibekov.scene
#   (or scripts/debug.sh config/lesson04_dzhanibekov.scene, which builds the debug preset first and runs that)
# then (gdb) run, and (gdb) continue from one stop to the next.
# Pending: VS Code sources this before the program is loaded.
set breakpoint pending on
# stage 2 (rotation): the free-body splitting, three exact spins about the body axes
break stepwise::rotateTorqueFree
# omega = I_world^-1 L after the turn
break stepwise::updateAngularVelocity
