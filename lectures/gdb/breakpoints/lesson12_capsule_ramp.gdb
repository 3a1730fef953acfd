# Breakpoints for config/lesson12_capsule_ramp.scene (lecture 12, lectures/12-bodies-from-parts.md).
# The same breakpoints as its entry in .vscode/launch.json, which sources this file.
# By function name, so they do not move when lines do; the lecture's own sessions (lectures/gdb/NN-*.gdb)
# go further, line by line. From the command line (after cmake --preset debug && cmake --build --preset debug):
#   gdb -x lectures/gdb/breakpoints/lesson12_capsule_ramp.gdb --args build/debug/stepwise run config/lesson12_capsule_ramp.scene --steps 10
#   (or scripts/debug.sh config/lesson12_capsule_ramp.scene -- --steps 10, which builds the debug preset first and runs that)
# then (gdb) run, and (gdb) continue from one stop to the next.
# Pending: VS Code sources this before the program is loaded.
set breakpoint pending on
# loading: the capsule's moments, a cylinder and two hemispheres
break stepwise::solidCapsuleInertia
# loading: the cylinder's moments
break stepwise::solidCylinderInertia
# stage 3 (narrowphase): the capsule's segment against the ramp
break stepwise::collideCapsulePlane
