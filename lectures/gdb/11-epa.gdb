# Lecture 11, session A: EPA grows a polytope inside A - B until a face is on its boundary: the hull crate's first overlap, step 6.
# Breakpoints inside a function are named by the code at the line (break-at FILE "TEXT", from
# lectures/gdb/stepwise.py), so they follow the code when lines move; run from the repository root.
#   interactive:  gdb -x lectures/gdb/11-epa.gdb --args build/debug/stepwise run config/lesson11_convex_contacts.scene --steps 10
#   all at once:  gdb -q -batch -x lectures/gdb/11-epa.gdb --args build/debug/stepwise run config/lesson11_convex_contacts.scene --steps 10
set pagination off
source lectures/gdb/stepwise.py
tbreak stepwise::epa
run
p start.count
p a.centre
break-at epa.cpp "const Real gain = glm::dot(p.w, face.normal) - face.distance;"
continue
p iteration
p poly.faceCount
p face.distance
p face.normal
p poly.vertices[face.v[0]].w
p poly.vertices[face.v[1]].w
p poly.vertices[face.v[2]].w
p p.w
next
p gain
delete
break-at convex_pairs.cpp "return convexManifold(a, b, e.normal, e.onA, e.onB, e.depth, maxGap, out);"
continue
p e.iterations
p e.depth
p e.normal
p e.onA
p e.onB
step
finish
p out.pointCount
p out.points[0]
p out.points[1]
p out.points[2]
p out.points[3]
