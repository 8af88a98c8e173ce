"""tests/hearthCaseResumeCoupled: pendularFoam's BDF2 across a restart.

    python3 checkBdf2Restart.py RESUMED REFERENCE TR

What a restart does to BDF2 (timeScheme BDF2, pendularFoam's default):
the history of the scheme (the unknowns and the stored water, air and
energy at t_{n-1}, the last steps' lengths) is not in the time folder, so
the restarted run builds its variableStepBdf2 afresh: its first step from
TR is backward Euler (order 1, as the first step of any run), the local
error estimate of T starts again at its third step, and the BDF2 term
C^N of its balances starts at 0 at TR (pendularFoam prints this at its
start). Each part's balances then close on their own, from the part's
start, and their sum is the whole run's (hearthCaseSummary,
hearthCaseRestart.runBalances). Checked:

1. pendularFoam's log of the resumed part says that its first step is by
   backward Euler from TR; the uninterrupted run's does not.
2. Each part's water, air and energy balances close at every write:
   |imbalance| <= 1e-9 of the largest term plus 1e-11 of the amount in
   the domain (the round-off of the stored totals: the solver's own check,
   balanceMonitor, is 1e-6 with a floor of 1e-12 of the amount held).
   Measured: water and energy below 5.3e-11 of their largest term; the
   air, whose flows are small, 5.5e-9 of them at 120 s, 3.5e-12 of the
   air in the domain.
3. The resumed part starts from the interrupted part's state at TR: its
   start amount, M^0 = (in the domain) - (stored change) + (BDF2 term) at
   each of its writes, equals the interrupted log's 'in the domain' at TR
   within 1e-9 relative (the fields are written with 12 digits). A part
   that carried the interrupted run's BDF2 term C (energy 42 J of 4.9e6 J
   here, 8.6e-6) or started from the initial state (the stored change to
   TR, 3146 J: 6.5e-4) fails.
Printed, not checked: the BDF2 terms C^N summed over the parts and the
uninterrupted run's (C is O(dt), the scheme's, and depends on the step
sequence, which the restart changes: it is what separates the summed
heat in from the uninterrupted run's, checkResume.py).
"""

import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                '..', '..', 'etc', 'python'))
import hearthTutorial as ht      # noqa: E402
import hearthCaseRestart as hr   # noqa: E402
from hearthcheck import Check    # noqa: E402

res, ref, tr = sys.argv[1:4]
c = Check('bdf2Restart')
WHAT = ('water', 'air', 'energy')
LINE = r'BDF2: restarted at t = (\S+) s: its first step by backward Euler'

# 1. the log line of the restart
with open(os.path.join(res, 'log.pendularFoam')) as fh:
    said = re.findall(LINE, fh.read())
with open(os.path.join(ref, 'log.pendularFoam')) as fh:
    refSaid = re.findall(LINE, fh.read())
c.true('resumed log: first step from %s s by backward Euler' % tr,
       len(said) == 1 and hr.same(float(said[0]), float(tr)), str(said))
c.true('uninterrupted log: no such line', not refSaid, str(refSaid))

# 2. each part's balances
logs = hr.segmentLogs(res, 'pendularFoam')
c.true('two parts: log.pendularFoam.%s and log.pendularFoam' % tr,
       len(logs) == 2 and hr.same(float(logs[0][1]), float(tr)),
       str([os.path.basename(p) for p, _ in logs]))
blocks = [ht.pendular_balances(p) for p, _ in logs]
for (path, _), bs in zip(logs, blocks):
    for w in WHAT:
        # |imbalance| over its allowance: 1e-9 of the largest term (the
        # imbalance over the relative the solver prints) plus 1e-11 of the
        # amount in the domain
        worst = max(abs(b[w]['imbalance'])
                    / (1e-9*abs(b[w]['imbalance']/b[w]['relative'])
                       + 1e-11*abs(b[w]['inDomain']))
                    if b[w]['relative'] else 0 for b in bs)
        c.le('%s: %s balance at %d writes, |imbalance| / allowance'
             % (os.path.basename(path), w, len(bs)), worst, 1)

# 3. the resumed part starts from the state at TR
atTr = [b for b in blocks[0] if hr.same(b['time'], float(tr))]
if c.true('interrupted log: balances at %s s' % tr, len(atTr) == 1):
    for w in WHAT:
        m0 = atTr[0][w]['inDomain']
        d = max(abs(b[w]['inDomain'] - b[w]['stored'] + b[w]['bdf2'] - m0)
                for b in blocks[1])
        c.le('%s: resumed start amount - amount at %s s, relative'
             % (w, tr), d/abs(m0), 1e-9)

# the BDF2 terms (printed): each part's at its end (as the summary adds
# them up, hearthCaseRestart.runBalances)
parts = atTr[:1] + blocks[1][-1:]
whole = ht.pendular_balances(os.path.join(ref, 'log.pendularFoam'))[-1]
for w in WHAT:
    print('  BDF2 term C^N of the %s balance: parts %s, sum %.6g; '
          'uninterrupted %.6g' % (w, ', '.join('%.6g' % b[w]['bdf2']
                                               for b in parts),
                                  sum(b[w]['bdf2'] for b in parts),
                                  whole[w]['bdf2']))
c.done()
