"""surfaceHeatLoss boundary condition against exact solutions.

(a) convective/level<N>: semi-infinite dry clay (k = 0.756 W/m/K,
    rho C = 1500*1300 J/m3/K) at Ti = 20 C, surface exchanging heat with
    air at Ta = 700 C, h = 20 W/m2/K, no radiation. Carslaw & Jaeger (1959)
    §2.7, with H = h/k, eta = z/(2 sqrt(alpha t)), beta = H sqrt(alpha t):
        T = Ti + (Ta - Ti)[erfc(eta) - exp(H z + H^2 alpha t) erfc(eta + beta)]
    evaluated as exp(-eta^2) erfcx(eta + beta) (no overflow). Compared at the
    cell centres of the top 10 cm and at the surface (boundary value) at
    t = 1800, 3600, 5400, 7200 s, on two levels: dz = 2 mm with dt = 20 s
    and dz = 1 mm with dt = 5 s (dt ~ dz^2: the scheme is second order in
    space and first order in time, so the error falls by 4 per level).
(b) slab/: 5 cm of dry clay, bottom held at Tb, top convecting to air at
    Ta and radiating (eps) to a sky at Tsky != Ta, run to steady state and
    restarted once (the written boundary entries are read back). The
    steady profile is linear, which the scheme represents exactly, so the
    surface temperature must equal the root Ts of
        k (Tb - Ts)/L = h (Ts - Ta) + eps sigma (Ts^4 - Tsky^4)
    up to the convergence to steady state and the solver tolerances.
(c) the energy balance printed by ahcFoam closes in every run, including
    a wet slab (porosity = water content = 0.2) whose surface dries, so that
    the conductivity the condition uses changes with the iterations.
(d) out-of-range entries end in a fatal error naming the patch, the
    keyword, the value and the valid range.
(e) the slab decomposed in 2 and run in parallel gives the serial result.
"""
import math
import os
import re
import sys

import hearthcheck as hc

# sigma as OpenFOAM v1912 computes it (pi^2 k^4/(60 hbar^3 c^2) with the
# constants of etc/controlDict): 5.67041e-8, 6e-6 above CODATA 2018
SIGMA = (math.pi**2/60*1.38065e-23**4
         / ((6.62607e-34/(2*math.pi))**3*2.99792e8**2))


def erfcx(x):
    """exp(x^2) erfc(x) for x >= 0, without overflow."""
    if x < 25.0:
        return math.exp(x*x)*math.erfc(x)
    # Asymptotic series (relative error < 1e-10 for x >= 25)
    x2 = 1.0/(x*x)
    return (1.0 - 0.5*x2 + 0.75*x2*x2 - 1.875*x2**3)/(x*math.sqrt(math.pi))


def convective_solution(z, t, Ti, Ta, h, k, alpha):
    """Carslaw & Jaeger §2.7: semi-infinite solid at Ti, surface z = 0
    exchanging heat with a medium at Ta through h from t = 0."""
    if t <= 0:
        return Ti
    s = math.sqrt(alpha*t)
    eta = z/(2*s)
    beta = h/k*s
    return Ti + (Ta - Ti)*(math.erfc(eta)
                           - math.exp(-eta*eta)*erfcx(eta + beta))


def read_field(path, patch):
    """Internal values and the value on one patch of a written T."""
    with open(path) as f:
        txt = f.read()
    cells = hc.read_internal_field(path)
    m = re.search(patch + r'\s*\{[^}]*?\bvalue\s+uniform\s+(\S+);', txt)
    return cells, float(m.group(1))


def time_dirs(case):
    return sorted((float(d), d) for d in os.listdir(case)
                  if re.match(r'^[0-9.e+-]+$', d) and float(d) > 0)


c = hc.Check('surfaceHeatLoss')
scratch = sys.argv[1] if len(sys.argv) > 1 else '.'

# ---------------------------------------------------------------- (a)
k, rhoC = 0.756, 1500.0*1300.0
alpha = k/rhoC
Ti, Ta, h = 293.15, 973.15, 20.0
L = 0.3

levels = sorted(d for d in os.listdir(scratch) if d.startswith('convective'))
errCells, errSurf = [], []
for lev in levels:
    case = os.path.join(scratch, lev)
    times = time_dirs(case)
    n = len(hc.read_internal_field(os.path.join(case, times[0][1], 'T')))
    dz = L/n
    eC = eS = 0.0
    for t, d in times:
        cells, Ts = read_field(os.path.join(case, d, 'T'), 'surface')
        # cell i counted from the bottom: centre at depth L - (i + 1/2) dz
        for i, T in enumerate(cells):
            depth = L - (i + 0.5)*dz
            if depth <= 0.1:
                eC = max(eC, abs(T - convective_solution(
                    depth, t, Ti, Ta, h, k, alpha)))
        eS = max(eS, abs(Ts - convective_solution(0, t, Ti, Ta, h, k, alpha)))
    print('  %s: dz = %g mm, %d writes: max |T - exact| cells %.4g K,'
          ' surface %.4g K' % (lev, 1e3*dz, len(times), eC, eS))
    errCells.append(eC)
    errSurf.append(eS)
    c.true('(a) %s reached t = 7200 s' % lev,
           abs(times[-1][0] - 7200) < 1e-6, '%g s' % times[-1][0])

if len(errCells) == 2:
    for what, e in (('cells, top 10 cm', errCells), ('surface', errSurf)):
        order = math.log(e[0]/e[1])/math.log(2.0)
        c.true('(a) observed order in dz (dt ~ dz^2), %s' % what,
               1.8 <= order <= 2.2, 'p = %.3f (expected 2, allowed [1.8, 2.2])'
               % order)
    # Measured at dz = 1 mm, dt = 5 s: 0.154 K (cells), 0.121 K (surface),
    # mostly the time error of backward Euler (0.57 K with dt = 20 s, 0.05 K
    # with dt = 1.25 s on the same mesh); 0.2 K is 0.03 % of the 680 K rise
    c.le('(a) max |T - Carslaw & Jaeger| at dz = 1 mm, cells [K]',
         errCells[1], 0.2)
    c.le('(a) max |T - Carslaw & Jaeger| at dz = 1 mm, surface [K]',
         errSurf[1], 0.2)
else:
    c.true('(a) two mesh levels', False, '%d found' % len(levels))

# ---------------------------------------------------------------- (b)
Lb, Tb, Tair, Tsky, hb, eps = 0.05, 873.15, 293.15, 253.15, 10.0, 0.9


def imbalance(Ts):
    return k*(Tb - Ts)/Lb - hb*(Ts - Tair) - eps*SIGMA*(Ts**4 - Tsky**4)


lo, hi = Tsky, Tb
for _ in range(200):
    mid = 0.5*(lo + hi)
    if imbalance(lo)*imbalance(mid) <= 0:
        hi = mid
    else:
        lo = mid
TsExact = 0.5*(lo + hi)
qExact = k*(Tb - TsExact)/Lb
print('  (b) steady root: Ts = %.6f K, q = %.4f W/m2 (convection %.2f,'
      ' radiation %.2f)' % (TsExact, qExact, hb*(TsExact - Tair),
                            eps*SIGMA*(TsExact**4 - Tsky**4)))

slab = os.path.join(scratch, 'slab')
restart = os.path.join(scratch, 'slabRestart')
tEnd = time_dirs(slab)[-1][1]
cells, Ts = read_field(os.path.join(slab, tEnd, 'T'), 'surface')
n = len(cells)
# cell i counted from the bottom (z = -L): centre at z = -L + (i + 1/2) dz
eProfile = max(abs(T - (Tb + (TsExact - Tb)*(i + 0.5)/n))
               for i, T in enumerate(cells))
c.true('(b) steady state reached (t = %s s)' % tEnd, float(tEnd) >= 60000)
c.le('(b) |Ts - root of the surface balance| [K]', abs(Ts - TsExact), 1e-6)
c.le('(b) max |T - linear steady profile| [K]', eProfile, 1e-6)

# Restart: the run stopped at 6000 s and restarted from the written field
# against the continuous run. Not bitwise: ahcFoam's first iterate after a
# restart is not extrapolated in time, and with a constant conductivity it
# takes one iteration per step, so the radiative term is linearised about a
# slightly different surface temperature (measured 2e-7 K). A restart that
# lost an entry (Tsky, emissivity, the h table) would differ by kelvins.
eRestart = 0.0
for t, d in time_dirs(slab):
    if t > 6000:
        a, sa = read_field(os.path.join(slab, d, 'T'), 'surface')
        b, sb = read_field(os.path.join(restart, d, 'T'), 'surface')
        eRestart = max([eRestart, abs(sa - sb)]
                       + [abs(x - y) for x, y in zip(a, b)])
c.le('(b) max |T restarted at 6000 s - T continuous| [K]', eRestart, 1e-3)

# ---------------------------------------------------------------- (e)
# Parallel (2 subdomains) against serial, every write; only the round-off
# of the parallel linear solver differs
parallel = os.path.join(scratch, 'slabParallel')
eParallel = 0.0
nCompared = 0
for t, d in time_dirs(slab):
    a, sa = read_field(os.path.join(slab, d, 'T'), 'surface')
    b, sb = read_field(os.path.join(parallel, d, 'T'), 'surface')
    eParallel = max([eParallel, abs(sa - sb)]
                    + [abs(x - y) for x, y in zip(a, b)])
    nCompared += 1
c.le('(e) max |T parallel - T serial|, %d writes [K]' % nCompared,
     eParallel, 1e-6)

# ---------------------------------------------------------------- (c)
logs = [os.path.join(scratch, d, 'log.ahcFoam')
        for d in levels + ['slab', 'slabRestart', 'slabParallel', 'slabWet']]
worst = 0.0
for log in logs:
    bal = hc.read_energy_balances(log)
    c.true('(c) energy balances in %s' % os.path.relpath(log, scratch),
           len(bal) > 0, '%d' % len(bal))
    worst = max([worst] + [abs(b[2]) for b in bal])
c.le('(c) energy imbalance / stored change, worst write of all runs',
     worst, 1e-6)
with open(os.path.join(scratch, 'slabWet', 'log.ahcFoam')) as f:
    iters = [int(v) for v in re.findall(r'iterations = (\d+)', f.read())]
c.true('(c) wet slab: nonlinear iterations (surface drying)',
       len(iters) > 0 and max(iters) > 2,
       '%d steps, up to %d iterations' % (len(iters), max(iters or [0])))
with open(os.path.join(scratch, levels[0], 'log.ahcFoam')) as f:
    zeroFlux = [float(v) for v in
                re.findall(r'heat in through bottom = (\S+)', f.read())]
c.true('(a) h = 0, emissivity 0 patch (bottom) is zero-flux',
       len(zeroFlux) > 0 and all(v == 0 for v in zeroFlux),
       'heat in through bottom = %s J' % (zeroFlux[-1] if zeroFlux else '?'))

# ---------------------------------------------------------------- (d)
# Bad input: the run must fail with a message naming the patch, the
# keyword and the valid range
for case, words in (
    ('badEmissivity', ["'emissivity' = 1.5", "patch 'surface'", '[0, 1]']),
    # (h's table checked over the whole run before any step: its row at
    # 50 s; before 2026-12-05 at the step that reached it, time 100)
    ('badH', ["'h' = -5", '(time 50)', "patch 'surface'", '[0, inf)']),
    ('badKappa', ["named 'kappaSoil'", "patch 'surface'"]),
):
    with open(os.path.join(scratch, case, 'log.ahcFoam')) as f:
        txt = f.read()
    missing = [w for w in words if w not in txt]
    c.true('(d) %s: fatal error naming %s' % (case, ', '.join(words)),
           'FOAM FATAL' in txt and not missing,
           'missing: %s' % missing if missing else '')

c.done()
