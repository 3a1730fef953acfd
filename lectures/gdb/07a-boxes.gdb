# Appendix 7a, session A: the eight box corners of the incline at step 60, one line each.
# Breakpoints inside a function are named by the code at the line (break-at FILE "TEXT", from
# lectures/gdb/stepwise.py), so they follow the code when lines move; run from the repository root.
#   interactive:  gdb -x lectures/gdb/07a-boxes.gdb --args build/debug/stepwise run config/lesson07_incline.scene --steps 60
#   all at once:  gdb -q -batch -x lectures/gdb/07a-boxes.gdb --args build/debug/stepwise run config/lesson07_incline.scene --steps 60
source lectures/gdb/stepwise.py
set trace-commands on
break-at world.cpp "resolveImpulses(bodies(), contacts_, h, settings_.impulseIterations" if stepCount_ == 59
run
delete 1
tbreak-at impulse_resolver.cpp "rememberImpulses(contacts, constraints, workspace);"
continue
set trace-commands off
set $i = 2
while $i < 10
  set $c = constraints[$i]
  printf "%d %-6s j %.6f  jt (%+.6f, %+.6f)  mu*j %.6f  normalMass %.4f  tangentMass (%.4f, %.4f)\n", $i, $c.a->name._M_dataplus._M_p, $c.normalImpulse, $c.tangentImpulse[0], $c.tangentImpulse[1], $c.friction * $c.normalImpulse, $c.normalMass, $c.tangentMass[0], $c.tangentMass[1]
  set $i = $i + 1
end
set trace-commands on
p constraints[7].rA
p constraints[9].rA
