"""pendularFoam, timeScheme BDF2 (variable-step BDF2, variableStepBdf2.H).

Order: the pressure of the isothermal pressure diffusion (linear, smooth)
at 2 s, largest difference over the cells from BDF2 at 0.0015625 s (whose
own error is below 1 % of the coarsest BDF2 run's). Measured (2026-12-02):
Euler 0.0671, 0.0344, 0.0172 Pa at 0.1, 0.05, 0.025 s (ratios 1.95,
2.00); BDF2 2.52e-3, 5.93e-4, ... Pa (ratio 4.25). Required: Euler ratios
in [1.7, 2.3] (first order), BDF2 ratios in [3.4, 4.6] (second order; a
first-order start alone would give 2). The coarsest step 0.2 s is left
out: it does not resolve the initial layer of the pressure step (ratio 1).

Column: T - reference (same 100 cells, BDF2 in time with its own error
control: tests/pendularReference) at 1, 2, 5 cm at 1, 3, 12 h. Measured:
BDF2 driven by localErrorTol 0.1 K, at most 0.019 K (0.016 K before the
dry cells' water kept backward Euler); backward Euler at
maxDeltaTemperature 2 K (the bench's default steps), 0.36 K (printed, not
required). Required: BDF2 within 0.05 K (three times the measured error:
the reference's own tolerance and the error control's variation), the
issue's 0.1 K with margin.

Balances: the water, air and energy balances with the BDF2 term C^N in
the stored change. Pressure diffusion (TTol 1e-9 K, pTol 1e-9 Pa), water
and air closed to 1e-10 relative (measured 4.7e-11; its isothermal energy
balance is excluded: its flows are round-off, tests/
pendularPressureDiffusion). Column at the tutorial's tolerances (TTol
1e-6 K, pTol 1e-2 Pa, WTol 1e-10): the worst balance (air) closes to
2.03e-10 with BDF2 (1.65e-10 before the dry cells' water kept backward
Euler) and 1.73e-10 with backward Euler (measured 2026-12-02; pTol 1e-4
Pa did not lower BDF2's: 2.6e-10), so both are required below 3e-10, and
without the BDF2 term the imbalance would be 0.098 (printed): the closing
form discriminates by eight orders of magnitude.
"""
import csv
import os
import re
import sys
import hearthcheck as hc

scratch = sys.argv[1]
c = hc.Check('pendularBdf2')

ref = hc.read_internal_field(os.path.join(scratch, 'BDF2_ref', '2', 'p'))
for scheme, lo, hi in (('Euler', 1.7, 2.3), ('BDF2', 3.4, 4.6)):
    err = []
    for dt in ('0.1', '0.05', '0.025'):
        p = hc.read_internal_field(os.path.join(scratch, '%s_%s' % (scheme, dt), '2', 'p'))
        err.append(max(abs(a - b) for a, b in zip(p, ref)))
    print('  %s: max |p - p_ref| at 2 s, steps 0.1, 0.05, 0.025 s: %s Pa'
          % (scheme, ', '.join('%.4g' % e for e in err)))
    for i in (0, 1):
        r = err[i]/max(err[i + 1], 1e-300)
        c.true('%s error ratio, step %s -> half' % (scheme, ('0.1', '0.05')[i]),
               lo <= r <= hi, '%.3f in [%g, %g]' % (r, lo, hi))
    bal = hc.read_energy_balances(os.path.join(scratch, '%s_0.025' % scheme, 'log.pendularFoam'))
    # water, air (every third from 0 and 1): the energy flows are round-off
    wa = [b for i, b in enumerate(bal) if i % 3 != 2]
    c.le('%s pressure diffusion: worst relative imbalance, water and air' % scheme,
         max(abs(b[2]) for b in wa), 1e-10)

H, N = 0.1, 100
depth = [H - (i + 0.5)*H/N for i in range(N)]


def interp(z, zs, vs):
    pts = sorted(zip(zs, vs))
    for (a, va), (b, vb) in zip(pts, pts[1:]):
        if a <= z <= b:
            return va + (vb - va)*(z - a)/(b - a)


for case, tol in (('columnBDF2', 0.05), ('columnEuler', None)):
    worst = 0
    for t in (3600, 10800, 43200):
        T = hc.read_internal_field(os.path.join(scratch, case, str(t), 'T'))
        rows = list(csv.DictReader(open(os.path.join(scratch, 'reference', 'profile_%d.csv' % t))))
        zr = [float(r['z']) for r in rows]
        Tr = [float(r['T']) for r in rows]
        d = [interp(z, depth, T) - interp(z, zr, Tr) for z in (0.01, 0.02, 0.05)]
        print('  %s: T - reference at 1, 2, 5 cm, %2d h: %s K'
              % (case, t//3600, ' '.join('%+.4f' % x for x in d)))
        worst = max(worst, max(abs(x) for x in d))
    cost = hc.read_solver_cost(os.path.join(scratch, case, 'log.pendularFoam'))
    print('  %s: %d steps, %d Newton iterations'
          % (case, cost['steps'], cost['iterations']))
    bal = hc.read_energy_balances(os.path.join(scratch, case, 'log.pendularFoam'))
    c.true('%s: balances reported' % case, len(bal) >= 9)
    c.le('%s: worst relative imbalance (water, air, energy)' % case,
         max(abs(b[2]) for b in bal), 3e-10)
    if tol is None:
        print('  %s: largest |T - reference| %.4f K (not required)' % (case, worst))
        continue
    c.le('%s: largest |T - reference| at 1, 2, 5 cm, 1-12 h [K]' % case, worst, tol)
    log = open(os.path.join(scratch, case, 'log.pendularFoam')).read()
    c.true('%s: BDF2 term in the balances' % case, 'of which BDF2 term' in log)
    # The wrong closing form: M^N - M^0 against the flows, without C^N
    terms = [float(x) for x in re.findall(r'of which BDF2 term\s+=\s+(\S+)', log)]
    if len(terms) == len(bal):
        print('  %s: without the BDF2 term the worst relative imbalance'
              ' would be %.3g' % (case, max(abs(b[1] - t)/max(abs(b[0] - t), 1e-300)
                                            for b, t in zip(bal, terms))))
# The crash settings (run: crash): the runs end at 3 h (they stopped at
# 7200 s by SIGFPE before the fix) with the balances closed; the rejected
# sub-steps and their reasons are printed (the diverging ones are the
# mechanism of the crash). Balances at the solver's default tolerances:
# measured worst relative imbalance 8.8e-10 and 3.9e-10 (2026-12-02),
# required below 3e-9 (the columns' 3e-10 at the tutorial's tolerances
# scaled by the measured ratio: the default WTol and TTol are looser).
for case in ('crash400', 'crash500'):
    logName = os.path.join(scratch, case, 'log.pendularFoam')
    log = open(logName).read()
    c.true('%s: reached t = 10800 s' % case,
           os.path.isfile(os.path.join(scratch, case, '10800', 'T')))
    bal = hc.read_energy_balances(logName)
    c.true('%s: balances reported (3 x 3)' % case, len(bal) >= 9)
    c.le('%s: worst relative imbalance (water, air, energy)' % case,
         max(abs(b[2]) for b in bal), 3e-9)
    reasons = re.findall(r'step rejected after \d+ iterations \(([^:(]*)', log)
    # The stall: sub-steps of maxIter Newton iterations (10 per run before
    # the water of the cells with a negative BDF2 history in the Kelvin
    # range kept backward Euler, pendularResidual::bdf2)
    nStall = reasons.count('nonlinear iterations not converged')
    c.true('%s: no sub-step rejected at maxIter (the stall; 10 before)' % case,
           nStall == 0, '%d' % nStall)
    cost = hc.read_solver_cost(logName)
    print('  %s: %d steps, %d Newton iterations, %d rejected: %s'
          % (case, cost['steps'], cost['iterations'], cost['rejected'],
             ', '.join('%s x%d' % (r.strip().rstrip(')'), reasons.count(r))
                       for r in sorted(set(reasons)))))
# The water that left the column is the water it lost: the BDF2 term of
# the water balance, C^N (O(dt): measured 0.5-0.7 % of the water out with
# the pure BDF2 of the crash settings and with the fix, 0.2 % on
# columnBDF2), against the water out. Backward Euler for the water of every
# cell with a negative history (also at the drying front) drops the BDF2
# term's pending part of the step that dried it: the column evaporated
# 2.7 times its water (measured: C^N 63 % of the water out, bench/
# pendularNewton's 500 cells, 12 h), hence 2 %.
for case in ('columnBDF2', 'crash400', 'crash500'):
    log = open(os.path.join(scratch, case, 'log.pendularFoam')).read()
    m = re.findall(r'Water balance at t = \S+ s \[kg\]:\n(?:.*\n)*?\s+of which BDF2 term\s+=\s+(\S+)\n'
                   r'\s+out \(all patches\)\s+=\s+(\S+)', log)
    c.true('%s: water balance with its BDF2 term' % case, len(m) > 0)
    if m:
        term, out = float(m[-1][0]), float(m[-1][1])
        c.le('%s: |BDF2 term| of the water balance / water out' % case,
             abs(term)/max(abs(out), 1e-300), 0.02)
c.done()
