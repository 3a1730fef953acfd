# Appendix to lecture 8: the fast path on the three-ball stacks, one step
# (lectures/08a-appendix-the-fast-path.md, "Step through it in gdb").
# The debug build takes the plain path unless the scene says FastPath=true, so run it on a copy that does:
#   scene copy:  sed 's/Sleep=false/FastPath=true, Sleep=false/' config/lesson08_three_balls.scene > /tmp/three_balls_fast.scene
#   interactive:  gdb -x lectures/gdb/08a-fast-path.gdb --args build/debug/stepwise run /tmp/three_balls_fast.scene --steps 1
#   all at once:  gdb -q -batch -x lectures/gdb/08a-fast-path.gdb --args build/debug/stepwise run /tmp/three_balls_fast.scene --steps 1
# Breakpoints by function name, so they do not move when lines do.
set pagination off
# Substeps count from 1, as stepwise trace counts them ("step 1 [1/16]").
set $sub = 1

# solveRoundContactRange() is built three times (AVX-512, AVX2, any x86-64), and a small "resolver"
# picks one copy when the program starts. Stop in main first, so that the resolver has run
# and the breakpoint below stops only in the copy this processor uses.
start

# After batchRoundContacts(), before the substeps: the step packs its balls' state (packed_records.cpp).
# Here the round contacts are in their waves and batches, four lanes a batch.
break stepwise::packRecords
commands
silent
printf "--- %d round contacts (indices in workspace.contacts) in %d waves, %d batches of four lanes (- : an empty lane)\n", solver.roundContacts._M_impl._M_finish - solver.roundContacts._M_impl._M_start, fast.waves, fast.roundBatches._M_impl._M_finish - fast.roundBatches._M_impl._M_start
set $b = 0
while $b < fast.roundBatches._M_impl._M_finish - fast.roundBatches._M_impl._M_start
  set $batch = &fast.roundBatches._M_impl._M_start[$b]
  printf "batch %d, wave %d, contacts:", $b, $batch->wave
  set $lane = 0
  while $lane < 4
    if $batch->contact[$lane] == 0xffffffff
      printf "  -"
    else
      printf "  %d", $batch->contact[$lane]
    end
    set $lane = $lane + 1
  end
  printf "\n"
  set $b = $b + 1
end
printf "substep  batch 2's lambda_n after the solve pass, lane by lane (N s)\n"
continue
end

# Every substep: a solve pass (useBias true), then a relax pass (false) over the batches.
# At the relax pass's entry the lanes hold what the solve pass left.
break stepwise::solveRoundContactRange
commands
silent
if !useBias
  set $l = fast.roundBatches._M_impl._M_start[2].normalImpulse
  printf "%5d    %.9f  %.9f  %.9f  %.9f\n", $sub, $l[0], $l[1], $l[2], $l[3]
  set $sub = $sub + 1
end
continue
end

# After the last relax: the balls' packed state goes back to the objects, once a step.
break stepwise::unpackRecords
commands
silent
set $top = solver.bodyRecord._M_impl._M_start[2]
printf "unpackRecords: stands_top's object still at y = %.9f m; its packed centre (record %d) at y = %.9f m\n", solver.dynamics._M_ptr[2].position.y, $top, fast.centres._M_impl._M_start[$top].position.y
continue
end

continue
