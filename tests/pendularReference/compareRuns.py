#!/usr/bin/env python3
"""Compare pendularColumn1D runs at the output times (convergence study).

Usage: compareRuns.py REF RUN [RUN ...]
Prints, for each RUN, the differences RUN - REF of T at 1, 2, 5 cm, the
front depth and the total water at the rows of REF/history.csv whose time
has a profile_<t>.csv (the output times).
"""
import csv, glob, os, sys

KEYS = ['T_1cm', 'T_2cm', 'T_5cm', 'front', 'water']

def outputs(d):
    times = {float(f.split('_')[-1][:-4])
             for f in glob.glob(os.path.join(d, 'profile_*.csv'))}
    rows = {}
    with open(os.path.join(d, 'history.csv')) as fh:
        for r in csv.DictReader(fh):
            t = float(r['t'])
            if t in times:
                rows[t] = {k: float(r[k]) for k in KEYS}
    return rows

ref = outputs(sys.argv[1])
print('reference %s' % sys.argv[1])
for t in sorted(ref):
    print('  t=%6g  ' % t + '  '.join('%s=%.6g' % (k, ref[t][k]) for k in KEYS))
for d in sys.argv[2:]:
    run = outputs(d)
    print('%s - reference' % d)
    for t in sorted(ref):
        if t in run:
            print('  t=%6g  ' % t + '  '.join(
                '%s=%+.2e' % (k, run[t][k] - ref[t][k]) for k in KEYS))
