#!/usr/bin/env python3
"""Summarise bench/coupledBlock/run: RUNDIR/coupled/log.np{1,2} (the
'newtonCost:' lines of testCoupledBlockSystem -newtonCost and /usr/bin/time
-v), RUNDIR/laplacian/log.np{1,2} and wall.np{1,2} (stamp.py).

    analyse.py RUNDIR"""
import os
import re
import sys

runDir = sys.argv[1]


def rss_mb(log):
    """Max resident set size of each process in the log [MB]."""
    with open(log) as f:
        return [int(m) / 1024 for m in
                re.findall(r'Maximum resident set size \(kbytes\): (\d+)',
                           f.read())]


def coupled(np, variant=''):
    log = os.path.join(runDir, 'coupled', 'log.%snp%d' % (variant, np))
    with open(log) as f:
        txt = f.read()
    cells = int(re.search(r'newtonCost: cells (\d+)', txt).group(1))
    its = int(re.search(r'Newton iterations (\d+)', txt).group(1))
    ksp = float(re.search(r'KSP iterations per solve (\S+)', txt).group(1))
    m = re.search(r'per iteration: assembly (\S+) s, solve (\S+) s, '
                  r'total (\S+) s', txt)
    c = re.search(r'CPU of the master: assembly (\S+) s, solve (\S+) s, '
                  r'total (\S+) s', txt)
    return cells, its, ksp, float(m.group(1)), float(m.group(2)), \
        float(m.group(3)), rss_mb(log), float(c.group(1)), \
        float(c.group(2)), float(c.group(3))


def laplacian(np):
    """Wall time per step over steps 2 .. n-1 (the first: start-up; the
    last writes the fields)."""
    with open(os.path.join(runDir, 'laplacian', 'wall.np%d' % np)) as f:
        t = [float(l) for l in f if not l.startswith('start')]
    steps = t[1:-1]
    # CPU time of the master: ExecutionTime over the same steps
    with open(os.path.join(runDir, 'laplacian', 'log.np%d' % np)) as f:
        cpu = [float(x) for x in
               re.findall(r'^ExecutionTime = (\S+) s', f.read(), re.M)]
    cpu = cpu[1:-1]
    return (steps[-1] - steps[0]) / (len(steps) - 1), \
        rss_mb(os.path.join(runDir, 'laplacian', 'log.np%d' % np)), \
        (cpu[-1] - cpu[0]) / (len(cpu) - 1)


res = {}
for variant, title in (('', 'central differences'),
                       ('forward.', 'forward differences')):
    print('Jacobian by %s' % title)
    for np in (1, 2):
        cells, its, ksp, ta, ts, tt, rss, ca, cs, ct = coupled(np, variant)
        tl, rssl, cl = laplacian(np)
        res[variant, np] = tt
        print('  %d rank(s), %d cells: Newton %d iterations, %.1f GMRES '
              'iterations per solve' % (np, cells, its, ksp))
        print('    per Newton iteration: assembly %.3f s, solve %.3f s, '
              'total %.3f s = %.2f us per cell' %
              (ta, ts, tt, 1e6 * tt / cells))
        print('    laplacianFoam step: %.4f s = %.3f us per cell' %
              (tl, 1e6 * tl / cells))
        print('    ratio Newton iteration / laplacianFoam step: %.1f' %
              (tt / tl))
        print('    CPU of the master: Newton iteration %.3f s (assembly %.3f,'
              ' solve %.3f) = %.2f us per cell; laplacianFoam step %.4f s ='
              ' %.3f us per cell; ratio %.1f' %
              (ct, ca, cs, 1e6 * ct / cells, cl, 1e6 * cl / cells, ct / cl))
        print('    peak RSS: coupled %s MB (%.0f MB per million cells), '
              'laplacianFoam %s MB (%.0f MB per million cells)' %
              (' + '.join('%.0f' % r for r in rss), sum(rss) / cells * 1e6,
               ' + '.join('%.0f' % r for r in rssl),
               sum(rssl) / cells * 1e6))
    print('  parallel efficiency of a Newton iteration t1/(2 t2): %.2f' %
          (res[variant, 1] / (2 * res[variant, 2])))
