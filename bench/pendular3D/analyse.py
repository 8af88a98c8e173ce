#!/usr/bin/env python3
"""pendular3D benchmark: times per step, per cell and step and per cell and
nonlinear iteration on 1 and 2 ranks, parallel efficiency and peak memory,
from log.pendularFoam (ClockTime, ExecutionTime, the iteration counts of
each step) and log.time (/usr/bin/time -v of each rank).

    analyse.py NCELLS SERIALDIR PARALLELDIR

The step time is the clock time from the end of the first step to the end
of the last (setup and first step excluded; ClockTime has a resolution of
1 s, ExecutionTime, the master's CPU time, is given too).
"""
import re
import sys


def run_figures(case):
    log = open(case + '/log.pendularFoam').read()
    if not re.search(r'^End\s*$', log, re.M):
        sys.exit('pendular3D: %s/log.pendularFoam has no End' % case)
    clock = [float(x) for x in re.findall(r'ClockTime = (\S+) s', log)]
    cpu = [float(x) for x in re.findall(r'ExecutionTime = (\S+) s', log)]
    steps = re.findall(r'pendularFoam: deltaT = \S+, iterations = (\d+), '
                       r'sub-steps = (\d+), rejected = (\d+)', log)
    iters = [int(s[0]) for s in steps]
    rejected = sum(int(s[2]) for s in steps)
    t = open(case + '/log.time').read()
    rss = [int(m) for m in re.findall(
        r'Maximum resident set size \(kbytes\): (\d+)', t)]
    wall = re.findall(r'Elapsed \(wall clock\) time.*: (\S+)', t)
    return dict(n=len(iters), clock=clock[-1] - clock[0],
                cpu=cpu[-1] - cpu[0], iters=sum(iters[1:]), rejected=rejected,
                total=clock[-1], rss=rss, wall=wall)


def main():
    n_cells = int(sys.argv[1])
    r1 = run_figures(sys.argv[2])
    r2 = run_figures(sys.argv[3])
    print('pendular3D: %d cells, %d fixed steps (timed: steps 2-%d)'
          % (n_cells, r1['n'], r1['n']))
    print('  %-5s %8s %8s %9s %10s %12s %12s %9s %15s' % (
        'ranks', 'wall [s]', 'steps [s]', 'iters', 's/step',
        'us/cell/step', 'us/cell/iter', 'rejected', 'peak RSS [MB]'))
    for ranks, r in ((1, r1), (2, r2)):
        steps = r['n'] - 1
        print('  %-5d %8.0f %8.0f %9d %10.2f %12.2f %12.3f %9d %15s' % (
            ranks, r['total'], r['clock'], r['iters'], r['clock']/steps,
            1e6*r['clock']/steps/n_cells,
            1e6*r['clock']/max(r['iters'], 1)/n_cells, r['rejected'],
            '+'.join('%.0f' % (x/1024) for x in r['rss'])
            + ' = %.0f' % (sum(r['rss'])/1024)))
    e_step = r1['clock']/max(2*r2['clock'], 1e-9)
    e_iter = (r1['clock']/max(r1['iters'], 1))/max(2*r2['clock']/max(r2['iters'], 1), 1e-9)
    print('  parallel efficiency on 2 ranks: per step E = t1/(2 t2) = %.3f,'
          ' per nonlinear iteration %.3f' % (e_step, e_iter))
    print('  master CPU time of the steps: %.1f s (1 rank), %.1f s (2 ranks)'
          % (r1['cpu'], r2['cpu']))
    print('  memory: %.0f MB per million cells on 1 rank, %.0f on 2'
          % (sum(r1['rss'])/1024/(n_cells/1e6),
             sum(r2['rss'])/1024/(n_cells/1e6)))


if __name__ == '__main__':
    main()
