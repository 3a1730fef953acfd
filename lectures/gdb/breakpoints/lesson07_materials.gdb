# Breakpoints for config/lesson07_materials.scene (lecture 7, lectures/07-friction-and-restitution.md).
# The same breakpoints as its entry in .vscode/launch.json, which sources this file.
# By function name, so they do not move when lines do. From the command line (after
# cmake --preset debug && cmake --build --preset debug):
#   gdb -x lectures/gdb/breakpoints/lesson07_materials.gdb --args build/debug/stepwise run config/lesson07_materials.scene
#   (or scripts/debug.sh config/lesson07_materials.scene, which builds the debug preset first and runs that)
# then (gdb) run, and (gdb) continue from one stop to the next.
# Pending: VS Code sources this before the program is loaded.
set breakpoint pending on
# prepare-constraints: each block's contact with the ramp becomes a constraint, its mu and e decided once
break stepwise::(anonymous namespace)::prepareOne
# the World's rule (GeometricMean here) and the ice-wood MaterialPair: print materialA, materialB and the result
break stepwise::ContactMaterials::mix
