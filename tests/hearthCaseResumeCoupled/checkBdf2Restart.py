"""tests/hearthCaseResumeCoupled: pendularFoam's BDF2 across a restart.

    python3 checkBdf2Restart.py RESUMED REFERENCE TR

What a restart does to BDF2 (timeScheme BDF2, pendularFoam's default):
the level before TR (the unknowns T, p_g, W and the stored air and energy
per cell at the start of the last accepted sub-step, T at the one before:
TR/*.bdf2Old, TR/T.bdf2Older) and the scheme's state (the last two
sub-steps' lengths, the balances' last changes: TR/uniform/
variableStepBdf2) are written with the fields and read back
(pendularBdf2Levels, variableStepBdf2): the resumed run's first step is
BDF2 with the uninterrupted run's coefficients, first iterate and local
error estimate, so that it takes the uninterrupted run's steps. The BDF2
term C^N of the balances starts at 0 in each part (each part's balances
close on their own, from the part's start), and the parts' C^N sum to the
uninterrupted run's (hearthCaseSummary, hearthCaseRestart.runBalances).
Before 2026-12-05 (restartBdf2) the level was not written: the first step
after TR was backward Euler, the steps after it others, T 7.6e-3 K from
the uninterrupted run (checkResume.py). Checked:

1. pendularFoam's log of the resumed part says that it restarted at TR
   from the levels before it (2 levels) and that its first step is BDF2;
   the uninterrupted run's log has no restart line.
2. The resumed part's steps are the uninterrupted run's after TR: the
   same number, each ending at the same time (the log's 'Time = ', to the
   time names' round-off), with the same sub-steps and rejections, the
   Newton iterations within one (a step whose last correction lands at
   the tolerance may take one more or one fewer: the fields it starts
   from are written with 12 digits, T to 1e-9 K), and max |dT| within
   1e-6 K. Measured: 142 steps at the same times, sub-steps and
   rejections identical, iterations apart at 2 steps by one (406 against
   408 in all), max |dT| 1.9e-10 K apart. Restarted by backward
   Euler (the levels removed, as a time written by an older build) the
   steps part from the second on (the first, sized from
   uniform/subStepController, ends at the same time).
3. Each part's water, air and energy balances close at every write:
   |imbalance| <= 1e-9 of the largest term plus 1e-11 of the amount in
   the domain (the round-off of the stored totals: the solver's own check,
   balanceMonitor, is 1e-6 with a floor of 1e-12 of the amount held).
   Measured: water and energy below 1.8e-2 of that allowance, the air
   0.33 at 120 s.
4. The resumed part starts from the interrupted part's state at TR: its
   start amount, M^0 = (in the domain) - (stored change) + (BDF2 term) at
   each of its writes, equals the interrupted log's 'in the domain' at TR
   within 1e-9 relative (measured 1.7e-12 to 4.7e-12). A part that carried
   the interrupted run's BDF2 term C (energy 42 J of 4.9e6 J here, 8.6e-6)
   or started from the initial state (the stored change to TR, 3146 J:
   6.5e-4) fails.
5. The parts' BDF2 terms C^N (the interrupted part's at TR, the resumed
   part's at its end) sum to the uninterrupted run's within 1e-11 of the
   amount in the domain (C^N sums c_n over the steps, each from the
   stored totals' changes: the same steps give the same sum, to the
   round-off of totals of 12-digit fields). Measured: energy 4.9e-9 J
   apart of 4.9e6 J (1e-15), water and air 1.5e-16 kg. With the first
   step by backward Euler and other steps after it (the run's oldBuild):
   1.8e-7 (energy, 0.88 J), 2.5e-7 (water), 4e-6 (air) of the amounts.
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
LINE = (r'BDF2: restarted at t = (\S+) s from the levels before it '
        r'\((\d+), .*\): its first step by (BDF2|backward Euler)')
STEP = (r'(?m)^pendularFoam: deltaT = \S+, iterations = (\d+), sub-steps = '
        r'(\d+), rejected = (\d+), max \|dT\| = (\S+?),')


def read(path):
    with open(path) as fh:
        return fh.read()


# 1. the log line of the restart
logRes = read(os.path.join(res, 'log.pendularFoam'))
logRef = read(os.path.join(ref, 'log.pendularFoam'))
said = re.findall(LINE, logRes)
c.true('resumed log: restarted at %s s from 2 levels, first step BDF2' % tr,
       len(said) == 1 and hr.same(float(said[0][0]), float(tr))
       and said[0][1:] == ('2', 'BDF2'), str(said))
c.true('uninterrupted log: no restart line',
       'BDF2: restarted at' not in logRef)


# 2. the steps after TR
def steps(log, after):
    times = [float(t) for t in re.findall(r'(?m)^Time = (\S+)$', log)]
    lines = re.findall(STEP, log)
    c.true('a step line per step (%d)' % len(times),
           len(lines) == len(times))
    return [(t, s) for t, s in zip(times, lines) if t > after]


sRes, sRef = steps(logRes, float(tr)), steps(logRef, float(tr))
if c.true('steps after %s s: %d resumed, %d uninterrupted'
          % (tr, len(sRes), len(sRef)), len(sRes) == len(sRef) > 0):
    apart = [i for i, (a, b) in enumerate(zip(sRes, sRef))
             if not hr.same(a[0], b[0]) or a[1][1:3] != b[1][1:3]
             or abs(int(a[1][0]) - int(b[1][0])) > 1]
    c.true('the same times, sub-steps, rejections; iterations within 1',
           not apart, 'first apart: step %d after %s s: %s against %s'
           % (apart[0] + 1, tr, sRes[apart[0]], sRef[apart[0]])
           if apart else '')
    print('  Newton iterations after %s s: resumed %d, uninterrupted %d'
          % (tr, sum(int(a[1][0]) for a in sRes),
             sum(int(b[1][0]) for b in sRef)))
    c.le('max |dT| of the steps: largest difference [K]',
         max(abs(float(a[1][3]) - float(b[1][3]))
             for a, b in zip(sRes, sRef)), 1e-6)

# 3. each part's balances
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

# 4. the resumed part starts from the state at TR; 5. the parts' BDF2
# terms sum to the uninterrupted run's
atTr = [b for b in blocks[0] if hr.same(b['time'], float(tr))]
whole = ht.pendular_balances(os.path.join(ref, 'log.pendularFoam'))[-1]
if c.true('interrupted log: balances at %s s' % tr, len(atTr) == 1):
    for w in WHAT:
        m0 = atTr[0][w]['inDomain']
        d = max(abs(b[w]['inDomain'] - b[w]['stored'] + b[w]['bdf2'] - m0)
                for b in blocks[1])
        c.le('%s: resumed start amount - amount at %s s, relative'
             % (w, tr), d/abs(m0), 1e-9)
    for w in WHAT:
        parts = (atTr[0][w]['bdf2'], blocks[1][-1][w]['bdf2'])
        print('  BDF2 term C^N of the %s balance: parts %.12g, %.12g, '
              'uninterrupted %.12g' % ((w,) + parts + (whole[w]['bdf2'],)))
        c.le('%s: parts\' C^N sum - uninterrupted C^N, of the amount'
             % w, abs(sum(parts) - whole[w]['bdf2'])
             / abs(whole[w]['inDomain']), 1e-11)
c.done()
