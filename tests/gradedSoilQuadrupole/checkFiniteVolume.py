"""(b) ahcFoam without phase change on the graded soil of Krapez & Profice
(gradedSoil.py: porosity 0, no water, c(z) and k(z) given directly in
0/rhoCpSolid and 0/kappaSolid by soilProfile) against quadrupoleTemperature.

Two problems over 24 h, on three meshes (refinement r = 1, 2, 4: cells of
4/r mm down to 1 m, fixed steps of 60/r^2 s: backward Euler is first order
in time and the scheme second order in space, so dt ~ dx^2 makes both
errors fall by 4 per level):
  temperature  the surface follows a fire history (up to 650 C): T at
               1, 2, 5, 10, 20, 50 cm and the heat that entered the soil
               (ahcFoam's energy balance, 'heat in through surface', against
               int c (T - T0) dz of the quadrupole profile, Simpson's rule on
               1600 depths to 2 m)
  flux         4 kW/m2 for 4 h then insulated: the surface temperature (the
               boundary value of the uniformFixedGradient patch) and the
               same depths

FV values at a depth: linear interpolation between the two nearest cell
centres (second order). Errors: largest over the hourly times 1..24 h.

Reference: the soil in 400 uniform-gamma layers (quadratic spacing, k and c
exact at every face); the layers approximate k(z), c(z) to O(h^2); the
400-layer error, estimated by |T_400 - T_200|/3, is below 4e-4 K
(reported; checked <= 1e-3 K), against finest-mesh errors of 3e-3 K (at
50 cm) to 6e-2 K, and is added to the Richardson bound below.

Checks, per quantity (tolerances from the observed convergence):
  - the error falls at every refinement;
  - observed order on the two finest meshes, log2(e_2/e_4), in [1.8, 2.2]
    (measured 1.99-2.01: second order, asymptotic);
  - the finest error within 1.25 x its Richardson estimate
    max_t |T_2 - T_4|/3 plus the reference's error (measured ratio 1.00):
    ahcFoam converges to the quadrupole solution, nothing else is left;
  - finest error <= 0.1 K on temperatures (measured 0.018-0.064 K; coarse
    1 K), <= 5e-4 relative on the heat (measured 1.7e-4);
  - energy imbalance of every ahcFoam write <= 1e-8 relative.
"""
import math
import os
import re
import sys

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gradedSoil as gs  # noqa: E402
import makeQuadrupoleDicts as mq  # noqa: E402
import hearthcheck as hc  # noqa: E402

c = hc.Check('gradedSoilQuadrupole (b): ahcFoam vs quadrupoles')

# The soil given to ahcFoam (case/system/soilProfileDict) is gradedSoil's
with open(os.path.join(os.path.dirname(os.path.abspath(__file__)),
                       'case', 'system', 'soilProfileDict')) as f:
    txt = re.sub(r'//[^\n]*', '', f.read())
kBlock = txt[txt.index('kappaSolid'):]
pairs = re.findall(r'\(\s*([-+0-9.eE]+)\s+(\d)\s*\)', kBlock)
kDict = [float(a) for a, e in sorted(pairs, key=lambda p: int(p[1]))]
kBelow = float(re.search(r'substrate\s*\{\s*from 1;\s*value (\S+);',
                         kBlock).group(1))
c.true('soilProfileDict: k(z) coefficients and k below 1 m = gradedSoil',
       len(kDict) == 4 and all(abs(a - b) <= 1e-15*abs(b) for a, b in
                               zip(kDict, gs.K_COEFFS))
       and abs(kBelow - gs.k(1.0)) <= 1e-15*gs.k(1.0),
       str(kDict))
cBlock = txt[txt.index('rhoCpSolid'):txt.index('kappaSolid')]
c.true('soilProfileDict: c(z) = 1.3e6 (1 + z), 2.6e6 below 1 m',
       'polynomial ((1.3e6 0) (1.3e6 1))' in cBlock
       and 'value 2.6e6;' in cBlock and gs.C_COEFFS == (1.3e6, 1.3e6))
LEVELS = (1, 2, 4)
AREA = 0.01*0.01            # cross-section of the column [m2]
HOURS = range(3600, 86401, 3600)


def quadrupole(name):
    """-> {time: [T_surface, T_depth...]}"""
    head, rows = gs.read_quadrupole_csv('quadrupole/postProcessing/%s.csv'
                                        % name)
    return {int(round(r[0])): r[1:] for r in rows}


def surface_value(path):
    with open(path) as f:
        txt = f.read()
    m = re.search(r'\n    surface\s*\{.*?\n\s*value\s+uniform\s+(\S+);', txt,
                  re.S)
    return float(m.group(1))


def finite_volume(case):
    """-> {time: [T_surface, T_depth...]} interpolated at mq.DEPTHS."""
    z = [-v for v in hc.read_internal_field(case + '/0/Cz')]
    order = sorted(range(len(z)), key=lambda i: z[i])
    zs = [z[i] for i in order]
    out = {}
    for t in HOURS:
        T = hc.read_internal_field('%s/%d/T' % (case, t))
        Ts = [T[i] for i in order]
        vals = [surface_value('%s/%d/T' % (case, t))]
        for d in mq.DEPTHS:
            j = max(i for i in range(len(zs)) if zs[i] <= d)
            w = (d - zs[j])/(zs[j + 1] - zs[j])
            vals.append((1 - w)*Ts[j] + w*Ts[j + 1])
        out[t] = vals
    return out


def surface_heat(case):
    """Heat in through the surface since t = 0 [J/m2] at the write times."""
    with open(case + '/log.ahcFoam') as f:
        txt = f.read()
    return {int(round(float(t))): float(q)/AREA for t, q in re.findall(
        r'Energy balance at t = (\S+) s \[J\]:\n'
        r'\s+heat in through surface = (\S+)', txt)}


def convergence(label, errors, rich, ref_err, tol):
    """errors: {r: e}; rich: Richardson estimate of the finest error"""
    e1, e2, e4 = (errors[r] for r in LEVELS)
    p = math.log2(e2/e4)
    print('  %-22s errors %.4g %.4g %.4g  orders %.2f %.2f  Richardson %.4g'
          % (label, e1, e2, e4, math.log2(e1/e2), p, rich))
    c.true('%s: error falls with refinement' % label, e1 > e2 > e4)
    c.true('%s: observed order %.3f in [1.8, 2.2]' % (label, p),
           1.8 <= p <= 2.2)
    c.le('%s: finest error / (1.25 Richardson + ref)' % label,
         e4/(1.25*rich + ref_err), 1.0)
    c.le('%s: finest error' % label, e4, tol)


for problem in ('temperature', 'flux'):
    name = 'bTemperature' if problem == 'temperature' else 'bFlux'
    ref = quadrupole(name + '400')
    ref2 = quadrupole(name + '200')
    fv = {r: finite_volume('%s_r%d' % (problem, r)) for r in LEVELS}
    first = 1 if problem == 'temperature' else 0   # surface imposed: skip
    print('%s problem: max |T_FV - T_quadrupole| over 1..24 h [K]' % problem)
    for i in range(first, len(mq.DEPTHS) + 1):
        label = 'surface' if i == 0 else '%g cm' % (100*mq.DEPTHS[i - 1])
        ref_err = max(abs(ref[t][i] - ref2[t][i])/3 for t in HOURS)
        errors = {r: max(abs(fv[r][t][i] - ref[t][i]) for t in HOURS)
                  for r in LEVELS}
        rich = max(abs(fv[2][t][i] - fv[4][t][i])/3 for t in HOURS)
        c.le('%s %s: reference error estimate [K]' % (problem, label),
             ref_err, 1e-3)
        convergence('%s %s' % (problem, label), errors, rich, ref_err, 0.1)
    for r in LEVELS:
        bal = hc.read_energy_balances('%s_r%d/log.ahcFoam' % (problem, r))
        c.le('%s r=%d: energy imbalance / stored, worst write' % (problem, r),
             max(abs(b[2]) for b in bal), 1e-8)

# Heat that entered through the surface (temperature problem)
head, rows = gs.read_quadrupole_csv('quadrupole/postProcessing/bHeat.csv')
z = [0.0] + mq.heat_depths()
assert len(z) == 1601 and abs(z[800] - 0.4) < 1e-12 and abs(z[-1] - 2) < 1e-12
Q = {}
for row in rows:
    f = [gs.c(zz)*(T - gs.T_INITIAL) for zz, T in zip(z, row[1:])]
    s1 = sum((1 if i in (0, 800) else 4 if i % 2 else 2)*f[i]
             for i in range(801))*0.0005/3
    s2 = sum((1 if i in (800, 1600) else 4 if i % 2 else 2)*f[i]
             for i in range(800, 1601))*0.002/3
    Q[int(round(row[0]))] = s1 + s2
heat = {r: surface_heat('temperature_r%d' % r) for r in LEVELS}
errors = {r: max(abs(heat[r][t] - Q[t])/Q[t] for t in HOURS) for r in LEVELS}
rich = max(abs(heat[2][t] - heat[4][t])/3/Q[t] for t in HOURS)
print('heat in through the surface: at 24 h %.6g J/m2 (quadrupole), '
      '%.6g (finest mesh)' % (Q[86400], heat[4][86400]))
convergence('surface heat (relative)', errors, rich, 0.0, 5e-4)
c.done()
