# Lecture 7, exercise 5: the sticky box's four corners after one pass of the first step (set kDefaultImpulseIterations = 1 and rebuild first).
# Line numbers are those of the commit named in the lecture; check them if the file has changed.
#   interactive:  gdb -x lectures/gdb/07-one-pass.gdb --args build/debug/stepwise run config/lesson07_incline.scene --steps 1
#   all at once:  gdb -q -batch -x lectures/gdb/07-one-pass.gdb --args build/debug/stepwise run config/lesson07_incline.scene --steps 1
set trace-commands on
break world.cpp:89 if stepCount_ == 0
run
delete 1
tbreak impulse_resolver.cpp:186
continue
set trace-commands off
set $i = 6
while $i < 10
  set $c = constraints[$i]
  printf "%d %-6s j %.6f  jt (%+.6f, %+.6f)  mu*j %.6f\n", $i, $c.a->name._M_dataplus._M_p, $c.normalImpulse, $c.tangentImpulse[0], $c.tangentImpulse[1], $c.friction * $c.normalImpulse
  set $i = $i + 1
end
