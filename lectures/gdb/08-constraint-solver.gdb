# Lecture 8: one contact of the 100 kg box on the 1 kg box, and one of the 1 kg box on the ground,
# over the 16 substeps of the first two steps (lectures/08-constraint-solver.md, "Step through it in gdb").
# Breakpoints by function name, so they do not move when lines do.
#   interactive:  gdb -x lectures/gdb/08-constraint-solver.gdb --args build/debug/stepwise run config/lesson08_heavy_on_light.scene --steps 2
#   all at once:  gdb -q -batch -x lectures/gdb/08-constraint-solver.gdb --args build/debug/stepwise run config/lesson08_heavy_on_light.scene --steps 2
# Contact 0 is a corner of the light box's top face against the heavy box (A = light, B = heavy,
# normal +y); contact 4 is a corner of the light box's bottom face on the ground (normal -y).
set pagination off
# Steps and substeps count from 1, as stepwise trace counts them ("step 1 [1/16]").
set $step = 0
set $sub = 1

# Stage 4, once a step: contacts -> SolverContact (what a pass reads) and ContactStart (where it came from), warm-started from the impulses kept last step.
break stepwise::prepareContacts
commands
silent
set $step = $step + 1
set $sub = 1
printf "--- step %d, prepareContacts: %d contacts, %d impulses kept from the last step\n", $step, contacts._M_extent._M_extent_value, workspace.previousImpulses._M_impl._M_finish - workspace.previousImpulses._M_impl._M_start
continue
end

# Stage 6 and 7, every substep: solveContacts(useBias=true) is the solve, (useBias=false) the relax pass.
# At the relax pass's entry the accumulated impulses are those the solve pass left.
break stepwise::solveContacts
commands
silent
set $c0 = &workspace.contacts._M_impl._M_start[0]
set $c4 = &workspace.contacts._M_impl._M_start[4]
set $s0 = &workspace.starts._M_impl._M_start[0]
set $s4 = &workspace.starts._M_impl._M_start[4]
if useBias
  if $sub == 1
    printf "contact 0: normalMass %.6f kg, startSeparation %+.3e m; contact 4: normalMass %.6f kg, startSeparation %+.3e m\n", $c0->normalMass, $s0->startSeparation, $c4->normalMass, $s4->startSeparation
    printf "substep  lambda0 in -> after solve    lambda4 in -> after solve   (N s)\n"
  end
  set $in0 = $c0->normalImpulse
  set $in4 = $c4->normalImpulse
else
  printf "%5d    %.6f -> %.6f      %.6f -> %.6f\n", $sub, $in0, $c0->normalImpulse, $in4, $c4->normalImpulse
  set $sub = $sub + 1
end
continue
end

# After the 16 substeps: bounces (none here: Elasticity=0), then the impulses are stored for the next step.
break stepwise::applyRestitution
commands
silent
printf "end of step %d: lambda0 %.6f N s, lambda4 %.6f N s, heavy box y %.9f m, light box y %.9f m\n", $step, workspace.contacts._M_impl._M_start[0].normalImpulse, workspace.contacts._M_impl._M_start[4].normalImpulse, workspace.dynamics._M_ptr[workspace.starts._M_impl._M_start[0].refB.index].position.y, workspace.dynamics._M_ptr[workspace.starts._M_impl._M_start[0].indexA].position.y
continue
end

run
