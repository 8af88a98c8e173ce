"""soilProfile writes exactly the layer values and the Function1 profiles at
the cell centres. Usage: check.py column|tilted CASE [OTHER_CASE]

The expected values are computed here from the dictionaries' numbers and
the cell centres written by 'postProcess -func writeCellCentres' (17
digits: the exact doubles): depth = (C - origin) . direction/|direction|.
- layers with numbers: equal to the bit (the fields are written with 17
  significant digits, which read back exactly);
- table, tableFile, csvFile (linear between rows, clamped outside),
  polynomials: 1e-13 relative (round-off of the two evaluations);
- the header: class volScalarField, the field's dimensions, the note
  'soilProfile: from <dict>'; zeroGradient on the patches, empty kept;
- 'parallel' (third argument): the fields reconstructed from a run of
  soilProfile -parallel on 2 ranks equal the serial ones to the bit.
"""
import math
import os
import re
import sys

import hearthcheck as hc

mode, case = sys.argv[1], sys.argv[2]
c = hc.Check('soilProfile (%s)' % mode)


def read(name, where=case):
    return hc.read_internal_field(os.path.join(where, '0', name))


def header(name, where=case):
    with open(os.path.join(where, '0', name)) as f:
        return f.read()


def interp(rows, x):
    """Linear interpolation, clamped outside the rows."""
    if x <= rows[0][0]:
        return rows[0][1]
    if x >= rows[-1][0]:
        return rows[-1][1]
    for (x0, y0), (x1, y1) in zip(rows, rows[1:]):
        if x0 <= x <= x1:
            return y0 + (x - x0)/(x1 - x0)*(y1 - y0)
    raise ValueError(x)


def poly(coeffs, x):
    return sum(a*x**e for a, e in coeffs)


def compare(name, expected, rel):
    got = read(name)
    c.true('%s: one value per cell' % name, len(got) == len(expected),
           '%d cells' % len(got))
    if rel == 0:
        bad = sum(g != e for g, e in zip(got, expected))
        c.true('%s: layer values exact at all %d cells' % (name, len(got)),
               bad == 0, '%d differ' % bad)
    else:
        err = max(abs(g - e)/abs(e) for g, e in zip(got, expected))
        c.le('%s: max relative difference from the profile' % name, err, rel)


def check_header(name, dims, dictName):
    txt = header(name)
    c.true('%s: header (class, dimensions, note)' % name,
           'class       volScalarField;' in txt
           and re.search(r'dimensions\s+\[%s\];' % dims, txt) is not None
           and 'note        "soilProfile: from %s";' % dictName in txt)
    patches = dict(re.findall(r'\n    (\w+)\n    \{\n        type\s+(\w+);',
                              txt))
    c.true('%s: patch types' % name,
           all(t == ('empty' if p == 'sides' else 'zeroGradient')
               for p, t in patches.items()) and len(patches) > 0,
           str(patches))


if mode == 'column':
    depth = [-z for z in read('Cz')]
    layers = [(0.0, 0.1, 0.45), (0.1, 0.234, 0.3), (0.234, 0.41, 0.38),
              (0.41, 1e300, 0.25)]
    porosity = [next(v for a, b, v in layers if a <= d < b) for d in depth]
    compare('porosity', porosity, 0)
    counts = [sum(a <= d < b for d in depth) for a, b, v in layers]
    c.true('every layer holds cells (interfaces on a face and in cells)',
           min(counts) > 0, str(counts))
    water = [interp([(0, 0.05), (0.07, 0.12), (0.2, 0.2), (0.3, 0.22)], d)
             for d in depth]
    compare('waterContent', water, 1e-13)
    c.true('waterContent clamped below the table (cells below 0.3 m)',
           sum(d > 0.3 for d in depth) > 0)
    rhoCp = [poly([(1.9e6, 0), (-2.0e6, 1), (4.0e6, 2)], d) if d < 0.3
             else 2.1e6 for d in depth]
    compare('rhoCpSolid', rhoCp, 1e-13)
    kappa = [interp([(0, 0.6), (0.05, 0.75), (0.18, 1.3), (0.5, 1.45)], d)
             for d in depth]
    compare('kappaSolid', kappa, 1e-13)
    for name, dims in (('porosity', '0 0 0 0 0 0 0'),
                       ('waterContent', '0 0 0 0 0 0 0'),
                       ('rhoCpSolid', '1 -1 -2 -1 0 0 0'),
                       ('kappaSolid', '1 1 -3 -1 0 0 0')):
        check_header(name, dims, 'system/soilProfileDict')
    if len(sys.argv) > 3:
        other = sys.argv[3]
        for name in ('porosity', 'waterContent', 'rhoCpSolid', 'kappaSolid'):
            a, b = read(name), read(name, other)
            c.true('%s: 2 ranks (reconstructed) = serial, to the bit' % name,
                   a == b, '%d cells' % len(a))

elif mode == 'tilted':
    o = (0.1, -0.2, 0.05)
    n = (1.0, 1.0, -2.0)
    norm = math.sqrt(sum(v*v for v in n))
    C = list(zip(read('Cx'), read('Cy'), read('Cz')))
    depth = [sum((p - q)*v for p, q, v in zip(cc, o, n))/norm for cc in C]
    rhoCp = [interp([(-0.5, 1.0e6), (0.1, 1.6e6), (0.35, 2.4e6),
                     (1.0, 2.5e6)], d) for d in depth]
    compare('rhoCpSolid', rhoCp, 1e-13)
    kappa = [0.8 if d < 0.25 else 0.8 + 1.0*d for d in depth]
    compare('kappaSolid', kappa, 1e-13)
    c.true('both layers hold cells', 0 < sum(d < 0.25 for d in depth)
           < len(depth))
    check_header('rhoCpSolid', '1 -1 -2 -1 0 0 0',
                 'system/soilProfileDict.tilted')
else:
    sys.exit('unknown mode ' + mode)

c.done()
