"""tests/pendularNonOrth: a Newton run of pendularFoam on the sheared mesh
(serial) and its 2-rank copy: the default engine is newton there (the log
says so, with the mesh's non-orthogonality, 33.69 degrees), the water, air
and energy balances close within 1e-10 (relative, hearthcheck.
worst_relative_imbalance; 1e-13 measured), and the two runs agree at 20 s
(below). Arguments: the serial case, the parallel case, and 'Liquid' for
the run with liquidFlow (then also: liquid water enters through the
bottom's fixed saturation, impermeable without liquidFlow)."""
import os
import re
import sys
import hearthcheck as hc

serial, parallel = sys.argv[1:3]
liquid = len(sys.argv) > 3 and sys.argv[3] == 'Liquid'
c = hc.Check('pendularNonOrth ' + os.path.basename(serial))
for case in (serial, parallel):
    log = os.path.join(case, 'log.pendularFoam')
    text = open(log).read()
    c.true('%s: engine newton by default' % os.path.basename(case),
           'Nonlinear engine: newton' in text)
    m = re.search(r'Non-orthogonal mesh \(up to ([0-9.eE+-]+) degrees\)',
                  text)
    c.true('%s: non-orthogonal mesh reported' % os.path.basename(case),
           m is not None)
    if m:
        c.le('%s: |non-orthogonality - 33.69 deg|' % os.path.basename(case),
             abs(float(m.group(1)) - 33.690067525979842), 1e-9)
    c.le('%s: worst relative imbalance' % os.path.basename(case),
         hc.worst_relative_imbalance(log), 1e-10)
if liquid:
    # the last water balance's flow out through the bottom: < 0 (in)
    for case in (serial, parallel):
        text = open(os.path.join(case, 'log.pendularFoam')).read()
        flows = re.findall(r'Water balance at t = [^\n]*\n'
                           r'(?:    [^\n]*\n)*?'
                           r'    out through bottom = ([0-9.eE+-]+)', text)
        c.true('%s: liquid in through the bottom' % os.path.basename(case),
               bool(flows) and float(flows[-1]) < -1e-7,
               flows[-1] if flows else 'no water balance')
# 2 ranks = serial: the decomposition changes the order of the sums of the
# linear solver (LU, MUMPS) and of the processor faces' fluxes; each run
# stops within the nonlinear tolerances of the same solution: TTol 1e-9 K,
# pTol 1e-5 Pa, WTol WScale 5.2e-12 kg/m3 allowed (measured 6e-14 K,
# 1.5e-11 Pa, 8.7e-15 kg/m3; with liquid flow 1.4e-12 K, 1.5e-11 Pa,
# 8.1e-13 kg/m3)
for field, tol in (('T', 1e-9), ('p', 1e-5), ('W', 5.2e-12)):
    a = hc.read_internal_field(os.path.join(serial, '20', field))
    b = hc.read_internal_field(os.path.join(parallel, '20', field))
    c.true('%s: same number of cells' % field, len(a) == len(b) == 24)
    c.le('max |%s serial - parallel| at 20 s' % field,
         max(abs(x - y) for x, y in zip(a, b)), tol)
c.done()
