"""Summary of bench/pendularColumn: CPU time, steps, iterations and the
temperatures at 1 h against the reference."""
import csv
import os
import re
import sys

work = sys.argv[1]
N, H = 500, 0.1
depth = [H - (i + 0.5)*H/N for i in range(N)]


def field(path):
    txt = open(path).read()
    m = re.search(r'internalField\s+nonuniform\s+List<scalar>\s*(\d+)\s*\(', txt)
    return [float(v) for v in txt[m.end():].split(')')[0].split()[:int(m.group(1))]]


def interp(z, zs, vs):
    pts = sorted(zip(zs, vs))
    for (a, va), (b, vb) in zip(pts, pts[1:]):
        if a <= z <= b:
            return va + (vb - va)*(z - a)/(b - a)


rows = list(csv.DictReader(open(os.path.join(work, 'reference/profile_3600.csv'))))
zr = [float(r['z']) for r in rows]
Tr = [float(r['T']) for r in rows]
user, sys_, wall, rss = open(os.path.join(work, 'reference.time')).read().split()
print('1-D column, 500 cells, 12 h of heating (model A)')
print('  %-34s %8s %7s %10s %8s  %s' % ('run', 'CPU [s]', 'steps', 'iterations', 'RSS [MB]',
                                         'T - reference at 1, 2, 5 cm, 1 h [K]'))
for name in ('accurate', 'default'):
    d = os.path.join(work, name)
    u, s, e, m = open(os.path.join(d, 'time.txt')).read().split()
    log = open(os.path.join(d, 'log.pendularFoam')).read()
    steps = log.count('\npendularFoam:')
    iters = sum(int(x) for x in re.findall(r'iterations = (\d+)', log))
    T = field(os.path.join(d, '3600/T'))
    dT = ['%+.3f' % (interp(z, depth, T) - interp(z, zr, Tr)) for z in (0.01, 0.02, 0.05)]
    print('  %-34s %8.2f %7d %10d %8.0f  %s' % ('pendularFoam, steps <= %s' % ('0.5 K, 30 s' if name == 'accurate' else '2 K, 600 s'),
                                              float(u) + float(s), steps, iters, float(m)/1024, ' '.join(dT)))
print('  %-34s %8.2f %7s %10s %8.0f' % ('reference (BDF2, Eigen), N = 500', float(user) + float(sys_),
                                        '-', '-', float(rss)/1024))
