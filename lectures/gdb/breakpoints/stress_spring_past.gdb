# Breakpoints for config/stress_spring_past.scene (lecture 9, lectures/09-accuracy-and-stability.md).
# The same breakpoints as its entry in .vscode/launch.json, which sources this file.
# By function name, so they do not move when lines do. From the command line:
#   scripts/debug.sh config/stress_spring_past.scene
# (it builds the debug preset, then runs
#   gdb -x lectures/gdb/breakpoints/stress_spring_past.gdb --args build/debug/stepwise run config/stress_spring_past.scene)
# then (gdb) run, and (gdb) continue from one stop to the next.
# Pending: VS Code sources this before the program is loaded.
set breakpoint pending on
# loading the scene: is h w within the integrator's limit? (the warning it prints)
break stepwise::analyseSpring
# stage 1: Hooke's law at the anchor
break stepwise::applySprings
