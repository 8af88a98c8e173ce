"""pendularFoam (100 cells of 1 mm, backward Euler, adaptive steps) against
the reference (200 nodes, BDF2, within 4e-4 K of its converged solution) on
the report's column at 1, 3, 6, 9 and 12 h:
- temperature at 1, 2 and 5 cm within 0.5 K (the required tolerance: the
  first-order time error of backward Euler with steps of up to 2 K);
- drying-front depth (alpha_l = alpha_0/2) within two cells (2 mm), while a
  front exists (1 h; the column is dry from 1.9 h on);
- total water within 0.5 % while the soil holds water (1 h); once both
  columns are dry (1e-12 kg/m2 left in the Kelvin range), within 10 % of
  the reference: measured 0.2-1.8 % at 3-12 h (first-order steps against
  BDF2, 1 mm cells against 0.5 mm nodes), while a Kelvin length twice too
  long leaves 4.6 times more;
- the water and energy balances of pendularFoam close to 1e-8.
A second argument sets the temperature tolerance: 0.01 K for the run with
variable-step BDF2 (`timeScheme BDF2; localErrorTol 1;`, pendularFoam's
default, which tutorials/column1D does not take), second order in time:
measured 2026-12-04 within 0.0017 K where backward Euler is 0.077 K off
(5 cm, 1 h), so 0.01 K fails a first-order run."""
import csv
import os
import sys
import hearthcheck as hc

ref = sys.argv[1]
tolT = float(sys.argv[2]) if len(sys.argv) > 2 else 0.5
c = hc.Check('pendularColumnReference')
N, H, phi, rhoL, alpha0 = 100, 0.1, 0.26, 1000.0, 0.005
depth = [H - (i + 0.5)*H/N for i in range(N)]      # cell centres, bottom first


def interp(z, zs, vs):
    pts = sorted(zip(zs, vs))
    for (a, va), (b, vb) in zip(pts, pts[1:]):
        if a <= z <= b:
            return va + (vb - va)*(z - a)/(b - a)
    raise ValueError(z)


def front(zs, alphas):
    """Depth where alpha first reaches alpha0/2 going down, or None."""
    pts = sorted(zip(zs, alphas))
    for (a, va), (b, vb) in zip(pts, pts[1:]):
        if va < alpha0/2 <= vb:
            return a + (b - a)*(alpha0/2 - va)/(vb - va)
    return None


history = list(csv.DictReader(open(os.path.join(ref, 'history.csv'))))
for t in (3600, 10800, 21600, 32400, 43200):
    rows = list(csv.DictReader(open(os.path.join(ref, 'profile_%d.csv' % t))))
    zr = [float(r['z']) for r in rows]
    Tr = [float(r['T']) for r in rows]
    ar = [float(r['alpha']) for r in rows]
    T = hc.read_internal_field('%d/T' % t)
    alpha = hc.read_internal_field('%d/alphaL' % t)
    W = hc.read_internal_field('%d/W' % t)
    for z in (0.01, 0.02, 0.05):
        c.le('|T - reference| at %g cm, %g h [K]' % (100*z, t/3600),
             abs(interp(z, depth, T) - interp(z, zr, Tr)), tolT)
    fr, ff = front(zr, ar), front(depth, alpha)
    waterRef = min(history, key=lambda r: abs(float(r['t']) - t))
    waterRef = float(waterRef['water'])
    water = sum(W)*H/N
    if fr is not None:
        c.true('a front in both at %g h' % (t/3600), ff is not None,
               'reference %.4f m, pendularFoam %s' % (fr, ff))
        if ff is not None:
            c.le('|front - reference| at %g h [m]' % (t/3600), abs(ff - fr), 2*H/N)
        c.le('|water - reference|/reference at %g h' % (t/3600),
             abs(water - waterRef)/waterRef, 5e-3)
    else:
        # Dried to the Kelvin range: a few 1e-12 kg/m2 are left, set by the
        # Kelvin-Laplace equilibrium at the temperature of the column, so
        # relative: an absolute bound would pass any value (a Kelvin length
        # twice too long leaves 4.6 times more)
        c.le('|water - reference|/reference, dry column at %g h (%.3g kg/m2)'
             % (t/3600, waterRef), abs(water - waterRef)/waterRef, 0.1)

bal = hc.read_energy_balances('log.pendularFoam')
c.le('worst relative imbalance (water, air, energy)',
     max(abs(b[2]) for b in bal), 1e-8)
c.done()
