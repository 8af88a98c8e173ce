#!/usr/bin/env python3
"""pitPendular3D benchmark: the cost of each run (wall and CPU time, steps,
nonlinear iterations per step, rejected sub-steps, peak memory of each
rank), the ratios pendularFoam/ahcFoam and full range/pendular, the 2-rank
parallel efficiency and the memory per million cells, from log.<solver>
(the step lines of either solver, its balances) and log.time
(/usr/bin/time -v of each rank, log.time.N).

    analyse.py NCELLS NCELLS_COARSE HOURS RUN...

RUN: a folder NAME_RANKS (pendular_1, pendular_2, ahc_1, ahc_2,
pendularCoarse_1, segregated_1, bjacobi_1, fullRange_1, fullRange_2).
"""
import glob
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                '..', '..', 'etc', 'python'))
import hearthTutorial as ht       # noqa: E402


def hms(s):
    """[h:]mm:ss.ss -> seconds"""
    x = 0.0
    for part in s.split(':'):
        x = 60*x + float(part)
    return x


def run_figures(case):
    solver = 'ahcFoam' if case.startswith('ahc') else 'pendularFoam'
    log = os.path.join(case, 'log.' + solver)
    text = open(log).read()
    if not re.search(r'^End\s*$', text, re.M):
        sys.exit('pitPendular3D: %s has no End' % log)
    steps, rejected, cpu_master, clock = ht.log_stats(log)
    iters = sum(int(m) for m in re.findall(
        r'^%s: deltaT = \S+, iterations = (\d+)' % solver, text, re.M))
    imbalance = [abs(float(x)) for x in re.findall(
        r'imbalance += \S+ \(relative (\S+)\)', text)]
    times = sorted(glob.glob(os.path.join(case, 'log.time.*')))
    if len(times) != int(case.rsplit('_', 1)[1]):
        sys.exit('pitPendular3D: %s: %d log.time.N for %s ranks'
                 % (case, len(times), case.rsplit('_', 1)[1]))
    t = ''.join(open(f).read() for f in times)
    rss = [int(m)/1024 for m in re.findall(
        r'Maximum resident set size \(kbytes\): (\d+)', t)]
    wall = max(hms(m) for m in re.findall(
        r'Elapsed \(wall clock\) time.*: (\S+)', t))
    cpu = sum(float(m) for m in re.findall(
        r'(?:User|System) time \(seconds\): (\S+)', t))
    return dict(solver=solver, ranks=int(case.rsplit('_', 1)[1]),
                steps=steps, iters=iters, rejected=rejected, wall=wall,
                cpu=cpu, rss=rss, imbalance=max(imbalance or [float('nan')]))


def main():
    n_cells, n_coarse = int(sys.argv[1]), int(sys.argv[2])
    hours = float(sys.argv[3])
    runs = dict((c, run_figures(c)) for c in sys.argv[4:])
    print('pitPendular3D: %d cells (coarse variant %d), %g h of fire'
          % (n_cells, n_coarse, hours))
    print('  %-17s %-13s %5s %9s %9s %6s %7s %8s %8s %18s %10s' % (
        'run', 'solver', 'ranks', 'wall [s]', 'CPU [s]', 'steps',
        'iters', 'it/step', 'rejected', 'peak RSS [MB]',
        'imbalance'))
    for c, r in runs.items():
        print('  %-17s %-13s %5d %9.1f %9.1f %6d %7d %8.2f %8d %18s %10.2g'
              % (c, r['solver'], r['ranks'], r['wall'], r['cpu'],
                 r['steps'], r['iters'], r['iters']/max(r['steps'], 1),
                 r['rejected'],
                 '+'.join('%.0f' % x for x in r['rss'])
                 + ('' if len(r['rss']) == 1 else ' = %.0f' % sum(r['rss'])),
                 r['imbalance']))
    print('  (imbalance: the largest relative imbalance over the writes,'
          ' of the water, air and energy balances of pendularFoam, of the'
          ' energy of ahcFoam)')

    def ratio(a, b, what):
        if a in runs and b in runs:
            print('  %-52s %8.2f %8.2f' % (
                what, runs[a]['wall']/runs[b]['wall'],
                runs[a]['cpu']/runs[b]['cpu']))

    print('Ratios (wall, CPU; on a loaded machine the CPU times are the'
          ' meaningful ones):')
    ratio('pendular_1', 'ahc_1', 'pendularFoam / ahcFoam, 1 rank')
    ratio('pendular_2', 'ahc_2', 'pendularFoam / ahcFoam, 2 ranks')
    ratio('segregated_1', 'pendular_1',
          'pendularFoam segregated / Newton engine, 1 rank')
    ratio('bjacobi_1', 'pendular_1',
          'pendularFoam block Jacobi / cpr (default), 1 rank')
    ratio('fullRange_1', 'pendular_1', 'full range / pendular, 1 rank')
    ratio('fullRange_2', 'pendular_2', 'full range / pendular, 2 ranks')
    print('Parallel efficiency on 2 ranks, E = t1/(2 t2) (wall times; and'
          ' the CPU time of 1 rank over that of the 2 ranks, summed):')
    for name in ('pendular', 'ahc', 'fullRange'):
        a, b = name + '_1', name + '_2'
        if a in runs and b in runs:
            print('  %-52s %8.3f %8.3f' % (
                name, runs[a]['wall']/(2*runs[b]['wall']),
                runs[a]['cpu']/runs[b]['cpu']))
    print('Peak memory (max resident set size, summed over the ranks):')
    for c, r in runs.items():
        n = n_coarse if 'Coarse' in c else n_cells
        print('  %-17s %8.0f MB, %8.0f MB per million cells (the'
              ' libraries included)' % (c, sum(r['rss']),
                                        sum(r['rss'])/(n/1e6)))
    if 'pendular_1' in runs and 'pendularCoarse_1' in runs:
        dm = sum(runs['pendular_1']['rss']) \
            - sum(runs['pendularCoarse_1']['rss'])
        print('  pendularFoam, 1 rank, per cell from the two meshes:'
              ' (%.0f - %.0f) MB / (%d - %d) cells = %.0f MB per million'
              ' cells' % (sum(runs['pendular_1']['rss']),
                          sum(runs['pendularCoarse_1']['rss']),
                          n_cells, n_coarse, dm/((n_cells - n_coarse)/1e6)))


if __name__ == '__main__':
    main()
