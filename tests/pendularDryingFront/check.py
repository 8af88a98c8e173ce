"""pendularDryingFront: the report's column with liquid flow through the
drying front (tests/pendularDryingFront/run says what is run)."""
import math
import os
import sys
import hearthcheck as hc
from hearthTutorial import interpolate  # (hearthcheck's path)

H, alpha0 = 0.1, 0.005
# The front: alpha_l = 1e-5, between the wet side (liquid drawn to the
# front: alpha_l 1e-4 to alpha_0) and the dry side (the Kelvin range,
# 1e-7 and less); alpha_0/2 is no front with liquid flow, which lowers
# alpha_l below it down the whole column
ALPHA_F = 1e-4
TIMES = (1800, 3600)
DEPTHS = (0.01, 0.02, 0.05)


def depths(n):
    """Cell-centre depths, bottom cell first (as blockMesh numbers them)."""
    return [H - (i + 0.5)*H/n for i in range(n)]


def front(zs, alphas):
    """Depth of the drying front: where alpha_l first reaches ALPHA_F
    going down (log-linear between the cells), or None."""
    pts = sorted(zip(zs, alphas))
    for (a, va), (b, vb) in zip(pts, pts[1:]):
        if va < ALPHA_F <= vb:
            la, lb = math.log(max(va, 1e-300)), math.log(vb)
            return a + (b - a)*(math.log(ALPHA_F) - la)/(lb - la)
    return None


def figures(case):
    """{t: (front [m], T at 1, 2, 5 cm [K])} of a run."""
    out = {}
    for t in TIMES:
        T = hc.read_internal_field(os.path.join(case, str(t), 'T'))
        a = hc.read_internal_field(os.path.join(case, str(t), 'alphaL'))
        z = depths(len(T))
        out[t] = [front(z, a)] + [interpolate(z[::-1], T[::-1], d)
                                  for d in DEPTHS]
    return out


NAMES = ['front [mm]', 'T(1 cm) [K]', 'T(2 cm) [K]', 'T(5 cm) [K]']
SCALE = [1e3, 1, 1, 1]


def show(label, f):
    for t in TIMES:
        print('%-22s t = %4d s: %s' % (label, t, ', '.join(
            '%s %.4f' % (n, v*s) for n, v, s in zip(NAMES, f[t], SCALE))))


def changes(fig, k, t):
    """|q100 - q50|, |q200 - q100| and the observed order of quantity k."""
    q = [fig['liquid_%d' % n][t][k] for n in (50, 100, 200)]
    d1, d2 = abs(q[1] - q[0]), abs(q[2] - q[1])
    order = math.log(d1/d2)/math.log(2) if d1 > 0 and d2 > 0 else float('nan')
    return d1, d2, order


# The README's figures (pendularFoam, liquid flow: through a drying front),
# 100 cells: (run, or 'change' for liquid flow minus none; t; quantity
# index; value; tolerance: half the last printed digit)
README = [
    ('noLiquid_100', 1800, 0, 35.1e-3, 0.05e-3),
    ('liquid_100', 1800, 0, 31.4e-3, 0.05e-3),
    ('noLiquid_100', 3600, 0, 64.1e-3, 0.05e-3),
    ('liquid_100', 3600, 0, 72.2e-3, 0.05e-3),
    ('change', 1800, 2, -0.35, 0.005),
    ('change', 3600, 3, 0.15, 0.005),
]


if __name__ == '__main__':
    scratch = sys.argv[1]
    runs = ['liquid_50', 'liquid_100', 'liquid_200', 'noLiquid_100',
            'linear1e-7_100', 'notRegularised_100', 'vanGenuchten_100']
    fig = {r: figures(os.path.join(scratch, r)) for r in runs}
    for r in runs:
        show(r, fig[r])
    c = hc.Check('pendularDryingFront')

    # 1. balances: round-off of the stored amounts (1e-10 asked, issue 14);
    # measured 3e-11 at most
    for r in runs:
        c.le('%s: largest relative imbalance (water, air, energy)' % r,
             hc.worst_relative_imbalance(
                 os.path.join(scratch, r, 'log.pendularFoam')), 1e-10)

    # 2. refinement 50 -> 100 -> 200 cells (fixed 20 s steps): every
    # quantity's change falls; at 1 h the front and T(5 cm) converge at
    # first order (k_rl upwind; measured 0.85 and 0.98: 0.7 asked); the
    # others' orders printed (0.72 to 1.21)
    for t in TIMES:
        for k, name in enumerate(NAMES):
            d1, d2, order = changes(fig, k, t)
            c.true('%s at %d s: change 100 -> 200 cells below 50 -> 100'
                   % (name, t), d2 < d1,
                   '%.4g < %.4g (order %.2f)' % (d2*SCALE[k], d1*SCALE[k],
                                                  order))
    for k in (0, 3):
        order = changes(fig, k, 3600)[2]
        c.true('%s at 3600 s: observed order >= 0.7' % NAMES[k],
               order >= 0.7, '%.3f' % order)

    # 3. what liquid flow changes (100 cells, against the same run without
    # it): printed for every quantity; checked where it exceeds 3 times the
    # 100-cell discretisation error (estimated by the 100 -> 200 change)
    for t in TIMES:
        for k, name in enumerate(NAMES):
            dl = fig['liquid_100'][t][k] - fig['noLiquid_100'][t][k]
            d2 = changes(fig, k, t)[1]
            print('liquid flow changes %s at %d s by %+.4g (100 -> 200 '
                  'cells: %.3g)' % (name, t, dl*SCALE[k], d2*SCALE[k]))
            if (k, t) in ((0, 1800), (0, 3600), (2, 1800), (3, 3600)):
                c.true('%s at %d s: |liquid flow - none| > 3 x the mesh '
                       'change' % (name, t), abs(dl) > 3*d2,
                       '%.4g > 3 x %.4g' % (abs(dl)*SCALE[k], d2*SCALE[k]))

    # 4. what the regularisation changes: the case's S_r = 1e-6 and 1e-7
    # against the unregularised pendular law (100 cells; on this column it
    # runs through the front: k_rl = S^2 vanishes faster than p_c ~
    # S^(-1/2) grows): the front within 0.25 mm (measured 0.08 and 0.13 mm
    # at 1e-6, 0.006 and 0.009 mm at 1e-7), T within 0.01 K (measured
    # 3.5e-3 K at most), and S_r 1e-7 closer than 1e-6 for the front (the
    # regularised solutions converge to the law's). Larger S_r change
    # more: at 1 h the front is 68.2, 69.3, 70.5, 71.4, 71.7 mm for S_r =
    # 1e-3, 5e-4, 1e-4, 2e-5, 1e-5 against 72.4 mm (measured 2026-12-02,
    # not checked here)
    ref = fig['notRegularised_100']
    for t in TIMES:
        for k, name in enumerate(NAMES):
            d6 = abs(fig['liquid_100'][t][k] - ref[t][k])
            d7 = abs(fig['linear1e-7_100'][t][k] - ref[t][k])
            for sr, d in (('1e-6', d6), ('1e-7', d7)):
                c.le('S_r %s - not regularised: |%s| at %d s' % (sr, name, t),
                     d*SCALE[k], 0.25 if k == 0 else 0.01)
            if k == 0:
                c.true('front at %d s: S_r 1e-7 closer than 1e-6' % t,
                       d7 < d6, '%.3g < %.3g mm' % (d7*1e3, d6*1e3))

    # 5. van Genuchten's law (Swr 1e-3, regularised below S_e = 0.01)
    # through the same front: its balances above (1); its front printed
    # (the run's script checks that without the regularisation it stops)

    # 6. the README's figures
    for r, t, k, value, tol in README:
        got = (fig['liquid_100'][t][k] - fig['noLiquid_100'][t][k]
               if r == 'change' else fig[r][t][k])
        c.le('README: %s %s at %d s = %g' % (r, NAMES[k], t, value*SCALE[k]),
             abs(got - value)*SCALE[k], tol*SCALE[k])
    c.done()
