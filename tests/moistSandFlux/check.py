"""moistSandFlux: condensation ahead of the drying front under a surface
heat flux (tests/moistSandFlux/run says what is run)."""
import os
import re
import sys
import hearthcheck as hc
from hearthTutorial import interpolate  # (hearthcheck's path)

H, PHI, RHO_L = 0.25, 0.38, 1000.0
ALPHA0 = 0.2631579          # 0/alphaL: 0.1 m3/m3 of water
AREA = 0.01*0.01            # the column's cross-section [m2]
TIMES = (300, 600, 900, 1200, 1500, 1800)
T100 = 373.15
DEPTHS = (0.01, 0.02, 0.05, 0.10)


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
    return dict(zd=zd, z100=z100, peak=ap, zp=zp, excess=excess,
                T=[interpolate(z, T, d) for d in DEPTHS])


def temperatures(case, t):
    """T at DEPTHS [K] at time t (ahcFoam's run)."""
    T = hc.read_internal_field(os.path.join(case, str(t), 'T'))
    z = depths(len(T))
    return [interpolate(z[::-1], T[::-1], d) for d in DEPTHS]


def top_energy_in(log):
    """{t: energy in through 'top' [J]} at each write of a pendularFoam
    ('out through top' of its energy balance) or ahcFoam ('heat in through
    top') log."""
    out, t = {}, None
    with open(log) as f:
        for line in f:
            m = re.match(r'Energy balance at t = (\S+) s', line)
            if m:
                t = float(m.group(1))
            elif line.startswith(('Water balance', 'Air balance')):
                t = None
            m = re.search(r'(out|heat in) through top = (\S+)', line)
            if m and t is not None:
                out[t] = float(m.group(2))*(-1 if m.group(1) == 'out' else 1)
    return out


def show(label, f):
    for t in sorted(f):
        g = f[t]
        print('%-14s t = %4d s: front %s mm, 100 C at %s mm, peak alpha_l '
              '%.4f at %.2f mm, water above alpha_0 ahead %.4f kg/m2'
              % (label, t, '%.2f' % (g['zd']*1e3) if g['zd'] else 'none',
                 '%.2f' % (g['z100']*1e3) if g['z100'] else 'none',
                 g['peak'], g['zp']*1e3, g['excess']))


def readme_figures(fig, ahc):
    """(name, README value, tolerance, computed) of the README's
    figures: 100 cells; tolerance half the last printed digit plus, for
    the bump's figures, the 100 -> 200 change (TOL in 3)."""
    out = []
    for r in README:
        name, run, t, key, value, tol = r
        if key.startswith('T'):
            i = int(key[1:])
            got = fig[run][t]['T'][i] - (ahc[t][i] if run == 'q25_100'
                                          else 0)
        elif key == 'ahead':
            got = (fig[run][t]['zp'] - fig[run][t]['z100'])*1e3
        else:
            got = fig[run][t][key]*(1e3 if key in ('zd', 'z100', 'zp')
                                    else 1)
        out.append((name, value, tol, got))
    return out


# name, run, time, key, README value, tolerance (half the printed digit)
README = [
    ('front 25 kW/m2 30 min [mm]', 'q25_100', 1800, 'zd', 51.55, 0.005),
    ('100 C 25 kW/m2 30 min [mm]', 'q25_100', 1800, 'z100', 51.25, 0.005),
    ('peak 25 kW/m2 30 min', 'q25_100', 1800, 'peak', 0.371, 0.0005),
    ('peak depth 25 kW/m2 30 min [mm]', 'q25_100', 1800, 'zp', 70.6, 0.05),
    ('peak ahead of 100 C 25 kW/m2 30 min [mm]', 'q25_100', 1800, 'ahead',
     19.4, 0.05),
    ('water 25 kW/m2 30 min [kg/m2]', 'q25_100', 1800, 'excess', 1.23,
     0.005),
    ('peak 25 kW/m2 15 min', 'q25_100', 900, 'peak', 0.362, 0.0005),
    ('peak depth 25 kW/m2 15 min [mm]', 'q25_100', 900, 'zp', 44.9, 0.05),
    ('water 25 kW/m2 15 min [kg/m2]', 'q25_100', 900, 'excess', 0.75, 0.005),
    ('front 10 kW/m2 30 min [mm]', 'q10_100', 1800, 'zd', 29.9, 0.05),
    ('peak 10 kW/m2 30 min', 'q10_100', 1800, 'peak', 0.337, 0.0005),
    ('water 10 kW/m2 30 min [kg/m2]', 'q10_100', 1800, 'excess', 0.78,
     0.005),
    ('front 50 kW/m2 30 min [mm]', 'q50_100', 1800, 'zd', 66.6, 0.05),
    ('peak 50 kW/m2 30 min', 'q50_100', 1800, 'peak', 0.377, 0.0005),
    ('water 50 kW/m2 30 min [kg/m2]', 'q50_100', 1800, 'excess', 1.24,
     0.005),
    ('no liquid flow: peak 30 min', 'noLiquid_100', 1800, 'peak', 0.483,
     0.0005),
    ('no liquid flow: peak ahead of 100 C 30 min [mm]', 'noLiquid_100', 1800,
     'ahead', 3.3, 0.05),
    ('no liquid flow: water 30 min [kg/m2]', 'noLiquid_100', 1800, 'excess',
     1.38, 0.005),
    ('T(1 cm) - ahcFoam 30 min [K]', 'q25_100', 1800, 'T0', -45.2, 0.05),
    ('T(10 cm) - ahcFoam 30 min [K]', 'q25_100', 1800, 'T3', 11.1, 0.05),
    ('T(5 cm) - ahcFoam 15 min [K]', 'q25_100', 900, 'T2', 31.2, 0.05),
]


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

    # 2. the flux enters exactly (surfaceHeatLoss, heatFlux): through the
    # closed top of the control column (pendularFoam) and through ahcFoam's
    # top, q t at every write; round-off of the sums (1e-10 relative)
    for r, q, log in (('noVapour_100', 1e4, 'log.pendularFoam'),
                      ('ahc_100', 2.5e4, 'log.ahcFoam')):
        e = top_energy_in(os.path.join(scratch, r, log))
        c.true('%s: energy in through the top at %d writes' % (r, len(e)),
               len(e) >= 3)
        for t, v in sorted(e.items()):
            c.le('%s: energy in through the top at %g s / (q t A) - 1'
                 % (r, t), abs(v/(q*t*AREA) - 1), 1e-10)

    # 3. mesh and step refinement at 25 kW/m2 (50 cells/5 s, 100/2.5 s,
    # 200/1.25 s), writes from 600 s: the 100 -> 200 change within TOL,
    # the largest measured (with k_rg: front 0.20 mm, 100 C isotherm
    # 0.63 mm, peak depth 1.73 mm, peak alpha_l 0.0071, water 0.060
    # kg/m2) rounded up; for the peak's depth and the water each change
    # below the previous one (the water converges slowly: observed order
    # 0.3-0.6, the front's evaporating cell). The front (alpha_0/2) and
    # the isotherm are converged to a fraction of a cell (their changes
    # do not fall monotonically), and so, from 1200 s, is the peak
    TOL = dict(zd=0.25e-3, z100=0.7e-3, zp=2e-3, peak=0.008, excess=0.065)
    UNIT = dict(zd=1e3, z100=1e3, zp=1e3, peak=1, excess=1)
    for t in TIMES[1:]:
        for k in ('zd', 'z100', 'zp', 'peak', 'excess'):
            q = [fig['q25_%d' % n][t][k] for n in (50, 100, 200)]
            d1, d2 = abs(q[1] - q[0]), abs(q[2] - q[1])
            if k in ('zp', 'excess'):
                c.true('%s at %d s: change 100 -> 200 below 50 -> 100'
                       % (k, t), d2 < d1,
                       '%.4g < %.4g' % (d2*UNIT[k], d1*UNIT[k]))
            c.le('%s at %d s: |200 - 100 cells|' % (k, t), d2*UNIT[k],
                 TOL[k]*UNIT[k])

    # 4. no vapour transport, no bump (10 kW/m2 to 900 s): alpha_l nowhere
    # above alpha_0 by more than round-off, where the run with vapour
    # transport has its bump (0.26 kg/m2 at 900 s)
    for t in (300, 600, 900):
        c.le('noVapour_100 at %d s: peak alpha_l - alpha_0' % t,
             fig['noVapour_100'][t]['peak'] - ALPHA0, 1e-6)
        c.le('noVapour_100 at %d s: water above alpha_0 [kg/m2]' % t,
             fig['noVapour_100'][t]['excess'], 1e-4)
    c.true('q10_100 at 900 s: bump above 0.1 kg/m2',
           fig['q10_100'][900]['excess'] > 0.1,
           '%.4f' % fig['q10_100'][900]['excess'])

    # 5. liquid flow spreads the bump: lower peak, deeper below the front
    for t in TIMES[1:]:
        w, wo = fig['q25_100'][t], fig['noLiquid_100'][t]
        c.true('at %d s: liquid flow lowers the peak' % t,
               w['peak'] < wo['peak'] - 0.03,
               '%.4f < %.4f' % (w['peak'], wo['peak']))
        c.true('at %d s: liquid flow moves the peak away from the front' % t,
               w['zp'] - w['zd'] > wo['zp'] - wo['zd'] + 5e-3,
               '%.2f > %.2f mm' % ((w['zp'] - w['zd'])*1e3,
                                   (wo['zp'] - wo['zd'])*1e3))

    # 6. T against ahcFoam (printed; the README's differences in 7)
    ahc = {t: temperatures(os.path.join(scratch, 'ahc_100'), t)
           for t in TIMES}
    for t in TIMES:
        print('t = %4d s: T at %s cm: pendularFoam %s, ahcFoam %s, '
              '200 - 100 cells %s K' % (
                  t, '/'.join('%g' % (d*100) for d in DEPTHS),
                  ' '.join('%.2f' % v for v in fig['q25_100'][t]['T']),
                  ' '.join('%.2f' % v for v in ahc[t]),
                  ' '.join('%+.2f' % (a - b) for a, b in
                           zip(fig['q25_200'][t]['T'],
                               fig['q25_100'][t]['T']))))

    # 6b. T under refinement: the 100 -> 200 change at most 6.5 K at 1,
    # 2, 5, 10 cm (measured 5.9 K, at 2 cm at 600 s as the front passes;
    # near the surface the changes do not all fall: 1 and 2 cm at 1200 s),
    # falling at 10 cm from 900 s; and what vapour transport does to T
    # (pendularFoam - ahcFoam, the README's) more than 3 times that change
    for t in TIMES[1:]:
        T = [fig['q25_%d' % n][t]['T'] for n in (50, 100, 200)]
        for i, d in enumerate(DEPTHS):
            d1, d2 = abs(T[1][i] - T[0][i]), abs(T[2][i] - T[1][i])
            c.le('T(%g cm) at %d s: |200 - 100 cells| [K]' % (d*100, t),
                 d2, 6.5)
            if i == 3 and t >= 900:
                c.true('T(10 cm) at %d s: change 100 -> 200 below 50 -> 100'
                       % t, d2 < d1, '%.3g < %.3g K' % (d2, d1))
    for t, i in ((1800, 0), (1800, 3), (900, 2)):
        dv = fig['q25_100'][t]['T'][i] - ahc[t][i]
        d2 = abs(fig['q25_200'][t]['T'][i] - fig['q25_100'][t]['T'][i])
        c.true('T(%g cm) at %d s: |pendularFoam - ahcFoam| > 3 x the mesh '
               'change' % (DEPTHS[i]*100, t), abs(dv) > 3*d2,
               '%.3g > 3 x %.3g K' % (abs(dv), d2))

    # 7. the README's figures (README.md, pendularFoam's 'Condensation
    # ahead of the drying front'): computed, and printed there
    readme = open(os.path.join(os.path.dirname(os.path.abspath(__file__)),
                               '..', '..', 'README.md')).read()
    i = readme.index('- **Condensation ahead of the drying front**')
    text = readme[i:readme.index('\n- **', i + 1)]
    words = set(re.findall(r'[-+]?[0-9][0-9.e-]*', ' '.join(text.split())))
    for name, value, tol, got in readme_figures(fig, ahc):
        c.le('README: %s = %g' % (name, value), abs(got - value), tol)
        c.true('README: %g printed' % value,
               '%g' % value in words or '+%g' % value in words)
    c.done()
