"""Flux jumps of Mansour (2015) Tab. 2.1 (tests/grainBridgeMeshStudy checks
the row eps/R0 0.1, theta 30 deg): Mansour's flux q = k_e/(1 + eps)
(R0 = 1, dT = 1; the mean flux density over the top), its jump when
filling (the drops touch, alpha_touch, and a bridge of that volume forms)
and when drying (the smallest stable bridge breaks into two drops of its
volume), on the wedge cell with n = 100 and 200 cells along R0.

The geometry of each row is given (to keep the test short): the neck of
the smallest stable bridge r0Min (tests/grainBridge and
tests/grainBridgeTable21 find it, 5 digits; V(r0) is flat there), the neck
rTouch of the bridge holding alpha_touch and the apex z0 of the drops
holding the smallest bridge's volume (bisections, written to 10 digits);
checked: the volumes they give agree, to 1e-8 relative for the bridge
(measured 6e-11) and 1e-6 for the drops (measured up to 1.4e-7: the
10-digit apex of a drop whose volume falls steeply with z0), far below
what moves a cell centre across the meniscus.

Tolerance: the filling jump is not mesh-converged (the drops touch the
mid-plane at a point; it still moves by up to 0.006 from n = 100 to 200
to 400, the order irregular, so no Richardson extrapolation): the filling
jump at n = 200 is compared with Tab. 2.1 within the difference n = 100
to 200 plus 2 % of the table (as tests/grainBridgeMeshStudy); measured once
at n = 400 (not run here, not in the README): 0.1713, 0.0451, 0.0232, 0.2885, 0.0500
for the five rows below, all above the table's values (+1 to +10 %).
"""
import importlib.machinery
import math
import os
import sys

import hearthcheck as hc

top = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..')
sys.path.insert(0, os.path.join(top, 'etc', 'python'))
import grainBridge as gb  # noqa: E402

gs = importlib.machinery.SourceFileLoader(
    'grainScale', os.path.join(top, 'bin', 'grainScale')).load_module()

c = hc.Check('grainBridgeFluxJumps')

# (eps, theta): (r0Min, rTouch, zMin), Tab. 2.1 flux jump
ROWS = {
    (0.05, 10): ((0.026135, 0.2970321975, 0.03722684495), 0.165),
    (0.05, 30): ((0.019782, 0.1168859284, 0.02722484961), 0.041026),
    (0.05, 45): ((0.016703, 0.07806365327, 0.02353527226), 0.021695),
    (0.1, 10): ((0.051466, 0.4956646673, 0.07448460322), 0.285),
    (0.1, 45): ((0.033207, 0.1519602373, 0.04740043641), 0.048),
}

figures = []
for (eps, t), ((r0Min, rTouch, zMin), tab) in ROWS.items():
    theta = math.radians(t)
    W = gb.void_volume(eps)
    tag = 'eps%g_theta%d' % (eps, t)
    aTouch = gb.drop_cap(0.0, theta, eps)[1]/W
    bTouch, dTouch = gb.bridge(rTouch, theta, eps), gb.drop(0.0, theta, eps)
    bMin, dMin = gb.bridge(r0Min, theta, eps), gb.drop(zMin, theta, eps)
    c.le('%s: bridge at rTouch holds alpha_touch (rel)' % tag,
         abs(bTouch.volume/W - aTouch)/aTouch, 1e-8)
    c.le('%s: drops at zMin hold the smallest bridge (rel)' % tag,
         abs(dMin.volume - bMin.volume)/bMin.volume, 1e-6)
    jump = {}
    for n in (100, 200):
        cell = gs.Cell(gs.parse(['-n', str(n), '-eps', str(eps),
                                 '-case', 'cell_%s_%d' % (tag, n)]))
        jump[('touch', n)] = (cell.k_e(bTouch) - cell.k_e(dTouch))/(1 + eps)
        jump[('min', n)] = (cell.k_e(bMin) - cell.k_e(dMin))/(1 + eps)
    dn = abs(jump[('touch', 200)] - jump[('touch', 100)])
    print('     %s: filling jump %.5g (n 100) %.5g (n 200), drying %.5g'
          ' %.5g; Tab. 2.1 %g' % (tag, jump[('touch', 100)],
                                  jump[('touch', 200)], jump[('min', 100)],
                                  jump[('min', 200)], tab))
    c.le('%s: filling jump n = 200 vs Tab. 2.1 %g (abs; mesh diff + 2 %%)'
         % (tag, tab), abs(jump[('touch', 200)] - tab), dn + 0.02*tab)
    c.true('%s: jump larger filling than drying (Fig. 2.11)' % tag,
           jump[('touch', 200)] > jump[('min', 200)] > 0)
    figures += [('jumpTouch_%s_n200' % tag, jump[('touch', 200)]),
                ('jumpTouch_%s_meshdiff' % tag, dn),
                ('jumpMin_%s_n200' % tag, jump[('min', 200)])]

with open('figures.csv', 'w') as f:
    f.write('name,value,unit\n')
    for name, v in figures:
        f.write('%s,%.10g,-\n' % (name, v))
        print('     %-32s %.6g' % (name, v))
c.done()
