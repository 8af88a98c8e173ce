"""Temperature on the axis of a disc fire (radius a = 0.15 m, Tw = 700 C)
in dry clay at T0 = 20 C, the plane around the fire held at T0: the
half-space solution with Dirichlet data on z = 0 (integrating the double-
layer heat kernel (z/s) (4 pi alpha s)^(-3/2) exp(-R^2/(4 alpha s)) over
the disc and the time) is exact on the axis,

  T = T0 + (Tw - T0) [erfc(z/(2 sqrt(alpha t)))
                      - z/sqrt(z^2 + a^2) erfc(sqrt(z^2 + a^2)/(2 sqrt(alpha t)))]

(the 1-D erfc solution minus the heat the disc's finite size withholds;
its limit t -> infinity is the solid-angle result 1 - z/sqrt(z^2 + a^2)).
Checked at 2, 5 and 10 cm over 0.5-3 h on the flatDisc3D template at
refinement 0.5 (hexahedra) and on its polyhedral dual, with backward Euler
steps of at most 2 K and 20 s. Tolerances are set at about twice the
measured errors (1.13 K hex, 1.04 K polyhedra, at 5 cm): they come from the surface
cells of 4 mm and the first-order steps, as in dryConductionErfc."""
import math
import os
import hearthcheck as hc

c = hc.Check('discFireAxis')
alpha = 0.756/(1500*1300)
T0, Tw, a = 293.15, 973.15, 0.15


def exact(z, t):
    s = 2*math.sqrt(alpha*t)
    R = math.hypot(z, a)
    return T0 + (Tw - T0)*(math.erfc(z/s) - z/R*math.erfc(R/s))


tol = {'hex': 2.0, 'poly': 2.0}
for mesh in ('hex', 'poly'):
    locs, times, cols = hc.read_probes(os.path.join(mesh, 'postProcessing/axis/0/T'))
    for (x, y, z), col in zip(locs, cols):
        err = max(abs(T - exact(-z, t)) for t, T in zip(times, col) if t >= 1800)
        dev1D = max(abs(exact(-z, t) - hc.erfc_solution(-z, t, T0, Tw, alpha))
                    for t in times if t >= 1800)
        c.le('%s: max |T - exact| on the axis at %g cm, 0.5-3 h [K] '
             '(1-D erfc is %.1f K off)' % (mesh, -100*z, dev1D), err, tol[mesh])
    c.true('%s: 3 h simulated' % mesh, abs(times[-1] - 10800) < 1e-6, '%g s' % times[-1])
    bal = hc.read_energy_balances(os.path.join(mesh, 'log.ahcFoam'))
    c.le('%s: energy imbalance / stored energy, worst write' % mesh,
         max(abs(b[2]) for b in bal), 1e-8)
c.done()
