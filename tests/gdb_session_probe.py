# What tests/test_gdb_sessions.cpp needs to know of a gdb session besides its output: which
# breakpoints it set, and which of them stopped the program. A breakpoint whose command list
# starts with `silent` prints nothing when it stops (03-minus-vn.gdb, 08-constraint-solver.gdb),
# so only gdb's own events can show that it stopped. Sourced before the session
# (gdb -batch -ex "source tests/gdb_session_probe.py" -x SESSION), it prints one line per event:
#
#   [gdb-probe] created N LOCATION     a breakpoint the session set (break, tbreak, break-at, start)
#   [gdb-probe] stop N[,M…] FUNCTION   the program stopped at breakpoint N, in FUNCTION
#   [gdb-probe] exited CODE            the program ended by itself
#
# A condition that is false is not a stop: gdb reports only the stops it makes.
import gdb


def created(breakpoint):
    if breakpoint.visible and breakpoint.number > 0:
        print(f"[gdb-probe] created {breakpoint.number} {breakpoint.location}", flush=True)


def stopped(event):
    if not isinstance(event, gdb.BreakpointEvent):
        return  # the end of a step, next or finish: the session's own command, not a breakpoint
    numbers = ",".join(str(b.number) for b in event.breakpoints if b.number > 0)
    function = gdb.selected_frame().function()
    print(f"[gdb-probe] stop {numbers} {function.name if function else '?'}", flush=True)


def exited(event):
    code = event.exit_code if hasattr(event, "exit_code") else "?"
    print(f"[gdb-probe] exited {code}", flush=True)


gdb.events.breakpoint_created.connect(created)
gdb.events.stop.connect(stopped)
gdb.events.exited.connect(exited)
