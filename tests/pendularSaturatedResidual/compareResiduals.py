#!/usr/bin/env python3
# compareResiduals.py SERIAL PARALLEL: the residual fields Rw, Ra, RE
# (time 0) of testPendularSaturatedResidual -parallelResidual, serial and
# reconstructed from 2 ranks: max |R_par - R_ser| within 1e-9 of max
# |R_ser| (round-off of the face sums taken in another order; the project's
# serial = parallel tolerance)
import sys, re
def read(f):
    s = open(f).read()
    m = re.search(r'internalField\s+nonuniform\s+List<scalar>\s*(\d+)\s*\((.*?)\)\s*;', s, re.S)
    return [float(v) for v in m.group(2).split()]
a, b = sys.argv[1], sys.argv[2]
worst = 0
for n in ('Rw', 'Ra', 'RE'):
    s, p = read(f'{a}/0/{n}'), read(f'{b}/0/{n}')
    assert len(s) == len(p) and len(s) > 0
    scale = max(abs(v) for v in s)
    e = max(abs(x - y) for x, y in zip(s, p))/scale
    print(f'{n}: max |R_par - R_ser|/max |R_ser| = {e:.3g} ({len(s)} cells)')
    worst = max(worst, e)
sys.exit(0 if worst <= 1e-9 else 1)
