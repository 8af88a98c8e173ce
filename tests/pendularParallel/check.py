"""Serial and 2-rank parallel runs of the column, with the same fixed steps
(20 s), agree at 2 h: the decomposition changes only the order of
floating-point sums in the linear solvers and the iteration counts, so the two differ by the nonlinear tolerances of the case (TTol
1e-7 K, pTol 1e-4 Pa, WTol 1e-11 of the water): the test allows 100 times
them (1e-5 K, 1e-2 Pa, 1e-9 of the water content). The water and energy
balances of the parallel run close as the serial ones. Arguments: the
serial and the parallel case, and optionally the time compared (7200)."""
import os
import sys
import hearthcheck as hc

serial, parallel = sys.argv[1:3]
# optional: the time compared (default 7200 s)
t = sys.argv[3] if len(sys.argv) > 3 else '7200'
c = hc.Check('pendularParallel ' + os.path.basename(serial))
for t in (t,):
    for field, tol in (('T', 1e-5), ('p', 1e-2), ('W', 1e-9*1.3)):
        a = hc.read_internal_field(os.path.join(serial, t, field))
        b = hc.read_internal_field(os.path.join(parallel, t, field))
        c.true('%s: same number of cells' % field, len(a) == len(b) == 100)
        c.le('max |%s serial - parallel| at %s s' % (field, t),
             max(abs(x - y) for x, y in zip(a, b)), tol)
for case in (serial, parallel):
    bal = hc.read_energy_balances(os.path.join(case, 'log.pendularFoam'))
    c.le('worst relative imbalance, %s' % os.path.basename(case),
         max(abs(x[2]) for x in bal), 1e-8)
c.done()
