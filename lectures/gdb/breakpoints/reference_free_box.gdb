# Breakpoints for config/reference_free_box.scene (lecture 9, lectures/09-accuracy-and-stability.md).
# The same breakpoints as its entry in .vscode/launch.json, which sources this file.
# By function name, so they do not move when lines do. From the command line:
#   scripts/debug.sh config/reference_free_box.scene
# (it builds the debug preset, then runs
#   gdb -x lectures/gdb/breakpoints/reference_free_box.gdb --args build/debug/stepwise run config/reference_free_box.scene)
# then (gdb) run, and (gdb) continue from one stop to the next.
# Pending: VS Code sources this before the program is loaded.
set breakpoint pending on
# stage 2 (rotation): the free-body splitting, three exact spins about the body axes
break stepwise::rotateTorqueFree
# omega = I_world^-1 L after the turn
break stepwise::updateAngularVelocity
