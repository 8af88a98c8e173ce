#!/usr/bin/env python3
"""Independent check of pendularColumn1D in the pure-conduction limit.

Exact series solution of  C dT/dt = lambda d2T/dz2  on 0 < z < H with
T(0,t) = T_init + a min(t, tRamp) (a = (T_top - T_init)/tRamp), dT/dz(H) = 0,
T(z,0) = T_init, C = (1-phi) rho_s C_s.  With u = T - T_init = g(t) + w:
  w = sum_n w_n(t) sin(l_n z),  l_n = (2n-1) pi/(2H),  b_n = 4/((2n-1) pi),
  w_n' = -k l_n^2 w_n - g'(t) b_n,   k = lambda/C.
Usage: conductionSeries.py OUTDIR [key=value ...]  (same keys as the program)
compares OUTDIR/profile_<t>.csv with the series and prints max |dT|.
"""
import csv, glob, math, os, sys

P = dict(phi=0.26, rho_s=2600.0, C_s=800.0, **{'lambda': 1.0}, H=0.1,
         T_init=293.15, T_top=463.15, tRamp=3600.0)
outdir = sys.argv[1]
for arg in sys.argv[2:]:
    k, v = arg.split('=')
    if k in P:
        P[k] = float(v)

def exact(z, t, nTerms=4000):
    k = P['lambda']/((1 - P['phi'])*P['rho_s']*P['C_s'])
    a = (P['T_top'] - P['T_init'])/P['tRamp']
    t1 = min(t, P['tRamp'])
    u = a*t1
    for n in range(1, nTerms + 1):
        l = (2*n - 1)*math.pi/(2*P['H'])
        b = 4/((2*n - 1)*math.pi)
        d = k*l*l
        wn = -a*b*(1 - math.exp(-d*t1))/d
        if t > P['tRamp']:
            wn *= math.exp(-d*(t - P['tRamp']))
        u += wn*math.sin(l*z)
    return P['T_init'] + u

worst = 0.0
for f in sorted(glob.glob(os.path.join(outdir, 'profile_*.csv')),
                key=lambda s: float(s.split('_')[-1][:-4])):
    t = float(f.split('_')[-1][:-4])
    err = 0.0
    at = {}
    with open(f) as fh:
        for row in csv.DictReader(fh):
            z, T = float(row['z']), float(row['T'])
            e = T - exact(z, t)
            err = max(err, abs(e))
            for zc in (0.01, 0.02, 0.05):
                if abs(z - zc) < 1e-9:
                    at[zc] = (T, exact(z, t))
    worst = max(worst, err)
    extra = '  '.join('T(%g)=%.4f exact %.4f' % (zc, v[0], v[1])
                      for zc, v in sorted(at.items()))
    print('t = %6g s  max|T - T_series| = %.3e K  %s' % (t, err, extra))
print('worst %.3e K' % worst)
