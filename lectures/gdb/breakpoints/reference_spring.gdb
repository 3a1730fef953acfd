# Breakpoints for config/reference_spring.scene (lecture 9, lectures/09-accuracy-and-stability.md).
# The same breakpoints as its entry in .vscode/launch.json, which sources this file.
# By function name, so they do not move when lines do. From the command line:
#   scripts/debug.sh config/reference_spring.scene
# (it builds the debug preset, then runs
#   gdb -x lectures/gdb/breakpoints/reference_spring.gdb --args build/debug/stepwise run config/reference_spring.scene)
# then (gdb) run, and (gdb) continue from one stop to the next.
# Pending: VS Code sources this before the program is loaded.
set breakpoint pending on
# stage 1: Hooke's law at the anchor, F = -k (|d| - L0) d/|d|
break stepwise::applySprings
# stage 2: symplectic Euler, whose stable steps reach h w = 2
break stepwise::integrateSymplecticEuler
