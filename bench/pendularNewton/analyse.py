"""Summary of bench/pendularNewton: CPU time, steps, iterations per step
and T - reference at 1, 2, 5 cm at 1, 3 and 12 h for both engines."""
import csv
import os
import re
import sys

work = sys.argv[1]
H = 0.1


def field(path):
    txt = open(path).read()
    m = re.search(r'internalField\s+nonuniform\s+List<scalar>\s*(\d+)\s*\(', txt)
    return [float(v) for v in txt[m.end():].split(')')[0].split()[:int(m.group(1))]]


def interp(z, zs, vs):
    pts = sorted(zip(zs, vs))
    for (a, va), (b, vb) in zip(pts, pts[1:]):
        if a <= z <= b:
            return va + (vb - va)*(z - a)/(b - a)


print('1-D column, 12 h of heating (model A); T - reference [K] at 1, 2, 5 cm')
print('  %-22s %8s %6s %6s %7s %6s  %s' % ('run', 'CPU [s]', 'steps', 'rej.', 'iter.', 'it/st',
                                           '1 h | 3 h | 12 h'))
for case, N, refN, runs in (
        ('column100', 100, 200, ('segregated', 'newton')),
        ('column500', 500, 500, ('segregated', 'newton', 'newton_before', 'newton_dT1', 'newton_dT4',
                               'bdf2_tol0.03', 'bdf2_tol0.1', 'bdf2_tol0.1_before', 'bdf2_tol0.3',
                               'bdf2_tol1', 'defaults'))):
    depth = [H - (i + 0.5)*H/N for i in range(N)]
    for engine in runs:
        d = os.path.join(work, '%s_%s' % (case, engine))
        if engine.endswith('_before') and not os.path.isdir(d):
            continue
        try:
            u, s, e, m = open(os.path.join(d, 'time.txt')).read().split()[:4]
            log = open(os.path.join(d, 'log.pendularFoam')).read()
        except (OSError, ValueError):
            print('  %-22s failed' % os.path.basename(d))
            continue
        steps = log.count('\npendularFoam:')
        iters = sum(int(x) for x in re.findall(r'iterations = (\d+)', log))
        rej = sum(int(x) for x in re.findall(r'rejected = (\d+)', log))
        cols = []
        for t in (3600, 10800, 43200):
            try:
                T = field(os.path.join(d, '%d/T' % t))
            except OSError:
                cols.append('-')
                continue
            rows = list(csv.DictReader(open(os.path.join(work, 'reference%d/profile_%d.csv' % (refN, t)))))
            zr = [float(r['z']) for r in rows]
            Tr = [float(r['T']) for r in rows]
            cols.append(' '.join('%+.3f' % (interp(z, depth, T) - interp(z, zr, Tr))
                                 for z in (0.01, 0.02, 0.05)))
        print('  %-22s %8.2f %6d %6d %7d %6.2f  %s' % (os.path.basename(d), float(u) + float(s), steps,
                                                    rej, iters, iters/max(steps, 1), ' | '.join(cols)))
