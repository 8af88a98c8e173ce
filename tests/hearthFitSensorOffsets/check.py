"""Checks of hearthFitSensorOffsets (run): the recovered sensor offsets,
the user's sensors file untouched, the -writeCase copy, the bad input."""
import csv
import os
import sys

fails = 0


def check(ok, what):
    global fails
    print('%s: %s' % ('PASS' if ok else 'FAIL', what))
    if not ok:
        fails += 1


# Truth: s2 +2 mm, s3 -1.5 mm, k_s 0.756. The sensors sample the cellPoint
# interpolant of the field, piecewise linear in z between cell centres and
# faces (every 0.25 mm here). Same mesh for data and model (fit): the truth
# is an exact zero-residual point, the accuracy is the solver noise over the
# gradient (~1e-12 m). Data from another mesh (fitFine, 4x finer): the
# interpolant differs from the smooth profile by ~h^2/8 T''; as a position,
# dz ~ h^2/8 |T''/T'|, with |T''/T'| ~ 2z/(4 alpha t) for the erfc-like
# profile (alpha ~ 4.7e-7 m2/s): ~350 /m at 1 min, ~6 /m at 1 h at 2 cm,
# i.e. dz <~ 0.01 mm with h = 0.5 mm (0.2 mm with the 2 mm cells of
# hearthFitSynthetic, too coarse for 0.05 mm). Tolerance 0.05 mm for both
# fits; k_s 0.5 %.
truth = {'dz_s2': 0.002, 'dz_s3': -0.0015, 'ks': 0.756}
tol = {'dz_s2': 5e-5, 'dz_s3': 5e-5, 'ks': 0.005*0.756}


def estimates(case):
    est = {}
    with open(case + '/postProcessing/hearthFit/parameters.csv') as f:
        for row in csv.DictReader(f):
            est[row['name']] = float(row['estimate'])
    return est


for case in ('fit', 'fitFine'):
    est = estimates(case)
    for name, t in truth.items():
        v = est.get(name)
        check(v is not None and abs(v - t) <= tol[name],
              '%s %s = %s, truth %g, |error| %s <= %g'
              % (case, name, v, t, None if v is None else abs(v - t),
                 tol[name]))
    check('(converged)' in open(case + '/log.hearthFit').read(),
          '%s: hearthFit converged' % case)
est = estimates('fit')

check(os.path.isfile('fit/unchanged'),
      "user's system/thermocouples.csv unchanged by hearthFit")

# The -writeCase copy: the sensors moved by the estimates
pos = {}
with open('best/system/thermocouples.csv') as f:
    for line in f:
        c = [x.strip() for x in line.split('#')[0].split(',')]
        if len(c) == 4 and c[0] != 'name':
            pos[c[0]] = float(c[3])
for name, nominal, key in (('s1', -0.0101, None), ('s2', -0.0201, 'dz_s2'),
                           ('s3', -0.0301, 'dz_s3')):
    want = nominal + (est.get(key, 0.0) if key else 0.0)
    check(name in pos and abs(pos[name] - want) <= 1e-12,
          '-writeCase %s z = %s, expected %.12g' % (name, pos.get(name), want))

for line in open('badInput.txt'):
    check(': ok (' in line, line.strip())

print('%d check(s) failed' % fails if fails else 'all checks passed')
sys.exit(1 if fails else 0)
