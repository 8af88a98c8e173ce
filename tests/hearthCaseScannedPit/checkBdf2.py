"""tests/hearthCaseScannedPit, the scannedPit pendular case with
timeScheme BDF2 (localErrorTol 1): BDF2's order reduction
(variableStepBdf2) retook the sub-steps whose BDF2 solve failed by
backward Euler (at least one 'step retried' line: the case exercises
it; measured 2026-12-04: 9 in 37 steps, 221 Newton iterations, against
998 and 11 rejected sub-steps before it), no sub-step was rejected for
unconverged nonlinear iterations, and the water, air and energy
balances, with the BDF2 term, close to 1e-10 relative
(hearthcheck.worst_relative_imbalance; measured 1e-14). The cost (iterations, rejections) is costBudget's."""
import re
import sys

import hearthcheck as hc

log = sys.argv[1]
text = open(log).read()
ok = True


def check(cond, what):
    global ok
    print(('ok   ' if cond else 'FAIL ') + what)
    ok = ok and cond


retried = len(re.findall(r'step retried after \d+ iterations .*BDF2 order'
                         r' reduction', text))
maxIter = len(re.findall(r'step rejected after \d+ iterations \(nonlinear'
                         r' iterations not converged\)', text))
check('\nEnd\n' in text, 'pendularFoam ended')
check(retried >= 1, '%d sub-step(s) retaken by backward Euler >= 1' % retried)
check(maxIter == 0, '%d sub-step(s) rejected at maxIter = 0' % maxIter)
worst = hc.worst_relative_imbalance(log)
check(worst < 1e-10, 'worst relative imbalance %.2g < 1e-10' % worst)
print('BDF2: %d order reductions, %d rejections at maxIter, balances %.1g'
      % (retried, maxIter, worst))
sys.exit(0 if ok else 1)
