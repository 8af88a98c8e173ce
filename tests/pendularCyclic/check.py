#!/usr/bin/env python3
"""tests/pendularCyclic, 3: check.py PERIODIC HALF WALLS. The periodic
strip's cells 4-11 (x in [L/4, 3L/4]) against the half strip between walls
(8 cells, the same centres) at the latest time: T, p, W within 10
tolerances (TTol 1e-9 K, pTol 1e-5 Pa, WTol 1e-12 of the largest W: each
run's distance to its discrete solution is within its tolerances, the two
discrete solutions are the same by the sine's mirror symmetry about L/4
and 3L/4); the strip between walls at 0 and L (no cyclic pair) at least
1e3 TTol away from the periodic strip's T (the pair carries flux); the
periodic (Newton, with or without liquid
flow), half and walled runs' balances within 1e-10. A fourth argument, with
liquid flow (3L): the periodic run without it, whose W must differ."""
import os
import sys

import hearthcheck as hc
from hearthcheck import read_internal_field
from hearthTutorial import time_dirs

periodic, half, walls = sys.argv[1:4]
# with liquid flow (3L): the periodic run without it, whose W the liquid's
# capillary flux must have moved (1e-3 of max W at least: 0.24 measured)
dry = sys.argv[4] if len(sys.argv) > 4 else None
c = hc.Check('pendularCyclic mirror')
last = {d: time_dirs(d)[-1] for d in (periodic, half, walls)}
c.true('the same latest time',
       len(set(os.path.basename(t) for t in last.values())) == 1)
W = read_internal_field(os.path.join(last[periodic], 'W'))
tol = {'T': 1e-8, 'p': 1e-4, 'W': 1e-11*max(abs(w) for w in W)}
for f in ('T', 'p', 'W'):
    a = read_internal_field(os.path.join(last[periodic], f))[4:12]
    b = read_internal_field(os.path.join(last[half], f))
    c.true('%s: 8 cells in the half strip' % f, len(b) == 8)
    c.le('%s: max |strip cells 4-11 - half strip|' % f,
         max(abs(x - y) for x, y in zip(a, b)), tol[f])
a = read_internal_field(os.path.join(last[periodic], 'T'))
b = read_internal_field(os.path.join(last[walls], 'T'))
dWalls = max(abs(x - y) for x, y in zip(a, b))
c.true('T: max |periodic - walled strip| >= 1e-6 K (the pair carries flux)',
       dWalls >= 1e-6, '%.4g K' % dWalls)
if dry:
    a = read_internal_field(os.path.join(last[periodic], 'W'))
    b = read_internal_field(os.path.join(time_dirs(dry)[-1], 'W'))
    dW = max(abs(x - y) for x, y in zip(a, b))/max(abs(x) for x in a)
    c.true('W: max |with - without liquid flow|/max W >= 1e-3',
           dW >= 1e-3, '%.4g' % dW)
for d in (periodic, half, walls):
    c.le('%s: worst relative imbalance' % os.path.basename(d),
         hc.worst_relative_imbalance(os.path.join(d, 'log.pendularFoam')),
         1e-10)
c.done()
