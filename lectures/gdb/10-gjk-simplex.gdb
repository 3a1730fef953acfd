# Lecture 10: one GJK query, iteration by iteration: the spike (a tetrahedron hull) 17 mm above the table, step 1.
# Breakpoints inside a function are named by the code at the line (break-at FILE "TEXT", from
# lectures/gdb/stepwise.py), so they follow the code when lines move; run from the repository root.
#   interactive:  gdb -x lectures/gdb/10-gjk-simplex.gdb --args build/debug/stepwise run config/lesson10_gjk.scene --steps 1
#   all at once:  gdb -q -batch -x lectures/gdb/10-gjk-simplex.gdb --args build/debug/stepwise run config/lesson10_gjk.scene --steps 1
# Each iteration stops twice: at the termination test, with the new support point w, and after
# the sub-algorithm has cut the simplex down to the points that hold its closest point.
set pagination off
source lectures/gdb/stepwise.py
tbreak stepwise::gjk if a.core == stepwise::ConvexCore::Hull
run
p a.centre
p b.centre
break-at gjk.cpp "if (simplex.count > 0 && vv - glm::dot(v, w) <= kGjkRelativeTolerance * vv) break;"
break-at gjk.cpp "if (record != nullptr) record->push_back(simplex);"
continue
p iteration
p v
p onA
p onB
p w
continue
p simplex.count
p simplex.closest
continue
p iteration
p onA
p onB
p vv - (v.x*w.x + v.y*w.y + v.z*w.z)
continue
p simplex.count
p simplex.closest
continue
p iteration
p w
p vv - (v.x*w.x + v.y*w.y + v.z*w.z)
continue
p simplex.count
p simplex.closest
continue
p iteration
p w
p vv - (v.x*w.x + v.y*w.y + v.z*w.z)
continue
p simplex.count
p simplex.closest
p simplex.vertices[0].w
p simplex.vertices[0].weight
p simplex.vertices[1].w
p simplex.vertices[1].weight
p simplex.vertices[2].w
p simplex.vertices[2].weight
continue
p iteration
p w
p vv - (v.x*w.x + v.y*w.y + v.z*w.z)
delete
break-at convex_pairs.cpp "iterations.gjk = g.iterations;"
continue
p g.iterations
p g.distance
p g.normal
p g.onA
p g.onB
