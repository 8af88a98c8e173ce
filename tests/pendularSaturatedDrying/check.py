#!/usr/bin/env python3
"""Checks of tests/pendularSaturatedDrying (see its run script): balances,
convergence under refinement, 2 ranks = serial, storage and gas seed."""
import math
import os
import re
import sys
import hearthcheck as hc

scratch = sys.argv[1]
H = 0.1
failures = []


def check(ok, what):
    print(('  ok   ' if ok else '  FAIL ') + what)
    if not ok:
        failures.append(what)


def field(run, t, name):
    """Internal field of run/t/name as a list (uniform expanded)."""
    s = open(os.path.join(scratch, run, t, name)).read()
    m = re.search(r'internalField\s+uniform\s+(\S+);', s)
    n = int(re.search(r'nCells\s+(\d+);', open(os.path.join(
        scratch, run, 'system', 'blockMeshDict')).read()).group(1))
    if m:
        return [float(m.group(1))]*n
    m = re.search(r'internalField\s+nonuniform\s+List<scalar>\s*\d+\s*\((.*?)\)\s*;',
                  s, re.S)
    return [float(v) for v in m.group(1).split()]


def depths(n):
    """Depths of the cell centres, cells ordered from the bottom."""
    return [H - (i + 0.5)*H/n for i in range(n)]


def at(values, z):
    """Linear interpolation in depth z between the cell centres."""
    d = depths(len(values))
    pts = sorted(zip(d, values))
    for (z0, v0), (z1, v1) in zip(pts, pts[1:]):
        if z0 <= z <= z1:
            return v0 + (v1 - v0)*(z - z0)/(z1 - z0)
    raise ValueError('depth %g outside the cell centres' % z)


def front(run, t, level=0.999):
    """Depth of the gas front: from the top down, where alpha_l reaches
    level (linear between cell centres; 0 if the top cell is above it)."""
    a = field(run, t, 'alphaL')
    pts = sorted(zip(depths(len(a)), a))
    if pts[0][1] >= level:
        return 0.0
    for (z0, a0), (z1, a1) in zip(pts, pts[1:]):
        if a0 < level <= a1:
            return z0 + (level - a0)*(z1 - z0)/(a1 - a0)
    return H


def quantities(run):
    return {
        'front(400 s) [m]': front(run, '400'),
        'T(1 cm, 400 s) [K]': at(field(run, '400', 'T'), 0.01),
        'T(2 cm, 400 s) [K]': at(field(run, '400', 'T'), 0.02),
        'T(1 cm, 600 s) [K]': at(field(run, '600', 'T'), 0.01),
        'T(2 cm, 600 s) [K]': at(field(run, '600', 'T'), 0.02),
    }


# 1. Balances at every write of every run: |imbalance| <= 1e-10 of the
# balance's scale (stored change + patch flows, as pendularFoam's
# 'relative'), or, where that scale is tiny (nothing has left yet), <= what
# the Newton tolerances leave over the column's volume V: WTol WScale V
# (water; WTol 1e-11, WScale 260 kg/m3, the initial water), phi M_a pTol
# V/(R T) (air; pTol 1e-4 Pa, 293 K), C TTol V (energy; TTol 1e-7 K, C <=
# 3e6 J/m3/K)
V = 0.1*0.01*0.01
newtonFloor = {
    'Water': 1e-11*260*V,
    'Air': 0.26*0.029*1e-4*V/(8.31*293),
    'Energy': 3e6*1e-7*V,
}


def balanceBounds(log):
    """(number of balances, worst |imbalance|/bound, largest relative
    imbalance) of a pendularFoam log's text, the bound max(1e-10 of its
    scale, the Newton floor of its quantity)"""
    blocks = re.findall(
        r'(Water|Air|Energy) balance at t = (\S+) s .*?in the domain\s+=\s+(\S+)'
        r'.*?imbalance\s+=\s+(\S+) \(relative (\S+)\)', log, re.S)
    worst = 0
    worstRel = 0
    for what, t, content, imb, rel in blocks:
        imb, rel = float(imb), float(rel)
        scale = abs(imb/rel) if rel != 0 else 0
        worst = max(worst, abs(imb)/max(1e-10*scale, newtonFloor[what]))
        worstRel = max(worstRel, abs(rel))
    return len(blocks), worst, worstRel


runs = ['cells_10', 'cells_20', 'cells_40', 'serialFixed_20',
        'parallelFixed_20', 'serialFixed1_20', 'storage10_20', 'seed1e-6_20',
        'outflow_20',
        'step1_20', 'step0.5_20', 'lowK_20', 'lowK_40', 'lowK_80',
        'bubble_40']
for run in runs:
    log = open(os.path.join(scratch, run, 'log.pendularFoam')).read()
    n, worst, worstRel = balanceBounds(log)
    check(n == 9 and worst <= 1,
          '%s: %d balances (3 writes), worst |imbalance| %.3g of its bound'
          ' (largest relative %.3g)' % (run, n, worst, worstRel))

# 8. The graded 40-cell column (30 um top cell) to 150 s, liquid-only: its
# balances at 50, 100, 150 s as in 1, and its sub-steps rejected at
# maxIter: the water and energy residuals of its thin top cells stall at
# the round-off floor of their unknowns (one unit of round-off of the
# absolute p_l moves a 30-um cell's water residual by 70-220 tolerances
# at dt ~ 1 s); judged against it (pendularNewton::unknownsRoundOff) 19
# sub-steps are rejected at maxIter, 34 without it (planted back once,
# 2026-12-03, with the liquid-only cells' own Jacobian steps; 12 and 26
# before them): the bound between the two. floorFix (2026-12-03): a cell
# accepted on the floor only within it, the floor capped at 1e3
# tolerances: 18 measured
log = open(os.path.join(scratch, 'graded_40', 'log.pendularFoam')).read()
n, worst, _ = balanceBounds(log)
check(n == 9 and worst <= 1,
      'graded_40 (to 150 s): %d balances (3 writes), worst |imbalance| %.3g'
      ' of its bound' % (n, worst))
nMaxIter = len(re.findall(r'rejected after \d+ iterations \(nonlinear'
                          r' iterations not converged\)', log))
check(nMaxIter <= 25,
      'graded_40 (to 150 s): %d sub-steps rejected at maxIter (at most 25;'
      ' 34 without the unknowns\' round-off floor)' % nMaxIter)

# 8b. graded_40 continued to 160 s: the gas appears in its top cells
# (issue 14: the run stopped at minDeltaT at 157.72 s with the gas residual
# R_w + R_a, whose water part was judged against the air's tolerance; 600 s
# reached since, doc/measurements.md, gradedStall2, gradedStall3): balances at 160 s as
# in 1, gas in at least one cell
log = open(os.path.join(scratch, 'gradedGas_40', 'log.pendularFoam')).read()
n, worst, _ = balanceBounds(log)
nGas = sum(1 for g in field('gradedGas_40', '160', 'gasPresent') if g > 0.5)
check(n == 3 and worst <= 1 and nGas > 0,
      'gradedGas_40 (150 to 160 s): %d balances (1 write), worst |imbalance|'
      ' %.3g of its bound, gas in %d cell(s) at 160 s' % (n, worst, nGas))

# 6. Restart from the written phase state (400 s) with fixed steps
same = all(x == y for x, y in zip(field('serialFixed_20', '600', 'gasPresent'),
                                  field('restartFixed_20', '600', 'gasPresent')))
wT = max(abs(x - y)/max(abs(x), abs(y)) for x, y in zip(
    field('serialFixed_20', '600', 'T'), field('restartFixed_20', '600', 'T')))
check(same and wT <= 1e-4,
      'restart from 400 s: the same cells hold gas at 600 s (%s), T within'
      ' %.3g relative (1e-4 required)' % (same, wT))

# 5. The dissolved air drained through the bottom is in the air balance
log = open(os.path.join(scratch, 'outflow_20', 'log.pendularFoam')).read()
airOut = [float(v) for v in re.findall(
    r'Air balance at t = \S+ s \[kg\]:.*?out through bottom = (\S+)', log,
    re.S)]
check(len(airOut) == 3 and min(airOut) > 0,
      'outflow_20: dissolved air out through bottom %s kg (in the balances'
      ' checked above)' % airOut)

# 2. Refinement: nothing here converges, printed only. T(2 cm, 400 s) and
# T(1 cm, 600 s) change less and less on 10, 20, 40 cells (1.21 then
# 0.075 K, 11 then 0.05 K), but on 80 cells (bench/pendularSaturatedFine,
# 136 s) they move by 0.57 and 33.5 K: apparent, not converged. The gas
# front, the water lost, T(1 cm, 400 s) and T(2 cm, 600 s) do not either,
# and cannot: the top is open (p_w of dry air) and held at
# the wall's T, the liquid drawn up to it by capillarity (K = 1e-11 m2)
# keeps the top cell wet and boiling at ~373 K whatever its size, so the
# wall's heat reaches the evaporation across half a top cell, lambda (T_w
# - T_1)/(dz/2), and the water evaporated through the top grows as the
# cells shrink (the dry layer that must separate the 200 C wall from the
# liquid is thinner than the top half-cell of these meshes; not a defect
# of the phase switching: the same growth with an imposed heat flux). The
# checks below hold that diagnosis (they fail if the top's evaporation
# converged): the top cell within 1 K of boiling at 1 atm at 600 s, and
# the water out through the top at 600 s more than doubled at each halving
# (a converging quantity changes less and less: ratio -> 1)
converging = ()    # see above: none on this case
q = {n: quantities('cells_%d' % n) for n in (10, 20, 40)}
meshError = {}
for k in q[10]:
    d1 = q[20][k] - q[10][k]
    d2 = q[40][k] - q[20][k]
    meshError[k] = abs(d2)
    order = math.log2(abs(d1/d2)) if d2 != 0 and d1 != 0 else float('nan')
    text = ('%s: %.6g, %.6g, %.6g on 10, 20, 40 cells (changes %.3g, %.3g:'
            ' observed order %.2f)' % (k, q[10][k], q[20][k], q[40][k], d1, d2,
                                       order))
    if k in converging:
        check(abs(d2) < abs(d1), text)
    else:
        print('  (printed, not converged) ' + text)


def waterOut(run, t):
    """Water out through the top by time t [kg/m2] (pendularFoam's balance;
    the column's section 1 cm x 1 cm)."""
    log = open(os.path.join(scratch, run, 'log.pendularFoam')).read()
    m = re.search(r'Water balance at t = %s s \[kg\]:\s*out through top = (\S+)'
                  % t, log)
    return float(m.group(1))/1e-4


Tw = 473.15    # the wall at 600 s
out = {n: waterOut('cells_%d' % n, '600') for n in (10, 20, 40)}
top = {n: field('cells_%d' % n, '600', 'T')[-1] for n in (10, 20, 40)}
for n in (10, 20, 40):
    print('  cells_%d at 600 s: water out through the top %.4g kg/m2, top'
          ' cell %.2f K, lambda (T_w - T_1)/(dz/2) = %.3g W/m2'
          % (n, out[n], top[n], 1.0*(Tw - top[n])/(0.5*H/n)))
check(all(abs(top[n] - 373.15) <= 1 for n in (20, 40)),
      'the top cell boils at 600 s on 20 and 40 cells (%.2f, %.2f K; 373.15'
      ' +- 1 K required)' % (top[20], top[40]))
check(out[20] > 2*out[10] and out[40] > 2*out[20],
      'the water out through the top at 600 s grows with the top cell\'s'
      ' conductance, not converging: %.3g, %.3g, %.3g kg/m2 on 10, 20, 40'
      ' cells (ratios %.2f, %.2f; > 2 required)'
      % (out[10], out[20], out[40], out[20]/out[10], out[40]/out[20]))
# The time step is not the cause: on 20 cells, maxDeltaTemperature 2, 1,
# 0.5 K (maxDeltaT 120, 60, 60 s) change the water out at 600 s less and
# less, and by less than 5 % of the 20 -> 40 cells change (the time error,
# first order, below a tenth of the space one; 1.69258, 1.68073, 1.67288
# kg/m2 measured), T at 1 and 2 cm at 400 and 600 s by less than 0.5 K
# (0.25 K measured, T(1 cm, 400 s); the 20 -> 40 cells changes of the
# quantities printed above as not converged are 7 K)
st = [out[20]] + [waterOut('step%s_20' % m, '600') for m in ('1', '0.5')]
d1, d2 = st[1] - st[0], st[2] - st[1]
check(abs(d2) < abs(d1) and abs(st[2] - st[0]) < 0.05*abs(out[40] - out[20]),
      'steps 2, 1, 0.5 K on 20 cells: water out at 600 s %.6g, %.6g, %.6g'
      ' kg/m2 (changes %.3g, %.3g; the change %.3g below 5 %% of the 20 ->'
      ' 40 cells change %.3g)' % (st[0], st[1], st[2], d1, d2, st[2] - st[0],
                                  out[40] - out[20]))
qs = quantities('step0.5_20')
wt = max(abs(qs[k] - q[20][k]) for k in qs if k.startswith('T'))
check(wt < 0.5, 'steps 2 -> 0.5 K on 20 cells: T at 1, 2 cm, 400, 600 s'
      ' within %.3g K (0.5 K required)' % wt)

# 2b. The same column with the liquid's permeability 1e-14 m2: the
# capillary supply falls short of the evaporation, the top dries and the
# front recedes from it, a dry zone the meshes resolve: the front (alpha_l
# = 0.999) at 400 and 600 s and T at 1 and 2 cm (but T(2 cm, 600 s))
# converge on 20, 40, 80 cells (10 cells: too coarse, the gas still in the top cell alone at
# 400 s): each change smaller than the previous, the observed order
# printed. Measured (2026-12-03, the sub-step growing back within its
# step): the 0.999 front at 600 s 26.68, 28.05, 28.30 mm (changes 1.38,
# 0.24 mm; 26.66, 28.11, 28.30 before); T(2 cm, 600 s) not (0.704, 0.749
# K; 0.713, 0.740 before); the
# water out through the top at 400 s does not (0.15, 0.64, 1.23 kg/m2 on
# 20-80 cells: the top cell still wet and boiling then, as above), nor
# the front at alpha_l = 0.9 at 600 s (14.05, 13.90, 13.03 mm), printed
def lowK(run):
    r = quantities(run)
    r['front(600 s) [m]'] = front(run, '600')
    return r


# Converging means each change at most 0.8 of the previous (an observed
# order of at least 0.32: a change equal to the previous one, within the
# round-off of the runs' step sequences, is no evidence). T(2 cm, 600 s)
# is not: changes 0.704 then 0.749 K (printed only)
lk = {n: lowK('lowK_%d' % n) for n in (20, 40, 80)}
for k in lk[20]:
    d1 = lk[40][k] - lk[20][k]
    d2 = lk[80][k] - lk[40][k]
    order = math.log2(abs(d1/d2)) if d2 != 0 and d1 != 0 else float('nan')
    text = ('K 1e-14: %s: %.6g, %.6g, %.6g on 20, 40, 80 cells (changes'
            ' %.3g, %.3g: observed order %.2f)'
            % (k, lk[20][k], lk[40][k], lk[80][k], d1, d2, order))
    if k == 'T(2 cm, 600 s) [K]':
        print('  (printed, not converged) ' + text)
    else:
        check(abs(d2) <= 0.8*abs(d1), text + ', each change <= 0.8 of the'
              ' previous required')
print('  (printed, not converged) K 1e-14: front at alpha_l = 0.9 at 600 s'
      ' %.4g, %.4g, %.4g mm on 20, 40, 80 cells'
      % tuple(1e3*front('lowK_%d' % n, '600', 0.9) for n in (20, 40, 80)))
print('  (printed, not converged) K 1e-14: water out through the top at 400'
      ' s %.3g, %.3g, %.3g kg/m2 on 20, 40, 80 cells; at 600 s %.3g, %.3g,'
      ' %.3g' % tuple([waterOut('lowK_%d' % n, t) for t in ('400', '600')
                       for n in (20, 40, 80)]))

# 3. 2 ranks against serial (fixed steps, direct linear solves): 1e-8
# while every cell is liquid-only (200 s); then the same phases and T
# within 1e-5 (the sub-steps where the gas appears take 15-30 chaotic
# Newton iterations, which round-off steers: see the run script)
def largest(t, names):
    worst = 0
    for name in names:
        a = field('serialFixed_20', t, name)
        b = field('parallelFixed_20', t, name)
        for x, y in zip(a, b):
            worst = max(worst, abs(x - y)/max(abs(x), abs(y), 1e-300))
    return worst


allNames = ('T', 'p', 'W', 'alphaL', 'gasPresent', 'Xair', 'pl')
w = largest('200', allNames)
liquidOnly = all(g == 0 for g in field('serialFixed_20', '200', 'gasPresent'))
check(w <= 1e-8 and liquidOnly,
      '2 ranks = serial at 200 s, every cell liquid-only (%s): T p W alphaL'
      ' gasPresent Xair pl within %.3g (1e-8 required)' % (liquidOnly, w))
for t in ('400', '600'):
    same = largest(t, ('gasPresent',)) == 0
    wT = largest(t, ('T',))
    check(same and wT <= 1e-5,
          '2 ranks against serial at %s s: the same cells hold gas (%s), T'
          ' within %.3g relative (1e-5 required)' % (t, same, wT))
gp = field('serialFixed_20', '600', 'gasPresent')
check(gp[9] == 1 and gp[10] == 1,
      'the gas on both sides of the processor boundary at 600 s')

# 4. Storage x10: within the 20 -> 40 cells change (below the
# discretisation error of the 20-cell run); gasSeed 1e-6, fixed 2 s steps:
# within the change that halving the steps makes (serialFixed1_20, 1 s
# steps: the time-discretisation error of the 2 s run, backward Euler).
# The seed moves Newton's iterates only, but with them the sub-steps that
# are rejected and halved (42 against 47 of the 300 steps with the fire
# 0.01 K hotter), hence a part of the time-discretisation error: measured
# 2.6e-4 mm and 4e-4 K at T(1 cm, 400 s), 0.033 mm and 0.039 K with the
# fire 0.01 K hotter, against 0.35 mm and 0.13 K from halving the steps.
# A seed that changed the solution (a gas fraction kept, not a Newton
# iterate) would move the results beyond the time-discretisation error.
r = quantities('storage10_20')
for k in r:
    d = r[k] - q[20][k]
    check(abs(d) <= meshError[k],
          'storage x10: %s changes by %.3g (bound %.3g: the 20 -> 40 cells'
          ' change)' % (k, d, meshError[k]))
r = quantities('seed1e-6_20')
rFixed = quantities('serialFixed_20')
rHalf = quantities('serialFixed1_20')
for k in r:
    d = r[k] - rFixed[k]
    bound = abs(rHalf[k] - rFixed[k])
    check(abs(d) <= bound,
          'gasSeed 1e-6: %s changes by %.3g (bound %.3g: halving the 2 s'
          ' steps)' % (k, d, bound))

# 8. The linear solver of the Newton steps on 2 ranks (issue 14): the 40
# cells to 20 s, serial and on 2 ranks with the default settings (LU,
# MUMPS, by default with saturatedZone on a decomposed mesh): the same
# sub-steps and Newton iterations (10 and 37 measured, identical), at
# most 10 % more on 2 ranks; with block Jacobi ILU (the default before:
# GMRES broke down 100-150 iterations short of relTol, 80 steps and 1132
# iterations measured) the one-time hint is printed once


def newtonCost(run):
    """The log of run and its steps and Newton iterations (the shared
    reader of the per-step summary lines, tests/lib/hearthcheck.py)."""
    name = os.path.join(scratch, run, 'log.pendularFoam')
    cost = hc.read_solver_cost(name)
    return open(name).read(), cost['steps'], cost['iterations']


_, nSerial, itSerial = newtonCost('short_40')
log, nPar, itPar = newtonCost('shortParallel_40')
check('Saturated zone on 2 ranks: the Newton steps solved by LU (MUMPS) by'
      ' default' in log, '2 ranks: LU (MUMPS) by default, said in the log')
# a format change of the summary line would count 0 steps in both runs
check(nSerial > 0 and nPar > 0 and itPar <= 1.1*itSerial
      and nPar <= 1.1*nSerial,
      '2 ranks, default linear solver: %d steps, %d Newton iterations'
      ' (serial %d, %d; both read, at most 10 %% more)'
      % (nPar, itPar, nSerial, itSerial))
# 3 ranks (simple, processor boundaries at 3.3 and 6.7 cm): LU by default
# as on 2, the same steps and iterations (35 of 35 measured; at most 10 %
# more), the fields at 20 s equal to serial within 1e-8 relative (a few
# Newton tolerances, pTol/p = 1e-9, as the 2-rank fixed-step run at 200 s;
# 9.8e-10 measured in p, T identical to the 10 digits written) and the
# balances of the write as in 1
log3, n3, it3 = newtonCost('shortParallel3_40')
check('Saturated zone on 3 ranks: the Newton steps solved by LU (MUMPS) by'
      ' default' in log3, '3 ranks: LU (MUMPS) by default, said in the log')
check(n3 > 0 and it3 <= 1.1*itSerial and n3 <= 1.1*nSerial,
      '3 ranks, default linear solver: %d steps, %d Newton iterations'
      ' (serial %d, %d; at most 10 %% more)' % (n3, it3, nSerial, itSerial))
worst3, where3 = 0, ''
for name in ['T', 'p', 'pl', 'W', 'alphaL', 'Xair']:
    s = field('short_40', '20', name)
    q = field('shortParallel3_40', '20', name)
    e = max(abs(a - b) for a, b in zip(s, q))/max(abs(a) for a in s)
    if len(s) != len(q) or e >= worst3:
        worst3, where3 = (e if len(s) == len(q) else 1), name
check(worst3 <= 1e-8, '3 ranks = serial at 20 s: max |diff|/max = %.3g'
      ' (%s; at most 1e-8)' % (worst3, where3))
n, worst, _ = balanceBounds(log3)
check(n == 3 and worst <= 1,
      '3 ranks: %d balances (1 write), worst |imbalance| %.3g of its bound'
      % (n, worst))
hint = 'linear solves of this sub-step\'s Newton steps stopped short'
check(hint not in log, '2 ranks, default: no hint of inexact linear solves')
log, nBj, itBj = newtonCost('shortBjacobi_40')
check(log.count(hint) == 1,
      '2 ranks, block Jacobi: the hint of inexact linear solves printed once'
      ' (%d times; %d steps, %d Newton iterations)'
      % (log.count(hint), nBj, itBj))
# the reason for LU by default: block Jacobi ILU's 2-rank run is several
# times costlier than serial (80 steps and 1132 Newton iterations against
# 10 and 37 measured); bound: twice the default's steps
check(nBj > 2*nPar,
      '2 ranks, block Jacobi: %d steps, more than twice the default\'s %d'
      % (nBj, nPar))
# a preconditioner's keyword without 'preconditioner' (here
# 'subPreconditioner ilu;' alone) keeps block Jacobi: no LU by default,
# and the log says so
log = open(os.path.join(scratch, 'subIlu_20', 'log.pendularFoam')).read()
check('solved by LU' not in log
      and 'the preconditioner of the Newton steps as set in' in log
      and 'subPreconditioner' in log,
      '2 ranks, subPreconditioner ilu alone: no LU by default, said in the'
      ' log')

if failures:
    print('%d check(s) failed' % len(failures))
    sys.exit(1)
print('all checks passed')
