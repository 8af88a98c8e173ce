"""ahcFoam with conductivityModel tabulated: the conductivity field of the
8 cells (written by writeObjects after one step at 20 C, where nothing
evaporates: sigma = 0 exactly) equals the table at alpha_l = theta_0/phi,
the table read and interpolated here independently (csv module, linear
interpolation; clamped above the last row as the case asks). Tolerance
1e-12 relative: the same linear formula in another order of operations."""
import csv
import os

import hearthcheck as hc

c = hc.Check('tabulatedConductivity ahcFoam')

rows = []
with open('constant/grainScale.csv') as f:
    for r in csv.reader(line for line in f if not line.startswith('#')):
        try:
            rows.append((float(r[0]), float(r[1])))
        except ValueError:
            pass                # the header line


def table(a):
    if a >= rows[-1][0]:
        return rows[-1][1]
    for (x0, y0), (x1, y1) in zip(rows, rows[1:]):
        if x0 <= a <= x1:
            return ((x1 - a)*y0 + (a - x0)*y1)/(x1 - x0)
    raise ValueError(a)


def field(path):
    with open(path) as f:
        text = f.read()
    body = text.split('internalField')[1]
    n = int(body.split('<scalar>')[1].split('(')[0])
    values = body.split('(', 1)[1].split(')')[0].split()
    assert len(values) == n
    return [float(v) for v in values]


theta = field('0/waterContent')
kappa = field(os.path.join('1', 'kappa'))
for t, k in zip(theta, kappa):
    a = t/0.4
    ref = table(a)
    c.le('kappa at alpha_l = %.4g: table %.10g (rel)' % (a, ref),
         abs(k - ref)/ref, 1e-12)
c.true('8 cells', len(kappa) == 8)
c.done()
