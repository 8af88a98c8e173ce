"""A resumed run against the uninterrupted one (tests/hearthCaseInput:
ahcFoam, 2 ranks; tests/hearthCaseResumeCoupled: pendularFoam, 1 rank).

    python3 checkResume.py RESUMED REFERENCE TR

RESUMED: a case of hearthCase -run interrupted (SIGINT) after its time TR
was written, then hearthCase -resume; REFERENCE: the same dictionary run
whole. The solver is system/hearthCaseInfo's; the tolerances are its
(TOL_T, FIELDS, TOL_BALANCE below).

Why not equal. The step controller's state (the last accepted sub-step's
length, change of T, iterations and local-error limit) is written in
<time>/uniform/subStepController and read back (since 2026-12-05): the
resumed run's first step is the one the uninterrupted run took (before,
it was uniform/time's deltaT, the last step before the write, often cut
short to land on it, and the steps after it fell at other times until
the next write). Not written: ahcFoam's first iterates (its rates);
pendularFoam's time scheme and rates are (below).
- ahcFoam: the last steps' enthalpy rates, from which the first iterate
  of a step is extrapolated, are not written: the first step after TR
  starts from the state at TR, and the first steps converge to other
  iterates within the nonlinear tolerance (TTol 1e-2 K:
  the first two took one more iteration, the steps' max |dT| up to 3.5e-3
  K apart, the difference then diffusing away); the steps fall at the
  same times (the resumed log's 'Time = ' lines are the uninterrupted
  run's after TR). Measured, restarted at 1800 s of a 3 h run (30 min
  writes, 2 ranks): 9.7e-6 K at 3600 s, 1.8e-6 at 10800 s (liquidWater
  1.7e-8), summary balances 3.9e-9 relative; hearthCaseInput's run of
  12 h restarted at 3600 s (its writes every 30 min):
  1.9e-6 K at 5400 s, balances 3.9e-10, its 743 steps after 3600 s at
  the uninterrupted run's times. Before the controller's
  state was written (main's checkResume.py, the same case): 1.19e-3 K,
  6.5e-4 at 5400 s, liquidWater 2.2e-6, balances 3.5e-7 to 9.3e-7: the
  tolerances 2e-4 K (20 times the measured, a sixth of the old), 4e-7
  (liquidWater) and 1e-7 (balances) fail that old resume. Checked by
  hand: the same interrupt, uniform/subStepController removed from the
  restart time before -resume (read as a case written before it: the old
  behaviour), gave 1.191e-3 K, 6.45e-4, 2.2e-6, 3.5e-7 and 9.3e-7 again,
  the first step to 1836.478379 s instead of 1833.333333 s: 26 checks
  failed.
- pendularFoam (timeScheme BDF2, localErrorTol 1 K, the defaults): BDF2's
  level before TR (the unknowns and the stored air and energy at the
  start of the last accepted sub-step, T at the one before, the scheme's
  state: TR/*.bdf2Old*, TR/T.bdf2Older, TR/uniform/variableStepBdf2,
  since 2026-12-05, restartBdf2) is written and read back: the resumed
  run's first step is BDF2, its first iterate extrapolated at the last
  sub-step's rates, and it takes the uninterrupted run's steps
  (checkBdf2Restart.py). What differs is the round-off of the fields it
  starts from (writePrecision 12: T to 1e-9 K). Measured
  (tests/hearthCaseResumeCoupled, 500 C fire, restart at 120 s, writes
  every 2 min): T and TMax 1e-9 K at every write to 960 s, alphaL
  3.6e-13, the sensors (8 decimals) and the summary's figures equal,
  its stored heat 2.8e-10 relative; tolerances 1e-7 K (100 times: a
  sensor's last printed digit, 1e-8 K, may turn), alphaL 1e-11 (30
  times) and balances 1e-8 relative (35 times). Before the level was
  written the first step after TR was backward Euler and the steps after
  it others: T 7.6e-3 K at 240 s, 8e-4 K at 960 s, alphaL 6.1e-6, the
  sensors 5.5e-3 K, the balances 1.7e-4 relative (the BDF2 term C^N, O(dt),
  depends on the step sequence); tests/hearthCaseResumeCoupled's oldBuild
  (the level removed before -resume) checks that these tolerances fail it.
A resume from a wrong time (the fire's clock restarted, a time lost)
differs by kelvins.

1. Fields at every time written after TR (the same time names in both):
   FIELDS, within their tolerances.
2. The merged sensor history postProcessing/thermocouples/0/sensors.csv:
   its rows up to TR are the reference's, byte for byte (the same run up
   to there, on the same ranks); after TR, one row per step of the
   resumed solver (the 'Time = ' lines of log.<solver>, in order: no time
   missing, none twice), strictly increasing, to the end time; at the
   write times (both runs land on them) within TOL_T, between them
   within TOL_T plus the error of the linear interpolation of the
   reference at the resumed times, |T''| h^2/8 over the reference's
   interval h, T'' its second divided differences at both ends of the
   interval (0 K beyond that measured for ahcFoam and pendularFoam, whose
   steps now fall at the same times; before, 3e-4 K and 7.6e-3 K).
3. summary.csv (the balances added up over the two logs: the interrupted
   one kept as log.<solver>.TR): heat in, stored, water within
   TOL_BALANCE relative; peaks within TOL_T K and depths within TOL_T cm
   (as 1); the peak times within one maxDeltaT (60 s; 0 measured).
   Summed over one log only (the summary before -resume), heat in is that
   since TR: 3.15 instead of 5.11 MJ (ahcFoam, TR 1800 s).
   The water evaporated adds each part's own, from its start (ahcFoam:
   0.1171 kg to 1800 s, 0.1675 kg after; 0.2845 kg uninterrupted,
   2026-12-05); the summary before 2026-12-05 took the first write's
   water minus the last's and gave 0.1675 kg for the uninterrupted run:
   what evaporated by the first write was missing.
4. system/controlDict: only startFrom differs from the reference's
   (latestTime), the rest as hearthCase wrote it.
"""

import bisect
import csv
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                '..', '..', 'etc', 'python'))
import hearthTutorial as ht      # noqa: E402
import hearthCaseRestart as hr   # noqa: E402
from hearthcheck import Check    # noqa: E402

res, ref, tr = sys.argv[1:4]
c = Check('resume')
solver = hr.info(ref)['solver']
# the tolerances of the solver's case (docstring): K for T, TMax and the
# sensors; the fields compared and theirs
TOL_T = {'ahcFoam': 2e-4, 'pendularFoam': 1e-7}[solver]
FIELDS = {'ahcFoam': (('T', TOL_T), ('TMax', TOL_T), ('liquidWater', 4e-7)),
          'pendularFoam': (('T', TOL_T), ('TMax', TOL_T),
                           ('alphaL', 1e-11))}[solver]
# the balances of the summary, relative
TOL_BALANCE = {'ahcFoam': 1e-7, 'pendularFoam': 1e-8}[solver]

# 1. fields
times = [os.path.basename(d) for d in ht.time_dirs(ref)
         if float(os.path.basename(d)) > float(tr)]
c.true('reference: times written after %s s' % tr, len(times) >= 2,
       ' '.join(times))
for t in times:
    for f, tol in FIELDS:
        a = ht.read_internal_field(os.path.join(res, t, f))
        b = ht.read_internal_field(os.path.join(ref, t, f))
        c.true('%s/%s: %d cells' % (t, f, len(b)), len(a) == len(b))
        c.le('%s/%s: max |resumed - uninterrupted|' % (t, f),
             max(abs(x - y) for x, y in zip(a, b)), tol)


# 2. sensors
def rows(case):
    with open(os.path.join(case, 'postProcessing', 'thermocouples', '0',
                           'sensors.csv')) as fh:
        return fh.read().split('\n')[1:-1]


rRes, rRef = rows(res), rows(ref)
before = [r for r in rRes if float(r.split(',')[0]) <= float(tr)]
c.true('sensors: rows up to %s s = the uninterrupted run\'s (%d rows)'
       % (tr, len(before)), before == [r for r in rRef if float(r.split(',')[0])
                                       <= float(tr)])
with open(os.path.join(res, 'log.' + solver)) as fh:
    steps = [float(m) for m in re.findall(r'(?m)^Time = (\S+)$', fh.read())]
# the first step after TR sized from the controller's state read back
# (uniform/subStepController): it ends where the uninterrupted run's did
# (printed to timePrecision 10; with the stored deltaT instead, before the
# state was written: 121.869483 s against 121.6666667 s, pendularFoam in
# tests/hearthCaseResumeCoupled)
with open(os.path.join(ref, 'log.' + solver)) as fh:
    stepsRef = [float(m) for m in re.findall(r'(?m)^Time = (\S+)$',
                                              fh.read())
                if float(m) > float(tr)]
c.true('first step after %s s: to the uninterrupted run\'s %s s'
       % (tr, stepsRef[0] if stepsRef else '?'),
       steps and stepsRef and abs(steps[0] - stepsRef[0]) <= 1e-9*steps[0],
       '%s s' % (steps[0] if steps else '?'))
if solver == 'ahcFoam':
    # no time scheme history: every later step too (measured)
    c.true('steps after %s s: the uninterrupted run\'s times' % tr,
           len(steps) == len(stepsRef) and
           all(abs(a - b) <= 1e-9*b for a, b in zip(steps, stepsRef)),
           '%d and %d steps' % (len(steps), len(stepsRef)))
after = [[float(x) for x in r.split(',')] for r in rRes
         if float(r.split(',')[0]) > float(tr)]
tAfter = [r[0] for r in after]
c.true('sensors: after %s s one row per step of the resumed log.%s '
       '(%d)' % (tr, solver, len(steps)),
       len(tAfter) == len(steps) and
       all(abs(a - b) <= 1e-9*b for a, b in zip(tAfter, steps)),
       '%d rows' % len(tAfter))
allT = [float(r.split(',')[0]) for r in rRes]
c.true('sensors: times strictly increasing, to %g s' % float(times[-1]),
       all(b > a for a, b in zip(allT, allT[1:]))
       and abs(allT[-1] - float(times[-1])) < 1e-9*allT[-1])
ref2 = [[float(x) for x in r.split(',')] for r in rRef]
tRef = [r[0] for r in ref2]
for t in times:
    a = [r for r in after if abs(r[0] - float(t)) < 1e-9*float(t)]
    b = [r for r in ref2 if abs(r[0] - float(t)) < 1e-9*float(t)]
    if c.true('sensors: a row at %s s in both' % t, len(a) == len(b) == 1):
        c.le('sensors at %s s: max |resumed - uninterrupted| [K]' % t,
             max(abs(x - y) for x, y in zip(a[0][1:], b[0][1:])), TOL_T)
worst = 0.0
for r in after:
    t = r[0]
    i = bisect.bisect_left(tRef, t)         # tRef[i - 1] < t <= tRef[i]
    h = tRef[i] - tRef[i - 1]
    for j in range(1, len(r)):
        col = [q[j] for q in ref2]
        interp = ht.interpolate(tRef, col, t)
        # |T''| from the second divided differences at both ends
        d2 = max(abs(2*((col[k + 1] - col[k])/(tRef[k + 1] - tRef[k])
                        - (col[k] - col[k - 1])/(tRef[k] - tRef[k - 1]))
                     / (tRef[k + 1] - tRef[k - 1]))
                 for k in (i - 1, i) if 0 < k < len(col) - 1)
        worst = max(worst, abs(r[j] - interp) - d2*h*h/8)
c.le('sensors after %s s: |resumed - interpolated| - |T\'\'| h^2/8 [K]' % tr,
     worst, TOL_T)


# 3. summary
def figures(case):
    with open(os.path.join(case, 'summary.csv')) as fh:
        return dict((r['name'], float(r['value'])) for r in csv.DictReader(fh))


fRes, fRef = figures(res), figures(ref)
c.true('summary.csv: the same figures', sorted(fRes) == sorted(fRef))
for k in sorted(fRef):
    d = abs(fRes.get(k, float('nan')) - fRef[k])
    if k in ('heatIn', 'stored', 'water'):
        c.le('summary %s: relative difference' % k, d/abs(fRef[k]),
             TOL_BALANCE)
    elif k.startswith('peakTime'):
        c.le('summary %s [h]' % k, d, 60/3600)
    else:
        c.le('summary %s' % k, d, TOL_T)

# 4. controlDict
with open(os.path.join(res, 'system', 'controlDict')) as fh:
    a = fh.read().split('\n')
with open(os.path.join(ref, 'system', 'controlDict')) as fh:
    b = fh.read().split('\n')
diff = [(x, y) for x, y in zip(a, b) if x != y]
c.true('controlDict: only startFrom changed',
       len(a) == len(b) and len(diff) == 1
       and re.match(r'startFrom\s+latestTime;', diff[0][0]) is not None,
       str(diff)[:200])
c.done()
