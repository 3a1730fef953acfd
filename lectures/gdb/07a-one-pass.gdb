# Appendix 7a, session B: the sticky box's four corners after one pass of the first step. Run it on a copy of the
# scene whose World line says ImpulseIterations=1:
#   scene copy:  sed 's/^World, \(.*\)$/World, \1, ImpulseIterations=1/' config/lesson07_incline.scene > /tmp/incline_1pass.scene
# Breakpoints inside a function are named by the code at the line (break-at FILE "TEXT", from
# lectures/gdb/stepwise.py), so they follow the code when lines move; run from the repository root.
#   interactive:  gdb -x lectures/gdb/07a-one-pass.gdb --args build/debug/stepwise run /tmp/incline_1pass.scene --steps 1
#   all at once:  gdb -q -batch -x lectures/gdb/07a-one-pass.gdb --args build/debug/stepwise run /tmp/incline_1pass.scene --steps 1
source lectures/gdb/stepwise.py
set trace-commands on
break-at world.cpp "resolveImpulses(bodies(), contacts_, h, settings_.impulseIterations" if stepCount_ == 0
run
delete 1
tbreak-at impulse_resolver.cpp "rememberImpulses(contacts, constraints, workspace);"
continue
set trace-commands off
set $i = 6
while $i < 10
  set $c = constraints[$i]
  printf "%d %-6s j %.6f  jt (%+.6f, %+.6f)  mu*j %.6f\n", $i, $c.a->name._M_dataplus._M_p, $c.normalImpulse, $c.tangentImpulse[0], $c.tangentImpulse[1], $c.friction * $c.normalImpulse
  set $i = $i + 1
end
