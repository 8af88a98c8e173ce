"""tests/hearthCaseInput: a resumed run against the uninterrupted one.

    python3 checkResume.py RESUMED REFERENCE TR

RESUMED: a case of hearthCase -run interrupted (SIGINT) after its time TR
was written, then hearthCase -resume; REFERENCE: the same dictionary run
whole. Both on 2 ranks (decomposed).

1. Fields T, TMax, liquidWater at every time written after TR (the same
   time names in both): within 1e-3 K (T, TMax) and 1e-6 (liquidWater, a
   volume fraction ~0.05). Why not equal: a restart changes the first
   iterate of its first step (ahcFoam's extrapolation from the last steps'
   enthalpy rates is not written), and its first step is the stored
   deltaT, shortened to land on the write time TR, where the run went on
   with its full step: the steps after TR fall at other times (e.g.
   3658.6 s for 3660 s) until the write times, which both land on. The
   fields then differ by the nonlinear tolerance of the steps and the
   change of backward Euler's error with the step sequence: measured
   6.7e-5 K at the write after the restart, 3.7e-6 K at 6 h (1 h writes),
   and the hostile testing of 2026-12-05 measured 2e-4 K on a restart; a
   resume from a wrong time (the fire's clock restarted, a time lost)
   differs by kelvins.
2. The merged sensor history postProcessing/thermocouples/0/sensors.csv:
   its rows up to TR are the reference's, byte for byte (the same run up
   to there, on the same 2 ranks); after TR, one row per step of the
   resumed solver (the 'Time = ' lines of log.ahcFoam, in order: no time
   missing, none twice), strictly increasing, to the end time; their
   values within 1e-3 K (as 1) plus the error of the linear interpolation
   of the reference at those times, bounded by its largest second
   difference around the point over 8 (|T''| h^2/8 of the interval's h).
3. summary.csv (the balances added up over the two logs: the interrupted
   one kept as log.ahcFoam.TR): heat in, stored, water within 1e-6
   relative (the restart's difference of 1 is below 1e-7 of them); peaks
   and depths within 1e-3 K and 1e-3 cm; the peak times within one
   maxDeltaT (60 s).
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
from hearthcheck import Check    # noqa: E402

res, ref, tr = sys.argv[1:4]
c = Check('resume')
TOL_T = 1e-3

# 1. fields
times = [os.path.basename(d) for d in ht.time_dirs(ref)
         if float(os.path.basename(d)) > float(tr)]
c.true('reference: times written after %s s' % tr, len(times) >= 2,
       ' '.join(times))
for t in times:
    for f, tol in (('T', TOL_T), ('TMax', TOL_T), ('liquidWater', 1e-6)):
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
with open(os.path.join(res, 'log.ahcFoam')) as fh:
    steps = [float(m) for m in re.findall(r'(?m)^Time = (\S+)$', fh.read())]
after = [[float(x) for x in r.split(',')] for r in rRes
         if float(r.split(',')[0]) > float(tr)]
tAfter = [r[0] for r in after]
c.true('sensors: after %s s one row per step of the resumed log.ahcFoam '
       '(%d)' % (tr, len(steps)),
       len(tAfter) == len(steps) and
       all(abs(a - b) <= 1e-9*b for a, b in zip(tAfter, steps)),
       '%d rows' % len(tAfter))
allT = [float(r.split(',')[0]) for r in rRes]
c.true('sensors: times strictly increasing, to %g s' % float(times[-1]),
       all(b > a for a, b in zip(allT, allT[1:]))
       and abs(allT[-1] - float(times[-1])) < 1e-9*allT[-1])
ref2 = [[float(x) for x in r.split(',')] for r in rRef]
tRef = [r[0] for r in ref2]
worst = 0.0
for r in after:
    t = r[0]
    i = bisect.bisect_left(tRef, t)         # tRef[i - 1] < t <= tRef[i]
    for j in range(1, len(r)):
        col = [q[j] for q in ref2]
        interp = ht.interpolate(tRef, col, t)
        d2 = max(abs(col[k - 1] - 2*col[k] + col[k + 1])
                 for k in (i - 1, i) if 0 < k < len(col) - 1)
        worst = max(worst, abs(r[j] - interp) - d2/8)
c.le('sensors after %s s: |resumed - interpolated| - |d2T|/8 [K]' % tr,
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
        c.le('summary %s: relative difference' % k, d/abs(fRef[k]), 1e-6)
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
