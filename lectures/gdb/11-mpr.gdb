# Lecture 11, session B: MPR on the same crate (a copy of the scene with Narrowphase=Mpr): the portal it ends on, step 6.
# Breakpoints inside a function are named by the code at the line (break-at FILE "TEXT", from
# lectures/gdb/stepwise.py), so they follow the code when lines move; run from the repository root.
#   scene copy:  sed 's/Solver=Impulse/Solver=Impulse, Narrowphase=Mpr/' config/lesson11_convex_contacts.scene > /tmp/lesson11_mpr.scene
#   interactive:  gdb -x lectures/gdb/11-mpr.gdb --args build/debug/stepwise run /tmp/lesson11_mpr.scene --steps 10
#   all at once:  gdb -q -batch -x lectures/gdb/11-mpr.gdb --args build/debug/stepwise run /tmp/lesson11_mpr.scene --steps 10
set pagination off
source lectures/gdb/stepwise.py
break-at mpr.cpp "return hit ? resultOf(v1, v2, v3, n, s.supports) : miss(s.supports);" if hit && a.core == stepwise::ConvexCore::Hull
run
p v0.w
p s.supports
p n
p beyond
p n.x*v1.w.x + n.y*v1.w.y + n.z*v1.w.z
p v1.w
p v2.w
p v3.w
