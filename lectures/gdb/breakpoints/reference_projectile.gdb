# Breakpoints for config/reference_projectile.scene (lecture 9, lectures/09-accuracy-and-stability.md).
# The same breakpoints as its entry in .vscode/launch.json, which sources this file.
# By function name, so they do not move when lines do. From the command line:
#   scripts/debug.sh config/reference_projectile.scene
# (it builds the debug preset, then runs
#   gdb -x lectures/gdb/breakpoints/reference_projectile.gdb --args build/debug/stepwise run config/reference_projectile.scene)
# then (gdb) run, and (gdb) continue from one stop to the next.
# Pending: VS Code sources this before the program is loaded.
set breakpoint pending on
# stage 1: gravity into body.acceleration
break stepwise::applyUniformForces
# stage 2: the integrator of the reference runs (kick, then drift)
break stepwise::integrateSymplecticEuler
