# Breakpoints for config/reference_kepler_eccentric.scene (lecture 9, lectures/09-accuracy-and-stability.md).
# The same breakpoints as its entry in .vscode/launch.json, which sources this file.
# By function name, so they do not move when lines do. From the command line:
#   scripts/debug.sh config/reference_kepler_eccentric.scene
# (it builds the debug preset, then runs
#   gdb -x lectures/gdb/breakpoints/reference_kepler_eccentric.gdb --args build/debug/stepwise run config/reference_kepler_eccentric.scene)
# then (gdb) run, and (gdb) continue from one stop to the next.
# Pending: VS Code sources this before the program is loaded.
set breakpoint pending on
# stage 1: the sun's pull, -mu r/|r|^3 (strongest at perihelion)
break stepwise::applyAttractors
# stage 2: symplectic Euler keeps the orbit's energy bounded
break stepwise::integrateSymplecticEuler
