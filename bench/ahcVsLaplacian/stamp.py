#!/usr/bin/env python3
"""Copy a solver's output (stdin) to stdout and record the wall-clock time at
which each 'ExecutionTime = ...' line arrives (OpenFOAM flushes there).

    solver 2>&1 | python3 stamp.py STAMPFILE > log.solver

STAMPFILE gets 'start <t>' and then one '<t>' line per time step, with t from
time.monotonic() [s]. ClockTime in the log only has a 1 s resolution."""
import sys
import time

with open(sys.argv[1], 'w') as stamps:
    stamps.write('start %.6f\n' % time.monotonic())
    for line in sys.stdin:
        if line.startswith('ExecutionTime'):
            stamps.write('%.6f\n' % time.monotonic())
            stamps.flush()
        sys.stdout.write(line)
        sys.stdout.flush()
