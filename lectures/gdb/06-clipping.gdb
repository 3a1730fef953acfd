# Lecture 6, session C: clipping the table's top face by the crate's side planes (lesson 5's scene).
# Breakpoints inside a function are named by the code at the line (break-at FILE "TEXT", from
# lectures/gdb/stepwise.py), so they follow the code when lines move; run from the repository root.
#   interactive:  gdb -x lectures/gdb/06-clipping.gdb --args build/debug/stepwise run config/lesson05_sat.scene --steps 10
#   all at once:  gdb -q -batch -x lectures/gdb/06-clipping.gdb --args build/debug/stepwise run config/lesson05_sat.scene --steps 10
source lectures/gdb/stepwise.py
break-at box_box.cpp "const int u = (referenceAxis + 1) % 3;"
run
p referenceFace
p incidentFace
p polygon[0]@4
break-at box_box.cpp "std::copy(clipped, clipped + count, polygon);"
continue
p side
p planeNormal
p offset
p clipped[0]@count
continue
p side
p count
continue
p side
p count
continue
p side
p count
p clipped[0]@count
finish
p out.points[0]
