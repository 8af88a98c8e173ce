#!/usr/bin/env python3
"""tutorialTimeScheme: a tutorial's runs with backward Euler and with BDF2.

    compare.py FIGURES EULER_CASE BDF2_CASE

For every log.pendularFoam under each case: steps, Newton iterations,
rejected sub-steps (tests/lib/hearthcheck.py's count, as the cost budgets)
and CPU time (the last ExecutionTime); their totals; then the figures of
FIGURES (a test's file: name, printed value, tolerance or 'below') that
each case's figures.csv holds outside the tolerance.
"""
import glob
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                '..', '..', 'tests', 'lib'))
import hearthcheck as hc        # noqa: E402


def costs(case):
    out = {}
    for log in sorted(glob.glob(os.path.join(case, '**', 'log.pendularFoam'),
                                recursive=True)):
        c = hc.read_solver_cost(log)
        cpu = re.findall(r'^ExecutionTime = (\S+)', open(log).read(), re.M)
        out[os.path.relpath(os.path.dirname(log), case)] = (
            c['steps'], c['iterations'], c['rejected'],
            float(cpu[-1]) if cpu else float('nan'))
    return out


def outside(figures_file, case):
    figs = hc.read_figures(os.path.join(case, 'figures.csv'))
    rows = [line.split('#')[0].split() for line in open(figures_file)]
    rows = [r for r in rows if len(r) == 3]
    bad = []
    for name, printed, tol in rows:
        ref = float(printed.replace('_', ''))
        if name not in figs:
            bad.append((name, printed, tol, None))
            continue
        v = figs[name][0]
        ok = abs(v) < ref if tol == 'below' else abs(v - ref) <= float(tol)
        if not ok:
            bad.append((name, printed, tol, v))
    return len(rows), bad


def main(figures_file, euler, bdf2):
    ce, cb = costs(euler), costs(bdf2)
    print('pendularFoam runs: steps, Newton iterations, rejected, CPU [s];'
          ' backward Euler | BDF2 (localErrorTol 1)')
    tot = {'e': [0, 0, 0, 0.0], 'b': [0, 0, 0, 0.0]}
    for run in sorted(set(ce) | set(cb)):
        e, b = ce.get(run), cb.get(run)
        print('  %-36s %s | %s' % (run, e, b))
        for k, x in (('e', e), ('b', b)):
            if x:
                for i in range(4):
                    tot[k][i] += x[i] if x[i] == x[i] else 0
    print('  %-36s %d %d %d %.1f | %d %d %d %.1f' % (
        'total', *tot['e'], *tot['b']))
    print('  BDF2/Euler: steps %.3f, iterations %.3f, CPU %.3f' % (
        tot['b'][0]/max(tot['e'][0], 1), tot['b'][1]/max(tot['e'][1], 1),
        tot['b'][3]/max(tot['e'][3], 1e-30)))
    for label, case in (('backward Euler', euler), ('BDF2', bdf2)):
        n, bad = outside(figures_file, case)
        print('%s: %d of the %d figures of %s outside their tolerance'
              % (label, len(bad), n, os.path.relpath(figures_file)))
        for name, printed, tol, v in bad:
            print('  %-40s printed %-9s tolerance %-8s run %s'
                  % (name, printed, tol, 'missing' if v is None else '%.6g' % v))


if __name__ == '__main__':
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    main(*sys.argv[1:])
