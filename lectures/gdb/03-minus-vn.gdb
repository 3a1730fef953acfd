# Lecture 3, exercise: bounce with -v_n instead of v_c, without recompiling (add --csv out.csv to see the apexes).
# Line numbers are those of the commit named in the lecture; check them if the file has changed.
#   interactive:  gdb -x lectures/gdb/03-minus-vn.gdb --args build/debug/stepwise run /tmp/my_bounce.scene
#   all at once:  gdb -q -batch -x lectures/gdb/03-minus-vn.gdb --args build/debug/stepwise run /tmp/my_bounce.scene
break impulse_resolver.cpp:91 if vn < 0
commands
silent
set var approachAtTouch = -vn
continue
end
run
