# Appendix 7a, exercise 1: the support displacement switched off, without recompiling. Every step,
# correctPositions() starts with supportStep = 0, as if the integrator's share s were 0: only the
# overlap is removed (add --csv out.csv to the command line to watch the sticky box creep).
# Breakpoints by function name, so they do not move when lines do; run from the repository root.
#   interactive:  gdb -x lectures/gdb/07a-no-support.gdb --args build/debug/stepwise run config/lesson07_incline.scene --duration 2
#   all at once:  gdb -q -batch -x lectures/gdb/07a-no-support.gdb --args build/debug/stepwise run config/lesson07_incline.scene --duration 2
break stepwise::correctPositions
commands
silent
set var supportStep = 0
continue
end
run
