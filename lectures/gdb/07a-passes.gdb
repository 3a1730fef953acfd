# Appendix 7a, session B: one upper corner of the sticky box over the ten passes of the incline's first step.
# Breakpoints inside a function are named by the code at the line (break-at FILE "TEXT", from
# lectures/gdb/stepwise.py), so they follow the code when lines move; run from the repository root.
#   interactive:  gdb -x lectures/gdb/07a-passes.gdb --args build/debug/stepwise run config/lesson07_incline.scene --steps 1
#   all at once:  gdb -q -batch -x lectures/gdb/07a-passes.gdb --args build/debug/stepwise run config/lesson07_incline.scene --steps 1
source lectures/gdb/stepwise.py
set trace-commands on
break-at impulse_resolver.cpp "for (int pass = 0; pass < iterations; ++pass)"
run
p constraints[6].a->name
p constraints[6].rA
set $corner = &constraints[6]
delete 1
set trace-commands off
break-at impulse_resolver.cpp "applyImpulse(c, change);" if &c == $corner
commands
silent
printf "j %.6f -> %.6f   jt (%+.6f, %+.6f)   mu*j %.6f\n", previous, c.normalImpulse, total[0], total[1], limit
continue
end
continue
