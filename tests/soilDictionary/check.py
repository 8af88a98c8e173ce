"""tests/soilDictionary: constant/soilProperties and its deprecated alias
give the same run. Each solver ran the same case from each file; every
volScalarField of every written time must agree to round-off: the same
numbers read through either route enter the same arithmetic, so the runs
should be identical (measured: 0); 1e-12 relative would let through only
a different order of operations, while a soil value read differently
(e.g. a default instead of the file's value, 1 % off) moves the fields by
1e-4 or more. The alias run logs the deprecation line once, the other
never."""
import os
import sys
from hearthcheck import Check, read_internal_field

scratch = sys.argv[1]
check = Check('soilDictionary')


def times(case):
    out = []
    for d in os.listdir(case):
        try:
            float(d)
        except ValueError:
            continue
        if float(d) > 0:
            out.append(d)
    return sorted(out, key=float)


for solver in ('ahcFoam', 'pendularFoam'):
    soil = os.path.join(scratch, solver + '.soil')
    old = os.path.join(scratch, solver + '.alias')
    ts = times(soil)
    check.true('%s: the same written times (%d)' % (solver, len(ts)),
               ts == times(old) and len(ts) > 0, ' '.join(ts))
    worst, where, n = 0.0, '', 0
    for t in ts:
        for f in sorted(os.listdir(os.path.join(soil, t))):
            p = os.path.join(soil, t, f)
            if not os.path.isfile(p):
                continue
            with open(p) as fh:
                if 'volScalarField' not in fh.read(2000):
                    continue
            a = read_internal_field(p)
            b = read_internal_field(os.path.join(old, t, f))
            n += 1
            if len(a) != len(b):
                worst, where = float('inf'), '%s/%s sizes' % (t, f)
                continue
            for x, y in zip(a, b):
                d = abs(x - y)/max(abs(x), abs(y), 1e-300)
                if d > worst:
                    worst, where = d, '%s/%s' % (t, f)
    check.le('%s: %d fields, largest relative difference (%s)'
             % (solver, n, where or '-'), worst, 1e-12)
    check.true('%s: at least 3 fields compared' % solver, n >= 3, str(n))
    note = 'Deprecated: the soil is read from constant/'
    with open(os.path.join(old, 'log.' + solver)) as fh:
        nOld = fh.read().count(note)
    with open(os.path.join(soil, 'log.' + solver)) as fh:
        nNew = fh.read().count(note)
    check.true('%s: deprecation line: alias run %d, soilProperties run %d'
               % (solver, nOld, nNew), nOld == 1 and nNew == 0)

check.done()
