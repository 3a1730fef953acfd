# Lecture 12, session B: the narrowphase tests the L part by part, each part placed in the world by geometryOfPart.
# Breakpoints inside a function are named by the code at the line (break-at FILE "TEXT", from
# lectures/gdb/stepwise.py), so they follow the code when lines move; run from the repository root.
#   interactive:  gdb -x lectures/gdb/12-compound-parts.gdb --args build/debug/stepwise run config/lesson12_parts.scene --steps 10
#   all at once:  gdb -q -batch -x lectures/gdb/12-compound-parts.gdb --args build/debug/stepwise run config/lesson12_parts.scene --steps 10
source lectures/gdb/stepwise.py
break-at narrowphase.cpp "const Geometry pieceA = compoundA != nullptr ? geometryOfPart(a, compoundA->parts[i], partA) : a;"
run
p a.centre
p a.orientation
p compoundA->parts._M_impl._M_start[i].position
next
p partA
p pieceA.centre
p pieceA.orientation
p pieceA.halfExtents
frame function stepwise::World::step
p stepCount_
