#!/usr/bin/env python3
"""compareEngines.py SEGREGATED NEWTON: pendularFoam's step by the
segregated engine (case SEGREGATED) against the same step by the Newton
engine (case NEWTON), tests/pendularResidual 2B: T, p, W of every cell at
the latest time within the engines' tolerances of each other, and the
water, air and energy balances of the Newton run within 1e-10.

Tolerances: the case's TTol 1e-9 K, pTol 1e-5 Pa, WTol 1e-12 (relative
to the largest W^n) bound each engine's distance to the discrete
solution (the segregated one on its updates, Newton on its residuals and
updates): 10 times them allowed for the difference of the two."""
import os
import sys

from hearthcheck import read_internal_field, worst_relative_imbalance
from hearthTutorial import time_dirs

seg, newton = sys.argv[1], sys.argv[2]
tol = {'T': 1e-8, 'p': 1e-4}
ok = True
last = {c: time_dirs(c)[-1] for c in (seg, newton)}
if os.path.basename(last[seg]) != os.path.basename(last[newton]):
    sys.exit('different latest times: %s, %s' % (last[seg], last[newton]))
Wseg = read_internal_field(os.path.join(last[seg], 'W'))
tol['W'] = 1e-11*max(abs(w) for w in Wseg)
for f in ('T', 'p', 'W'):
    a = read_internal_field(os.path.join(last[seg], f))
    b = read_internal_field(os.path.join(last[newton], f))
    if len(a) != len(b):
        sys.exit('%s: %d and %d values' % (f, len(a), len(b)))
    d = max(abs(x - y) for x, y in zip(a, b))
    good = d <= tol[f]
    ok &= good
    print('    %s %s: max |newton - segregated| = %.3g (allowed %.3g)'
          % ('ok  ' if good else 'FAIL', f, d, tol[f]))
imb = worst_relative_imbalance(os.path.join(newton, 'log.pendularFoam'))
good = imb <= 1e-10
ok &= good
print('    %s Newton run: worst relative imbalance %.3g (allowed 1e-10)'
      % ('ok  ' if good else 'FAIL', imb))
sys.exit(0 if ok else 1)
