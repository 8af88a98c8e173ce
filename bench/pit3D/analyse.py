#!/usr/bin/env python3
"""pit3D benchmark: wall time per simulated hour on 1 and 2 ranks, parallel
efficiency and peak memory, from log.ahcFoam (ClockTime, steps, iterations)
and log.time (/usr/bin/time -v of each rank).

    analyse.py NCELLS HOURS SERIALDIR PARALLELDIR
"""
import re
import sys


def run_figures(case):
    log = open(case + '/log.ahcFoam').read()
    if not re.search(r'^End\s*$', log, re.M):
        sys.exit('pit3D: %s/log.ahcFoam has no End' % case)
    clock = float(re.findall(r'ClockTime = (\S+) s', log)[-1])
    steps = len(re.findall(r'^Time = ', log, re.M))
    rejected = len(re.findall(r'step rejected', log))
    imbalance = re.findall(r'imbalance += \S+ \(relative (\S+)\)', log)
    rss = [int(m) for m in re.findall(
        r'Maximum resident set size \(kbytes\): (\d+)',
        open(case + '/log.time').read())]
    return clock, steps, rejected, imbalance[-1] if imbalance else '?', rss


def main():
    n_cells, hours = int(sys.argv[1]), float(sys.argv[2])
    t1, s1, r1, b1, rss1 = run_figures(sys.argv[3])
    t2, s2, r2, b2, rss2 = run_figures(sys.argv[4])
    mcells = n_cells/1e6
    print('pit3D: %d cells, %.2f h of fire' % (n_cells, hours))
    print('  %-8s %10s %14s %7s %9s %12s %14s' % (
        'ranks', 'wall [s]', 'wall/sim. h [s]', 'steps', 'rejected',
        'peak RSS [MB]', 'MB per Mcells'))
    for ranks, t, s, r, rss in ((1, t1, s1, r1, rss1), (2, t2, s2, r2, rss2)):
        total = sum(rss)/1024
        print('  %-8d %10.1f %14.1f %7d %9d %12s %14.0f' % (
            ranks, t, t/hours, s, r,
            '+'.join('%.0f' % (x/1024) for x in rss), total/mcells))
    print('  parallel efficiency on 2 ranks E = t1/(2 t2) = %.3f (goal >= 0.8)'
          % (t1/(2*t2)))
    print('  relative energy imbalance at the end: %s (1 rank), %s (2 ranks)'
          % (b1, b2))


if __name__ == '__main__':
    main()
