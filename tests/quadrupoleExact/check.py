"""quadrupoleTemperature against exact and independent solutions (see run).

Error measures (the CSVs hold 12 significant digits):
- step surface temperature: |T - T_exact| / (T_w - T_0), T_w - T_0 = 680 K;
- flux: |T - T_exact| / (surface rise of the step flux at that time,
  2 q sqrt(t/pi)/b), or / the largest rise of the history;
- tolerance 1e-8 for the closed forms; the inversion itself is good to
  about 1e-11 (tests/deHoogInversion), the superposition over a history
  multiplies it by (output time)/(shortest history interval), <= 36 here.
- two independent quadrupole runs that must agree (stacked = homogeneous,
  effusivityBottom = gamma): 1e-9 of the scale.
- finite-volume reference (fd1d.py): three grids (h = 1, 0.5, 0.25 mm near
  the surface, dt = 10, 5, 2.5 s, the stretched part refined alike). Its
  observed order must be 2 (1.9-2.1: the asymptotic range, where
  Richardson extrapolation holds); the quadrupole result must lie within
  1.25 x the Richardson estimate of the finest grid's error,
  |T_f - T_m|/3, of the finest grid, and within |R_2 - R_1| (the
  estimated error of the coarser extrapolation R_1 = (4 T_m - T_c)/3,
  larger than that of R_2 = (4 T_f - T_m)/3) of R_2.
"""
import csv
import math
import os
import sys

import hearthcheck as hc

sys.dont_write_bytecode = True     # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fd1d  # noqa: E402

c = hc.Check('quadrupoleExact')


def read_csv(path):
    """-> (depths [surface 0 first], {time: [T...]})"""
    with open(path) as f:
        rows = list(csv.reader(f))
    head = rows[0]
    assert head[0] == 'time_s' and head[1] == 'T_surface', head
    depths = [0.0] + [float(h[2:-1]) for h in head[2:]]
    data = {float(r[0]): [float(x) for x in r[1:]] for r in rows[1:]}
    return depths, data


# Homogeneous solid of the dictionaries
k, C = 1.2, 2.0e6
a = k/C
b = math.sqrt(k*C)
SQPI = math.sqrt(math.pi)


def erfc_step(z, t):
    """Rise / (T_w - T_0) under a unit step of surface temperature."""
    return math.erfc(z/(2.0*math.sqrt(a*t)))


def flux_step(z, t, q):
    """Rise under a step flux q: (2q/k) sqrt(a t) ierfc(x)."""
    x = z/(2.0*math.sqrt(a*t))
    return 2.0*q/k*math.sqrt(a*t)*(math.exp(-x*x)/SQPI - x*math.erfc(x))


def ramp_unit(z, t):
    """Rise under a surface temperature rising as t (unit slope):
    t 4 i2erfc(x) = t [(1 + 2x^2) erfc(x) - 2x exp(-x^2)/sqrt(pi)]."""
    if t <= 0:
        return 0.0
    x = z/(2.0*math.sqrt(a*t))
    return t*((1.0 + 2.0*x*x)*math.erfc(x) - 2.0*x*math.exp(-x*x)/SQPI)


# 1. Homogeneous solid -------------------------------------------------------
print('1. homogeneous semi-infinite solid (k 1.2 W/(m K), c 2e6 J/(m3 K))')
depths, T = read_csv('homogeneousStepTemperature.csv')
err = max(abs(T[t][j] - 20 - 680*erfc_step(z, t))/680
          for t in T for j, z in enumerate(depths))
c.le('step temperature, t 1 s..1e6 s: max |T - erfc|/680 K', err, 1e-8)

depths, T = read_csv('homogeneousStepFlux.csv')
err = max(abs(T[t][j] - flux_step(z, t, 1000))
          / (2*1000*math.sqrt(t/math.pi)/b)
          for t in T for j, z in enumerate(depths))
c.le('step flux 1000 W/m2: max |T - ierfc form|/surface rise', err, 1e-8)

depths, T = read_csv('homogeneousRamp.csv')
kinks = [(0.0, 680/600.0), (600.0, -680/600.0), (7200.0, -600/3600.0),
         (10800.0, 600/3600.0)]
err = max(abs(T[t][j] - 20 - sum(s*ramp_unit(z, t - tk) for tk, s in kinks))
          / 680 for t in T for j, z in enumerate(depths))
c.le('ramp-hold-cool history (60 s..6 h): max |T - i2erfc sum|/680 K',
     err, 1e-8)
c.true('surface = the history at 300 s, 1 h, 2.5 h, 6 h',
       all(abs(T[t][0] - v) < 1e-9 for t, v in
           ((300, 360), (3600, 700), (9000, 400), (21600, 100))),
       '%s' % [T[t][0] for t in (300, 3600, 9000, 21600)])

_, Tfile = read_csv('homogeneousRampFile.csv')
c.le('same history from system/rampHistory.csv (min): max |diff| [K]',
     max(abs(Tfile[t][j] - T[t][j]) for t in T for j in range(len(depths))),
     1e-9)

depths, T = read_csv('homogeneousFluxPulse.csv')
scale = 2*5000*math.sqrt(3600/math.pi)/b
err = max(abs(T[t][j] - flux_step(z, t, 5000)
              - (-flux_step(z, t - 3600, 5000) if t > 3600 else 0))/scale
          for t in T for j, z in enumerate(depths))
c.le('5000 W/m2 for 1 h then 0: max |T - ierfc sum|/surface rise at 1 h',
     err, 1e-8)

# 2. Stacked identical layers ------------------------------------------------
print('2. four layers of the same material (interfaces at 1, 2, 5, 15 cm)')
for name, scl in (('StepTemperature', 680.0), ('StepFlux', None)):
    dh, Th = read_csv('homogeneous%s.csv' % name)
    ds, Ts = read_csv('stacked%s.csv' % name)
    assert dh == ds and sorted(Th) == sorted(Ts)
    err = max(abs(Ts[t][j] - Th[t][j])
              / (scl or 2*1000*math.sqrt(t/math.pi)/b)
              for t in Th for j in range(len(dh)))
    c.le('%s: max |stacked - homogeneous|/scale' % name, err, 1e-9)

# 3. Graded semi-infinite medium --------------------------------------------
print('3. thick layer of uniform gamma (a = 5e-7 m2/s, b = 1000 exp(2 gamma xi))')
for name, g in (('gradedPositive', 1e-3), ('gradedNegative', -1e-3)):
    depths, T = read_csv(name + '.csv')
    err = 0.0
    for t in T:
        st = math.sqrt(t)
        for j, z in enumerate(depths):
            xi = z/math.sqrt(5e-7)
            ex = 0.5*(math.exp(-2*g*xi)*math.erfc(xi/(2*st) - g*st)
                      + math.erfc(xi/(2*st) + g*st))
            err = max(err, abs(T[t][j] - 20 - 680*ex)/680)
    c.le('gamma = %g s^-0.5, t 1 s..2e4 s: max |T - exact|/680 K' % g,
         err, 1e-8)

# 4. gamma -> 0 ---------------------------------------------------------------
print('4. gamma -> 0: graded layer (5 cm, b 800, a 4e-7) over b 1600, a 6e-7,'
      ' flux 1000 W/m2')
depths, T0 = read_csv('gammaLimit_0.csv')
scale0 = {t: 2*1000*math.sqrt(t/math.pi)/800 for t in T0}


def dev(name):
    _, Tg = read_csv('gammaLimit_%s.csv' % name)
    return max(abs(Tg[t][j] - T0[t][j])/scale0[t]
               for t in T0 for j in range(len(depths)))


d6, d7, d8 = dev('1e-6'), dev('1e-7'), dev('1e-8')
xiL = 0.05/math.sqrt(4e-7)
print('  max |T(gamma) - T(0)|/surface rise: gamma 1e-6: %.4g, 1e-7: %.4g,'
      ' 1e-8: %.4g (gamma xi_L = %.3g, %.3g, %.3g)'
      % (d6, d7, d8, 1e-6*xiL, 1e-7*xiL, 1e-8*xiL))
c.le('deviation at gamma = 1e-8 s^-0.5', d8, 1e-5)
c.le('|deviation(1e-6)/deviation(1e-7) - 10| (linear in gamma)',
     abs(d6/d7 - 10), 0.1)
c.le('|deviation(1e-7)/deviation(1e-8) - 10| (linear in gamma)',
     abs(d7/d8 - 10), 0.1)
_, Tb = read_csv('gammaLimit_bBottom.csv')
_, T6 = read_csv('gammaLimit_1e-6.csv')
err = max(abs(Tb[t][j] - T6[t][j])/scale0[t]
          for t in T0 for j in range(len(depths)))
c.le('effusivityBottom = 800 exp(2e-6 xi_L) vs gamma 1e-6: max diff/scale',
     err, 1e-9)

# 5. Finite-volume reference ------------------------------------------------
print('5. two-layer and graded soils against fd1d.py (finite volumes,'
      ' Crank-Nicolson)')


def uniform(kk, cc, L):
    return dict(thickness=L, bTop=math.sqrt(kk*cc), aTop=kk/cc,
                aBottom=kk/cc, gamma=0.0)


def graded_kc(k0, c0, k1, c1, L):
    """Layer given by (k, c) at its top and bottom, as quadrupoleTemperature
    reads conductivityBottom and volumetricHeatCapacityBottom."""
    b0, a0 = math.sqrt(k0*c0), k0/c0
    b1, a1 = math.sqrt(k1*c1), k1/c1
    xi = 2*L/(math.sqrt(a0) + math.sqrt(a1))
    return dict(thickness=L, bTop=b0, aTop=a0, aBottom=a1,
                gamma=math.log(b1/b0)/(2*xi))


cases = [
    ('twoLayerTemperature', 'temperature', 20.0,
     fd1d.Soil([uniform(0.5, 1.3e6, 0.02), uniform(1.5, 2.6e6, 0.04)],
               (math.sqrt(1.0*2e6), 1.0/2e6)),
     [(0, 0), (600, 680), (7200, 680), (10800, 80)]),
    ('gradedFlux', 'flux', 0.0,
     fd1d.Soil([graded_kc(0.3, 1.2e6, 0.9, 2.0e6, 0.03),
                dict(thickness=0.05, bTop=1341.640786499874, aTop=4.5e-7,
                     aBottom=6e-7, gamma=-5e-4)],
               (math.sqrt(1.2*2.2e6), 1.2/2.2e6)),
     [(0, 0), (300, 8000), (3600, 8000), (3900, 0)]),
]
for name, bc, Tinit, soil, rows in cases:
    depths, Tq = read_csv(name + '.csv')
    times = sorted(Tq)
    res = []
    for h, dt, stretch in ((1e-3, 10.0, 1.05), (5e-4, 5.0, 1.05**0.5),
                           (2.5e-4, 2.5, 1.05**0.25)):
        out, nodes = fd1d.solve(soil, bc, rows, h, dt, times[-1], depths[1:],
                                times, 0.12, 1.0, stretch)
        res.append(out)
    Tc, Tm, Tf = res
    pts = [(t, j) for t in times for j in range(len(depths))]

    def mx(f):
        return max(abs(f(t, j)) for t, j in pts)

    d_cm = mx(lambda t, j: Tc[t][j] - Tm[t][j])
    d_mf = mx(lambda t, j: Tm[t][j] - Tf[t][j])
    order = math.log(d_cm/d_mf, 2)
    est_f = d_mf/3
    err_f = mx(lambda t, j: Tq[t][j] - Tinit - Tf[t][j])
    R1 = {t: [(4*Tm[t][j] - Tc[t][j])/3 for j in range(len(depths))]
          for t in times}
    R2 = {t: [(4*Tf[t][j] - Tm[t][j])/3 for j in range(len(depths))]
          for t in times}
    dR = mx(lambda t, j: R2[t][j] - R1[t][j])
    err_R = mx(lambda t, j: Tq[t][j] - Tinit - R2[t][j])
    rise = mx(lambda t, j: Tq[t][j] - Tinit)
    print('  %s (largest rise %.1f K): FD grid errors ~ %.3g, %.3g, %.3g K;'
          ' quadrupole - finest FD %.3g K; - Richardson %.3g K'
          % (name, rise, 4*est_f*4, 4*est_f, est_f, err_f, err_R))
    c.le('%s: observed order of the FD reference |p - 2|' % name,
         abs(order - 2), 0.1)
    c.le('%s: max |quadrupole - finest FD| [K]' % name, err_f, 1.25*est_f)
    c.le('%s: max |quadrupole - Richardson R2| [K]' % name, err_R, dR)

# 6. The annotated example --------------------------------------------------
print('6. the annotated example (Krapez & Profice soil, 6 h fire at 700 C)')
depths, T = read_csv('postProcessing/quadrupoleTemperature/temperature.csv')
vals = [v for t in T for v in T[t]]
c.true('144 output times, surface and 5 depths, all finite',
       len(T) == 144 and len(depths) == 6
       and all(math.isfinite(v) for v in vals),
       '%d times, %d columns' % (len(T), len(depths)))
# noise allowed: 1e-11 x 680 K x (1 day / 10 min ramp) = 1e-6 K
c.le('maximum principle: max(T - 700, 20 - T, 0) [K]',
     max(max(v - 700, 20 - v, 0) for v in vals), 1e-6)
c.true('surface = 700 C at 6 h, 40 C from 12 h',
       abs(T[21600][0] - 700) < 1e-9 and abs(T[86400][0] - 40) < 1e-9,
       '%.12g %.12g' % (T[21600][0], T[86400][0]))

c.done()
