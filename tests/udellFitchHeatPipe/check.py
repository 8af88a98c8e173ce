#!/usr/bin/env python3
"""Checks of tests/udellFitchHeatPipe (see run): pendularFoam's steady heat
pipe on 48, 96, 192 cells, the hot end under 100 W/m2, against
reference.py's semi-analytical one with the solver's diffusion law (Fick
in mass fraction); the published form (mole fraction) is excluded."""
import csv
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import front as fr  # noqa: E402
import hearthcheck as hc  # noqa: E402

scratch = sys.argv[1]
c = hc.Check('udellFitchHeatPipe')


def reference(name):
    """(x, S, T) of a reference profile (the last row is the hot end)."""
    rows = list(csv.DictReader(open(os.path.join(scratch, name))))
    return ([float(r['x']) for r in rows], [float(r['S']) for r in rows],
            [float(r['T']) for r in rows])


def refFront(log):
    return float(re.search(r'REFERENCE front ([0-9.]+)',
                           open(log).read()).group(1))


rx, rS, rT = reference('reference.csv')
mx, mS, mT = reference('referenceMole.csv')
xRef, ThotRef = rx[-2], rT[-1]
xMole = mx[-2]
q = 100.0

Ns = (48, 96, 192)


def hotValue(case, t):
    """The hot patch's T (surfaceHeatLoss's surface temperature)."""
    s = open(os.path.join(case, t, 'T')).read()
    b = re.search(r'\n\s*hot\s*\{(.*?)\n\s*\}', s, re.S).group(1)
    return float(re.search(r'\bvalue\s+uniform\s+(\S+);', b).group(1))


def zoneDev(x, v, xs, vs, xr):
    """max |v - v_ref| at the cells 0.1 m short of the reference front."""
    return max(abs(v[i] - fr.interp(xs, vs, x[i]))
               for i in range(len(x)) if x[i] < xr - 0.1)


def load(name, N, label):
    """A run's steady profile, front, T_hot, dry-zone flux and deviations
    from the references; checks its steadiness and balances."""
    case = os.path.join(scratch, name)
    x, S, T, t = fr.profile(case)
    times = sorted((d for d in os.listdir(case)
                    if re.fullmatch(r'[0-9.e+-]+', d) and d != '0'), key=float)
    Sprev = fr.field(os.path.join(case, times[-2], 'alphaL'))
    steady = max(abs(a - b) for a, b in zip(S, Sprev))
    log = open(os.path.join(case, 'log.pendularFoam')).read()
    kDry = float(re.search(r'k_e_dry\s+(\S+)', log).group(1))
    dx = fr.L/N
    r = dict(x=x, S=S, T=T, xf=fr.front(x, S),
             Thot=hotValue(case, times[-1]),
             q=kDry*(T[-1] - T[-2])/dx if S[-2] < 1e-6 else None,
             dS=zoneDev(x, S, rx, rS, xRef), dT=zoneDev(x, T, rx, rT, xRef),
             dSm=zoneDev(x, S, mx, mS, xMole),
             dTm=zoneDev(x, T, mx, mT, xMole))
    print('%3d cells%s, t = %g s: front %.4f m (reference %.4f, published '
          'form %.4f), T_hot %.3f K (%.3f), dry-zone flux %s, two-phase '
          'zone max |S - S_ref| %.4f (%.4f), max |T - T_ref| %.3f K '
          '(%.3f), max |dS| over the last write interval %.1e'
          % (N, label, t, r['xf'], xRef, xMole, r['Thot'], ThotRef,
             '%.8f W/m2' % r['q'] if r['q'] else '-', r['dS'], r['dSm'],
             r['dT'], r['dTm'], steady))
    c.le('%d cells%s: steady (max |dS| over the last 1e6 s)' % (N, label),
         steady, 1e-5)
    imb = [abs(float(v)) for v in
           re.findall(r'imbalance\s+=\s+\S+ \(relative (\S+)\)', log)]
    c.le('%d cells%s: max relative imbalance (water, air, energy)'
         % (N, label), max(imb) if imb else 1, 1e-9)
    return r


# The study with the default upwind k_rl, k_rg (cells_N) and with their
# arithmetic mean on the faces (arith_N)
runs = dict((N, load('cells_%d' % N, N, '')) for N in Ns)
arith = dict((N, load('arith_%d' % N, N, ', arithmetic k_rl'))
             for N in Ns)


# 1. The front: first order, extrapolated onto the reference
err = [runs[N]['xf'] - xRef for N in Ns]
c.true('front: error falling by 1.5 to 2.5 per refinement (first order)',
       all(err[i + 1] > 0 and 1.5 < err[i]/err[i + 1] < 2.5
           for i in range(2)),
       ', '.join('%.4f' % e for e in err) + ' m')
xExt = 2*runs[192]['xf'] - runs[96]['xf']
c.le('front extrapolated (2 x_192 - x_96) - reference [m]',
     abs(xExt - xRef), 0.01)
c.true('front extrapolated: more than 0.1 m from the published form\'s',
       abs(xExt - xMole) > 0.1, '%.4f vs %.4f m' % (xExt, xMole))

# 2. The profiles in the two-phase zone
for key, tol, unit in (('S', 0.012, ''), ('T', 0.15, ' [K]')):
    d = [runs[N]['d' + key] for N in Ns]
    c.true('max |%s - %s_ref| falling with refinement' % (key, key),
           d[0] > d[1] > d[2], ', '.join('%.4g' % v for v in d))
    c.le('192 cells: max |%s - %s_ref|%s' % (key, key, unit), d[2], tol)
x48 = runs[48]['x']
for key, tol, tolMole, unit in (('S', 0.006, 0.04, ''),
                                ('T', 0.03, 1.0, ' [K]')):
    ext = [(xa, 2*fr.interp(runs[192]['x'], runs[192][key], xa)
            - fr.interp(runs[96]['x'], runs[96][key], xa)) for xa in x48]
    dev = max(abs(v - fr.interp(rx, rS if key == 'S' else rT, xa))
              for xa, v in ext if xa < xRef - 0.1)
    devMole = max(abs(v - fr.interp(mx, mS if key == 'S' else mT, xa))
                  for xa, v in ext if xa < xMole - 0.1)
    c.le('%s extrapolated (2 v_192 - v_96) at the 48 cells\' centres: '
         'max |%s - %s_ref|%s' % (key, key, key, unit), dev, tol)
    c.true('%s extrapolated: more than %g from the published form\'s'
           % (key, tolMole), devMole > tolMole, '%.4g' % devMole)

# 3. The hot end's T (a result now) and the flux through the dry zone
eh = [ThotRef - runs[N]['Thot'] for N in Ns]
c.true('T_hot: error falling with refinement', eh[0] > eh[1] > eh[2] > 0,
       ', '.join('%.3f' % e for e in eh) + ' K')
c.le('T_hot extrapolated (2 T_192 - T_96) - reference [K]',
     abs(2*runs[192]['Thot'] - runs[96]['Thot'] - ThotRef), 2.0)
for N in (96, 192):
    c.true('%d cells: the last two cells dry' % N, runs[N]['q'] is not None,
           '')
    if runs[N]['q'] is not None:
        c.le('%d cells: dry-zone flux / %g W/m2 - 1' % (N, q),
             abs(runs[N]['q']/q - 1), 1e-7)

# 5. Issue 14's demand, the front within 0.03 m of the reference at the
# finest mesh: with the upwind k_rl above it is 0.042 m off at 192 cells
# (first order, 3.4 cells behind). With the arithmetic mean of k_rl and
# k_rg on the faces (liquidDarcyFlux's second-order choice) the profiles'
# error is a fraction of the upwind one's and the front lies within one
# cell of the reference's at every mesh (0.0106, 0.0125, 0.0043 m:
# 0.21, 0.50, 0.34 cells), not monotone in the cell size: no order is
# claimed for it (where the front falls between two centres sets the
# linear marker's error).
errA = [arith[N]['xf'] - xRef for N in Ns]
for N, e in zip(Ns, errA):
    c.le('%d cells, arithmetic k_rl: |front - reference| / cell size'
         % N, abs(e)/(fr.L/N), 1.0)
c.le('192 cells, arithmetic k_rl: |front - reference| [m] (issue 14: '
     '0.03)', abs(errA[2]), 0.03)
for key, tol, unit in (('S', 0.004, ''), ('T', 0.12, ' [K]')):
    d = [arith[N]['d' + key] for N in Ns]
    c.true('arithmetic k_rl: max |%s - %s_ref| falling with refinement'
           % (key, key), d[0] > d[1] > d[2],
           ', '.join('%.4g' % v for v in d))
    c.le('192 cells, arithmetic k_rl: max |%s - %s_ref|%s'
         % (key, key, unit), d[2], tol)
    c.true('192 cells: arithmetic k_rl\'s max |%s - %s_ref| below the '
           'upwind one\'s' % (key, key), d[2] < runs[192]['d' + key],
           '%.4g vs %.4g' % (d[2], runs[192]['d' + key]))
ehA = [ThotRef - arith[N]['Thot'] for N in Ns]
c.true('arithmetic k_rl: T_hot error falling with refinement',
       ehA[0] > ehA[1] > ehA[2] > 0, ', '.join('%.3f' % e for e in ehA)
       + ' K')
c.le('arithmetic k_rl: T_hot extrapolated (2 T_192 - T_96) - reference '
     '[K]', abs(2*arith[192]['Thot'] - arith[96]['Thot'] - ThotRef), 1.0)
for N in (96, 192):
    if arith[N]['q'] is not None:
        c.le('%d cells, arithmetic k_rl: dry-zone flux / %g W/m2 - 1'
             % (N, q), abs(arith[N]['q']/q - 1), 1e-7)
    else:
        c.true('%d cells, arithmetic k_rl: the last two cells dry' % N,
               False, '')

# 2b. The diffusivity: the front's shift from tau D_wa = 1e-5 m2/s (96
# cells, arithmetic k_rl: upwind, the two runs cost 81158 iterations
# instead of 17771)
shifts, refShifts, moleFronts = [], [], []
for tau in ('0.15', '1.0'):
    case = os.path.join(scratch, 'tau_' + tau)
    x, S, T, t = fr.profile(case)
    xr = refFront(os.path.join(case, 'log.reference'))
    moleFronts.append(refFront(os.path.join(case, 'log.referenceMole')))
    shifts.append(fr.front(x, S) - arith[96]['xf'])
    refShifts.append(xr - xRef)
    print('tortuosity %s (tau D_wa %g m2/s), 96 cells, arithmetic k_rl: '
          'front %.4f m (shift %+.4f), reference %.4f m (shift %+.4f), '
          'published form %.4f m'
          % (tau, float(tau)*2e-5, fr.front(x, S), shifts[-1], xr,
             refShifts[-1], moleFronts[-1]))
c.le('96 cells, arithmetic k_rl, tau D_wa 3e-6, 2e-5 m2/s: max |shift '
     '- reference shift| [m]',
     max(abs(a - b) for a, b in zip(shifts, refShifts)), 0.006)
c.true('the front moves with tau D_wa as the reference\'s (rising), the '
       'published form\'s the other way',
       shifts[0] < 0 < shifts[1] and refShifts[0] < 0 < refShifts[1]
       and moleFronts[0] > xMole > moleFronts[1],
       'solver %+.4f, %+.4f; reference %+.4f, %+.4f m' % (
           shifts[0], shifts[1], refShifts[0], refShifts[1]))
c.done()
