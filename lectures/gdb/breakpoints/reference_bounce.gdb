# Breakpoints for config/reference_bounce.scene (lecture 9, lectures/09-accuracy-and-stability.md).
# The same breakpoints as its entry in .vscode/launch.json, which sources this file.
# By function name, so they do not move when lines do. From the command line:
#   scripts/debug.sh config/reference_bounce.scene
# (it builds the debug preset, then runs
#   gdb -x lectures/gdb/breakpoints/reference_bounce.gdb --args build/debug/stepwise run config/reference_bounce.scene)
# then (gdb) run, and (gdb) continue from one stop to the next.
# Pending: VS Code sources this before the program is loaded.
set breakpoint pending on
# stage 5: the ball against the floor
break stepwise::collideSpherePlane
# stage 6: the impact speed v_c at touch, and e v_c
break stepwise::(anonymous namespace)::prepare
