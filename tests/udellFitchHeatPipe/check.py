#!/usr/bin/env python3
"""Checks of tests/udellFitchHeatPipe (see run): pendularFoam's steady heat
pipe on 48, 96, 192 cells against reference.py's semi-analytical one."""
import csv
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import front as fr  # noqa: E402
import hearthcheck as hc  # noqa: E402

scratch = sys.argv[1]
c = hc.Check('udellFitchHeatPipe')
rows = list(csv.DictReader(open(os.path.join(scratch, 'reference.csv'))))
rx = [float(r['x']) for r in rows]
rS = [float(r['S']) for r in rows]
rT = [float(r['T']) for r in rows]
xRef = rx[-2]                  # the last row is the hot end
kDry = float(re.search(r'k_dry ([0-9.]+)', open(
    os.path.join(scratch, 'log.reference')).read()).group(1))
q = 100.0

Ns = (48, 96, 192)
runs = {}
for N in Ns:
    case = os.path.join(scratch, 'cells_%d' % N)
    x, S, T, t = fr.profile(case)
    times = sorted((d for d in os.listdir(case)
                    if re.fullmatch(r'[0-9.e+-]+', d) and d != '0'), key=float)
    Sprev = fr.field(os.path.join(case, times[-2], 'alphaL'))
    steady = max(abs(a - b) for a, b in zip(S, Sprev))
    xf = fr.front(x, S)
    dx = fr.L/N
    qDry = kDry*(T[-1] - T[-2])/dx
    zone = [i for i in range(N) if x[i] < xRef - 0.1]
    dT = max(abs(T[i] - fr.interp(rx, rT, x[i])) for i in zone)
    dS = max(abs(S[i] - fr.interp(rx, rS, x[i])) for i in zone)
    runs[N] = dict(x=x, S=S, T=T, xf=xf, q=qDry)
    print('%3d cells, t = %g s: front %.4f m (reference %.4f), dry-zone '
          'flux %.2f W/m2, two-phase zone max |T - T_ref| %.3f K, '
          'max |S - S_ref| %.4f, max |dS| over the last write interval '
          '%.1e' % (N, t, xf if xf else -1, xRef, qDry, dT, dS, steady))
    c.le('%d cells: steady (max |dS| over the last 3e5 s)' % N, steady, 1e-5)
    runs[N].update(dT=dT, dS=dS)
    log = open(os.path.join(case, 'log.pendularFoam')).read()
    imb = [abs(float(v)) for v in
           re.findall(r'imbalance\s+=\s+\S+ \(relative (\S+)\)', log)]
    c.le('%d cells: max relative imbalance (water, air, energy)' % N,
         max(imb) if imb else 1, 1e-9)

fine = runs[Ns[-1]]
c.le('front at 192 cells - reference [m]', abs(fine['xf'] - xRef), 0.03)
ch = [abs(runs[Ns[i + 1]]['xf'] - runs[Ns[i]]['xf']) for i in range(2)]
c.true('front: change 96 -> 192 below 48 -> 96 cells', ch[1] < ch[0],
       '%.4f < %.4f m' % (ch[1], ch[0]))


def change(a, b, key):
    """max over a's cell centres of |b - a| (b interpolated)."""
    return max(abs(fr.interp(b['x'], b[key], xa) - va)
               for xa, va in zip(a['x'], a[key]) if xa < xRef - 0.1)


for key in ('S', 'T'):
    c1 = change(runs[48], runs[96], key)
    c2 = change(runs[96], runs[192], key)
    c.true('%s: change 96 -> 192 below 48 -> 96 (two-phase zone)' % key,
           c2 < c1, '%.4g < %.4g' % (c2, c1))
c.le('192 cells: max |T - T_ref| [K] in the two-phase zone (rising: '
     'the same model difference)', fine['dT'], 1.0)
c.le('192 cells: max |S - S_ref| in the two-phase zone (not falling: '
     'mass- vs mole-fraction Fick)', fine['dS'], 0.05)
qs = [runs[N]['q'] for N in Ns]
c.true('dry-zone flux falling towards %g W/m2' % q,
       all(qs[i] > qs[i + 1] > q for i in range(2)),
       ', '.join('%.2f' % v for v in qs))
c.done()
