# Lecture 7, session A (continued): the ImpulseReport of each contact of the bowling scene's first step, read in World::step() after stage 7.
# Breakpoints by function name, so they do not move when lines do.
#   interactive:  gdb -x lectures/gdb/07-report.gdb --args build/debug/stepwise run config/lesson07_bowling.scene --steps 1
#   all at once:  gdb -q -batch -x lectures/gdb/07-report.gdb --args build/debug/stepwise run config/lesson07_bowling.scene --steps 1
set trace-commands on
break stepwise::correctPositions
run
finish
p impulses_[0]
p impulses_[1]
