#!/usr/bin/env python3
"""Observed orders of convergence from pendularColumn1D runs.

Usage: convergenceOrders.py DIR_N DIR_2N DIR_4N [DIR_8N]
At each output time prints the values, the successive differences and
log2 of the ratio of successive differences (the observed order).
"""
import sys
import csv, glob, os, math
KEYS = ['T_1cm', 'T_2cm', 'T_5cm', 'front', 'water']
def outputs(d):
    times = {float(f.split('_')[-1][:-4]) for f in glob.glob(os.path.join(d, 'profile_*.csv'))}
    rows = {}
    for r in csv.DictReader(open(os.path.join(d, 'history.csv'))):
        t = float(r['t'])
        if t in times: rows[t] = {k: float(r[k]) for k in KEYS}
    return rows
runs = [outputs(d) for d in sys.argv[1:]]
for t in sorted(runs[-1]):
    print('t = %g' % t)
    for k in KEYS:
        v = [r[t][k] for r in runs]
        d = [v[i] - v[i+1] for i in range(len(v) - 1)]
        p = ['%.2f' % math.log2(abs(d[i]/d[i+1])) if d[i+1] != 0 and d[i] != 0 else '-' for i in range(len(d) - 1)]
        print('  %-6s values %s  diffs %s  orders %s' % (k, ' '.join('%.8g' % x for x in v), ' '.join('%+.2e' % x for x in d), ' '.join(p)))
