# Breakpoints for config/lesson12_parts.scene (lecture 12, lectures/12-bodies-from-parts.md).
# The same breakpoints as its entry in .vscode/launch.json, which sources this file.
# By function name, so they do not move when lines do; the lecture's own sessions (lectures/gdb/NN-*.gdb)
# go further, line by line. From the command line (after cmake --preset debug && cmake --build --preset debug):
#   gdb -x lectures/gdb/breakpoints/lesson12_parts.gdb --args build/debug/stepwise run config/lesson12_parts.scene --steps 10
#   (or scripts/debug.sh config/lesson12_parts.scene -- --steps 10, which builds the debug preset first and runs that)
# then (gdb) run, and (gdb) continue from one stop to the next.
# Pending: VS Code sources this before the program is loaded.
set breakpoint pending on
# loading: the tetrahedron's volume, centroid and tensor by the divergence theorem
break stepwise::polyhedronMassProperties
# loading: the L's mass, centre of mass and tensor, summed over its parts
break stepwise::compoundMassProperties
# loading: the principal moments and axes of a tensor, by Jacobi rotations
break stepwise::principalAxes
# stage 3 (narrowphase), and the broadphase's bounding boxes: one part of the L, placed in the world
break stepwise::geometryOfPart
