# Lecture 6, session C: clipping the table's top face by the crate's side planes (lesson 5's scene).
# Line numbers are those of the commit named in the lecture; check them if the file has changed.
#   interactive:  gdb -x lectures/gdb/06-clipping.gdb --args build/debug/stepwise run config/lesson05_sat.scene --steps 10
#   all at once:  gdb -q -batch -x lectures/gdb/06-clipping.gdb --args build/debug/stepwise run config/lesson05_sat.scene --steps 10
break box_box.cpp:266
run
p referenceFace
p incidentFace
p polygon[0]@4
break box_box.cpp:275
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
