"""ahcFoam (porosity 0, no water) against laplacianFoam, cell by cell, at
every write (600, 1200, 1800, 2400 s): max |T_ahc - T_lap| / (max T_lap -
min T_lap) <= 1e-9.

Tolerance. Both solvers solve, every step, linear systems that are the same
up to a scaling by rho C (the normalised residual does not see it) and up
to round-off in the coefficients (k interpolated to the faces, C T^k -
(H^k - H^n) = C T^n in floating point: ~1e-16 of T). PCG stops at a
normalised residual of 1e-14; the error that leaves in T is at most about
1e-14 times the condition of the diagonally scaled matrix, 1 + 4 alpha dt /
h^2 ~ 40 on these meshes (h = 0.9 mm at the surface), i.e. <= 4e-13 of the
field's range per step; backward Euler does not amplify it, so 120 steps
accumulate at most 5e-11. On the plane mesh the non-orthogonal correction
is converged in both solvers (laplacianFoam: 20 correctors; ahcFoam:
residualTol 1e-13, TTol 1e-12 K), leaving < 1e-14. 1e-9 is 20 times that
worst case; the differences measured are 1e-14 to 3e-12.

Sensitivity: laplacianFoam with DT 1e-4 (relative) larger differs by ~1e-5
of the range: the test would see a relative error of 1e-8 in k or rho C."""
import os
import re
import hearthcheck as hc

TOL = 1e-9
TIMES = ['600', '1200', '1800', '2400']

c = hc.Check('laplacianFoamEquality')


def field(case, t):
    return hc.read_internal_field(os.path.join(case, t, 'T'))


def worst(case, ref):
    """max over the writes of max |T - T_ref| / range(T_ref)."""
    out = 0.0
    for t in TIMES:
        T, Tr = field(case, t), field(ref, t)
        assert len(T) == len(Tr) > 1, '%s, %s at %s: %d, %d cells' % (
            case, ref, t, len(T), len(Tr))
        out = max(out, max(abs(a - b) for a, b in zip(T, Tr))
                  / (max(Tr) - min(Tr)))
    return out


def above(what, value):
    """A difference the test must see: at least 100 tolerances."""
    c.true(what, value >= 100*TOL, '%.4g >= 100 tol = %.4g' % (value, 100*TOL))


for case in ['plane-ahc', 'plane-lap', 'plane-lapDT', 'plane-lapNoCorr',
             'wedge-ahc', 'wedge-ahc-arithmetic', 'wedge-ahc-geometric',
             'wedge-lap', 'wedge-lapDT']:
    c.true('%s wrote %s s' % (case, ', '.join(TIMES)),
           all(os.path.isfile(os.path.join(case, t, 'T')) for t in TIMES))

# Plane, non-orthogonal: against the converged non-orthogonal correction
e = worst('plane-ahc', 'plane-lap')
ok = c.le('plane: max |ahcFoam - laplacianFoam| / range', e, TOL)
eNoCorr = worst('plane-ahc', 'plane-lapNoCorr')
with open(os.path.join('plane-ahc', 'log.ahcFoam')) as f:
    iters = [int(n) for n in re.findall(r'ahcFoam: deltaT = \S+, iterations'
                                        r' = (\d+)', f.read())]
print('       (against laplacianFoam without non-orthogonal correctors:'
      ' %.3g; ahcFoam iterations per step %d to %d)'
      % (eNoCorr, min(iters), max(iters)))
if not ok and max(iters) <= 2:
    print('       ahcFoam accepted its steps after one or two linear solves:'
          ' the explicit\n'
          '       non-orthogonal correction of the laplacian, evaluated at'
          ' the first iterate (T^n,\n'
          '       or T extrapolated in time), was not iterated to'
          ' convergence, although\n'
          '       residualTol 1e-13 and TTol 1e-12 K ask for it (with T^n as'
          ' the first iterate and one\n'
          '       solve the result is laplacianFoam\'s without correctors)')
above('plane: laplacianFoam with/without non-orth. correctors differ',
      worst('plane-lap', 'plane-lapNoCorr'))
above('plane: sensitivity, laplacianFoam DT*(1 + 1e-4) differs',
      worst('plane-lapDT', 'plane-lap'))

# Wedge, orthogonal: every conductivity law that reduces to k_s
for law in ['', '-arithmetic', '-geometric']:
    c.le('wedge%s: max |ahcFoam - laplacianFoam| / range'
         % (law.replace('-', ' ') or ' harmonic'),
         worst('wedge-ahc' + law, 'wedge-lap'), TOL)
above('wedge: sensitivity, laplacianFoam DT*(1 + 1e-4) differs',
      worst('wedge-lapDT', 'wedge-lap'))

c.done()
