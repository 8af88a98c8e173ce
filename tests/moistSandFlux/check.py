"""moistSandFlux: condensation ahead of the drying front under a surface
heat flux (tests/moistSandFlux/run says what is run)."""
import os
import re
import sys
import hearthcheck as hc

H, PHI, RHO_L = 0.25, 0.38, 1000.0
ALPHA0 = 0.2631579          # 0/alphaL: 0.1 m3/m3 of water
AREA = 0.01*0.01            # the column's cross-section [m2]
TIMES = (300, 600, 900, 1200, 1500, 1800)
T100 = 373.15


def depths(n):
    """Cell-centre depths, bottom cell first (as blockMesh numbers them)."""
    return [H - (i + 0.5)*H/n for i in range(n)]


def crossing(zs, vs, level, rising):
    """First depth going down where v crosses level (upwards if rising,
    linear between the cells), or None."""
    for (a, va), (b, vb) in zip(zip(zs, vs), zip(zs[1:], vs[1:])):
        if (va < level <= vb) if rising else (va > level >= vb):
            return a + (b - a)*(level - va)/(vb - va)
    return None


def figures(case, t):
    """The bump at time t: dict of the drying front z_d (alpha_l =
    alpha_0/2 going down), the 100 C isotherm z_100, the peak alpha_l and
    its depth z_p (parabola through the largest cell and its neighbours),
    and the water above the initial content deeper than z_d [kg/m2]."""
    T = hc.read_internal_field(os.path.join(case, str(t), 'T'))[::-1]
    a = hc.read_internal_field(os.path.join(case, str(t), 'alphaL'))[::-1]
    n = len(T)
    z = depths(n)[::-1]                 # top cell first
    dz = H/n
    zd = crossing(z, a, ALPHA0/2, True)
    z100 = crossing(z, T, T100, False)
    k = max(range(n), key=lambda i: a[i])
    zp, ap = z[k], a[k]
    if 0 < k < n - 1:
        den = a[k - 1] - 2*a[k] + a[k + 1]
        if den < 0:
            s = 0.5*(a[k - 1] - a[k + 1])/den
            zp = z[k] + s*dz
            ap = a[k] - 0.25*(a[k - 1] - a[k + 1])*s
    # cells wholly ahead of the front, and the ahead part of the cut cell
    excess = 0.0
    for zi, ai in zip(z, a):
        lo, hi = zi - dz/2, zi + dz/2
        w = max(0.0, min(1.0, (hi - zd)/dz)) if zd is not None else 1.0
        excess += w*max(0.0, ai - ALPHA0)*PHI*RHO_L*dz
    return dict(zd=zd, z100=z100, peak=ap, zp=zp, excess=excess)


def top_energy_in(log):
    """The energy in through 'top' [J] at each write of a pendularFoam log."""
    out, section = [], None
    with open(log) as f:
        for line in f:
            if line.startswith('Energy balance'):
                section = 'E'
            elif line.startswith(('Water balance', 'Air balance')):
                section = None
            m = re.search(r'out through top = (\S+)', line)
            if m and section == 'E':
                out.append(-float(m.group(1)))
    return out


def show(label, f):
    for t in sorted(f):
        g = f[t]
        print('%-14s t = %4d s: front %s mm, 100 C at %s mm, peak alpha_l '
              '%.4f at %.2f mm, water above alpha_0 ahead %.4f kg/m2'
              % (label, t, '%.2f' % (g['zd']*1e3) if g['zd'] else 'none',
                 '%.2f' % (g['z100']*1e3) if g['z100'] else 'none',
                 g['peak'], g['zp']*1e3, g['excess']))


if __name__ == '__main__':
    scratch = sys.argv[1]
    runs = ['q25_50', 'q25_100', 'q25_200', 'q10_100', 'q50_100',
            'noLiquid_100', 'noVapour_100']
    fig = {r: {t: figures(os.path.join(scratch, r), t) for t in TIMES
               if os.path.isdir(os.path.join(scratch, r, str(t)))}
           for r in runs}
    for r in runs:
        show(r, fig[r])
    c = hc.Check('moistSandFlux')

    # 1. balances at every write (issue 14: 1e-10)
    for r in runs:
        c.le('%s: largest relative imbalance (water, air, energy)' % r,
             hc.worst_relative_imbalance(
                 os.path.join(scratch, r, 'log.pendularFoam')), 1e-10)
    c.done()
