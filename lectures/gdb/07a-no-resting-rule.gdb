# Appendix 7a, exercise 3: the resting rule with no margin, without recompiling. After prepare() has
# applied the rule, c.resting becomes v_c <= 0, as if kRestingContactSteps were 0 (add --csv out.csv
# to the command line to see the ball hop).
# Breakpoints inside a function are named by the code at the line (break-at FILE "TEXT", from
# lectures/gdb/stepwise.py), so they follow the code when lines move; run from the repository root.
#   scene copy:  sed "s/0, 1.1, 0,/0, 0.1, 0,/; s/1, 0.8, Name=ball/1, 0.5, Name=ball/; s/Integrator=Verlet/Integrator=Euler/" config/lesson03_bounce.scene > /tmp/rest_Euler.scene
#   interactive:  gdb -x lectures/gdb/07a-no-resting-rule.gdb --args build/debug/stepwise run /tmp/rest_Euler.scene --duration 10
#   all at once:  gdb -q -batch -x lectures/gdb/07a-no-resting-rule.gdb --args build/debug/stepwise run /tmp/rest_Euler.scene --duration 10
source lectures/gdb/stepwise.py
break-at impulse_resolver.cpp "const Real e = c.resting ? Real(0) : material.elasticity;"
commands
silent
set var c.resting = approachAtTouch <= 0
continue
end
run
