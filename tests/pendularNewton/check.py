"""pendularFoam, engine newton: balances closed to 1e-10 (to the Newton
tolerances, below), on average at most 4 Newton iterations per step on the report's column
(the issue's target; measured 2.4), Newton's quadratic convergence near
the solution on that column (below), and the serial and 2-rank runs of
the column of tests/pendularParallel equal within 100 times its
nonlinear tolerances (TTol 1e-7 K, pTol 1e-4 Pa, WTol 1e-11 of the water:
1e-5 K, 1e-2 Pa, 1.3e-9 kg/m3), as the segregated engine's, at 1 h (the
drying front past the processor boundary).

Quadratic convergence: in a step with three successive residuals r0 >
r1 > r2 above the tolerances (the largest scaled residual of the verbose
'Newton k:' lines, each iterate a plain Newton update: no cell chopped or
projected), the order ln(r2/r1)/ln(r1/r0) is 2 for Newton with an exact
Jacobian and 1 for a linearly converging iteration (a lagged or wrong
Jacobian, a fixed point). Measured (2026-12-02, 100 cells, 12 h): 254
such steps of 1688, median order 1.97, tenth percentile 1.59; required:
at least 50 steps and median at least 1.8 (the forward-difference
Jacobian's 1e-8 relative error and the residuals' round-off bend the
last ratios).

The balances close to the Newton tolerances, not to round-off: the air's
imbalance is the gas residuals Newton leaves at acceptance (within pTol),
summed over the cells and sub-steps, and the 1e-10 at 1 h holds with a
margin of about 3 only. Measured 2026-12-03 (alphaLPolish), the 1 h runs
written every 20 s: relative to its flows (the solver's 'relative') the
air imbalance is 1.37e-9 at 20 s in serial and on 2 ranks, before and
after alpha_l(W) was made continuous (flows of 4.5e-10 kg against 3.05e-6
kg held), 2.2e-9 at worst; at 1 h on 2 ranks 3.9e-11 before, 3.2e-11 now,
and 1.09e-10 with an intermediate form of the same change (alpha_l's last
Newton step taken in ln(alpha_l)), which failed this check: 1.37e-16 kg,
5.6e-11 of the air held, a mean gas pressure error of 5.7e-6 Pa (0.057
pTol). The serial and 2-rank fields agreed in every written digit; not a
rank-dependent guess of alphaL (the residual's guess is the sub-step's
start on every rank, swapped across processor faces; pendularState's is
its last value; alphaL now returns the root to round-off whatever the
guess); with pTol 1e-6 instead of 1e-4 that run's imbalance at 1 h fell
to 1.28e-17 kg (every sub-step then accepted at the gas residual's
round-off floor)."""
import math
import os
import re
import statistics
import sys
import hearthcheck as hc


def newton_orders(log):
    """Orders of convergence of the last three residuals above tolerance
    of each step of a verbose Newton log."""
    pat = re.compile(r'Newton (\d+): residual/tol \(water (\S+), gas (\S+), '
                     r'energy (\S+)\).*chopped (\d+), projected (\d+)')
    steps, cur = [], []
    for line in open(log):
        m = pat.search(line)
        if not m:
            continue
        if int(m.group(1)) == 0 and cur:
            steps.append(cur)
            cur = []
        cur.append((max(float(m.group(i)) for i in (2, 3, 4)),
                    int(m.group(5)) + int(m.group(6))))
    if cur:
        steps.append(cur)
    orders = []
    for s in steps:
        for i in reversed(range(2, len(s))):
            (r0, _), (r1, m1), (r2, m2) = s[i - 2:i + 1]
            if r2 > 1 and m1 == 0 and m2 == 0 and r0 > r1 > r2:
                orders.append(math.log(r2/r1)/math.log(r1/r0))
                break
    return len(steps), orders

column, serial, parallel = sys.argv[1:4]
c = hc.Check('pendularNewton')
# The drying front has crossed the processor boundary (5 cm, between the
# ranks' 50 cells, numbered from the bottom): at 1 h every cell of the top
# rank is below alpha_0/2 (measured: the front at about 6 cm)
alpha = hc.read_internal_field(os.path.join(serial, '3600', 'alphaL'))
c.true('serial: at 1 h the top 50 cells dry (alpha_l < 0.0025), the '
       'front past the processor boundary', len(alpha) == 100
       and max(alpha[50:]) < 0.0025 and max(alpha[:50]) > 0.0025,
       'max alpha_l above / below 5 cm: %.3g / %.3g'
       % (max(alpha[50:]), max(alpha[:50])))
for t in ('3600',):
    for field, tol in (('T', 1e-5), ('p', 1e-2), ('W', 1e-9*1.3)):
        a = hc.read_internal_field(os.path.join(serial, t, field))
        b = hc.read_internal_field(os.path.join(parallel, t, field))
        c.true('%s: same number of cells' % field, len(a) == len(b) == 100)
        c.le('max |%s serial - parallel| at %s s' % (field, t),
             max(abs(x - y) for x, y in zip(a, b)), tol)
for case in (column, serial, parallel):
    log = os.path.join(case, 'log.pendularFoam')
    c.true('%s: engine newton' % os.path.basename(case),
           'Nonlinear engine: newton' in open(log).read())
    bal = hc.read_energy_balances(log)
    c.true('%s: balances reported' % os.path.basename(case),
           len(bal) >= (6 if case == column else 3))
    c.le('worst relative imbalance (water, air, energy), %s'
         % os.path.basename(case), max(abs(x[2]) for x in bal), 1e-10)
cost = hc.read_solver_cost(os.path.join(column, 'log.pendularFoam'))
c.le('column: Newton iterations per step', cost['iterations']/max(cost['steps'], 1), 4)
nSteps, orders = newton_orders(os.path.join(column, 'log.pendularFoam'))
c.true('column: steps with three residuals above tolerance >= 50',
       len(orders) >= 50, '%d of %d steps' % (len(orders), nSteps))
if orders:
    c.true('column: median order of Newton convergence >= 1.8',
           statistics.median(orders) >= 1.8,
           'median %.3f, tenth percentile %.3f (1 = linear)'
           % (statistics.median(orders), sorted(orders)[len(orders)//10]))
c.done()
