# Breakpoints named by the code at the line, not by its number.
#
# The lecture sessions (lectures/gdb/NN-*.gdb) stop at one statement inside
# a function. A line number goes stale as soon as a line is added above it;
# the statement's own text does not. So the sessions say
#
#     source lectures/gdb/stepwise.py
#     break-at impulse_resolver.cpp "c.targetSeparation = e * approachAtTouch;"
#     break-at impulse_resolver.cpp "c.resting = approachAtTouch <=" if vn < 0
#     tbreak-at impulse_resolver.cpp "rememberImpulses(contacts, constraints, workspace);"
#     until-at impulse_resolver.cpp "for (ContactConstraint& c : constraints) {"
#
# Each command finds the one line of that file under src/ that contains the
# text (exact characters, spaces included; write \" for a quote inside it),
# prints the gdb command it runs ("-> break impulse_resolver.cpp:80"), and
# runs it: break, tbreak or until at FILE:LINE, with the `if CONDITION` if
# one is given. If the text is on no line, or on more than one, it stops the
# script with an error that says so: fix the text, never guess a number.
# `+N` after the text moves N lines down, for a line with no text of its own.
#
# tests/test_lectures.cpp ([lectures]) checks every anchor of every session
# the same way, so a change to src/ that breaks one fails the tests.
import os
import re

import gdb

SOURCE_ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "src")
ANCHOR = re.compile(r'^(\S+)\s+"((?:[^"\\]|\\.)*)"\s*(?:\+(\d+))?\s*(?:if\s+(.+))?$')


def find_file(name):
    """The one file under src/ whose path ends with NAME (e.g. world.cpp or world/world.cpp)."""
    found = []
    for folder, _, files in os.walk(SOURCE_ROOT):
        for file in files:
            path = os.path.normpath(os.path.join(folder, file))
            if path.endswith(os.sep + name):
                found.append(path)
    if len(found) != 1:
        raise gdb.GdbError(f"{name}: {len(found)} files of that name under src/, need exactly 1")
    return found[0]


def find_line(name, text):
    """The line number (from 1) of the one line of src/.../NAME containing TEXT."""
    with open(find_file(name), encoding="utf-8") as source:
        lines = [number for number, line in enumerate(source, 1) if text in line]
    if len(lines) != 1:
        where = "lines " + ", ".join(str(n) for n in lines) if lines else "no line"
        raise gdb.GdbError(f'{name}: "{text}" is on {where}; it must be on exactly one line')
    return lines[0]


class AnchoredCommand(gdb.Command):
    """CMD FILE "TEXT" [+N] [if CONDITION]: gdb's break, tbreak or until at the line of FILE containing TEXT."""

    def __init__(self, name, gdb_command):
        super().__init__(name, gdb.COMMAND_BREAKPOINTS)
        self.gdb_command = gdb_command

    def invoke(self, argument, from_tty):
        match = ANCHOR.match(argument.strip())
        if not match:
            raise gdb.GdbError(f'usage: {self.gdb_command}-at FILE "TEXT" [+N] [if CONDITION]')
        name, text, offset, condition = match.groups()
        text = text.replace('\\"', '"').replace("\\\\", "\\")
        line = find_line(name, text) + int(offset or 0)
        location = f"{name}:{line}"
        command = f"{self.gdb_command} {location}" + (f" if {condition}" if condition else "")
        print(f"-> {command}")
        gdb.execute(command, from_tty)


AnchoredCommand("break-at", "break")
AnchoredCommand("tbreak-at", "tbreak")
AnchoredCommand("until-at", "until")
