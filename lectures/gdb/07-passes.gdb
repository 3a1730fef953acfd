# Lecture 7, session D: one upper corner of the sticky box over the ten passes of the incline's first step.
# Line numbers are those of the commit named in the lecture; check them if the file has changed.
#   interactive:  gdb -x lectures/gdb/07-passes.gdb --args build/debug/stepwise run config/lesson07_incline.scene --steps 1
#   all at once:  gdb -q -batch -x lectures/gdb/07-passes.gdb --args build/debug/stepwise run config/lesson07_incline.scene --steps 1
set trace-commands on
break impulse_resolver.cpp:183
run
p constraints[6].a->name
p constraints[6].rA
set $corner = &constraints[6]
delete 1
set trace-commands off
break impulse_resolver.cpp:135 if &c == $corner
commands
silent
printf "j %.6f -> %.6f   jt (%+.6f, %+.6f)   mu*j %.6f\n", previous, c.normalImpulse, total[0], total[1], limit
continue
end
continue
