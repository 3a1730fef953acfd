# Breakpoints for config/bench_sphere_rain_1k.scene (appendix 8a, lectures/08a-appendix-the-fast-path.md).
# The same breakpoints as its entry in .vscode/launch.json, which sources this file.
# By function name, so they do not move when lines do. From the command line:
#   scripts/debug.sh config/bench_sphere_rain_1k.scene
# (it builds the debug preset, then runs
#   gdb -x lectures/gdb/breakpoints/bench_sphere_rain_1k.gdb --args build/debug/stepwise run config/bench_sphere_rain_1k.scene)
# then (gdb) run, and (gdb) continue from one stop to the next.
# Pending: VS Code sources this before the program is loaded.
set breakpoint pending on
# stage 4: a thousand balls' contacts become constraints
break stepwise::prepareContacts
# stage 6, every substep, on the plain path (the debug build's): one soft pass over the contacts;
# a copy with FastPath=true runs stepwise::solveRoundContactRange instead (appendix 8a)
break stepwise::solveContacts
