"""tests/hearthCaseScannedPit: the sensors and alteration lines of a case
written by hearthCase on the scanned bowl (syntheticScan bowl -r R -d D)
against the analytic sphere of the bowl, in the ground frame:
    z_s(x, y) = (rho - D) - sqrt(rho^2 - x^2 - y^2),  rho = (R^2 + D^2)/(2 D).
The scan is a polar grid of the sphere (12 rings of equal polar-angle steps
theta_max/12, 48 sectors): between its vertices the triangles lie under
the sphere by at most the sag of a chord, rho (1 - cos(a/2)) with a the
largest angle a triangle edge subtends (the ring step or the sector step
at the rim, 2 pi/48 sin(theta_max)): the tolerance (a sensor measured
from z = 0, or from the tilted scan, would be off by cm)."""
import math
import os
import re
import sys

case, R, D = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
rho = (R*R + D*D)/(2*D)
thetaMax = math.asin(R/rho)
a = max(thetaMax/12, 2*math.pi/48*math.sin(thetaMax))
tol = rho*(1 - math.cos(a/2)) + 1e-9
ok = True


def check(cond, what):
    global ok
    print(('ok   ' if cond else 'FAIL ') + what)
    ok = ok and cond


def zs(x, y):
    return (rho - D) - math.sqrt(rho*rho - x*x - y*y)


want = {'centre': (0.0, 0.0, 0.01), 'rim': (R, 0.0, 0.01),
        'mid': (0.10, 0.05, 0.02), 'steep': (0.17, 0.003, 0.005)}
got = {}
with open(os.path.join(case, 'system', 'thermocouples.csv')) as f:
    for line in f:
        if line.startswith('#'):
            continue
        n, x, y, z = [w.strip() for w in line.split(',')]
        got[n] = (float(x), float(y), float(z))
check(sorted(got) == sorted(want), 'sensors %s' % sorted(got))
worst = 0
for n, (x, y, depth) in want.items():
    if n not in got:
        continue
    gx, gy, gz = got[n]
    # the quarter: points on the symmetry planes moved 0.1 mm inside
    check(abs(gx - max(x, 1e-4)) < 1e-9 if n != 'rim' else
          abs(gx - R) < tol, '%s x %.6g' % (n, gx))
    ze = zs(min(math.hypot(gx, gy), R), 0) - depth
    err = gz - ze
    worst = max(worst, abs(err))
    check(abs(err) <= tol,
          '%s z %.6f m, the sphere %.6f m: %.2g m (tolerance %.2g m)'
          % (n, gz, ze, err, tol))
text = open(os.path.join(case, 'system', 'hearthAlterationDict')).read()
below = float(re.search(r'start ([0-9.e-]+) m under', text).group(1))
for n, r in (('centre', 1e-4), ('rim', 0.9*R)):
    m = re.search(r'%s\s*\{ start \(([^)]*)\)' % n, text)
    x, y, z = (float(v) for v in m.group(1).split())
    ze = zs(math.hypot(x, y), 0) - below
    check(abs(z - ze) <= tol, 'line %s starts at z %.6f, sphere - %g: %.6f'
          % (n, z, below, ze))
print('sensors and lines within %.2g m of the sphere (tolerance %.2g m)'
      % (worst, tol))
sys.exit(0 if ok else 1)
