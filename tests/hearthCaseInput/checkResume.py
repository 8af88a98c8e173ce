"""tests/hearthCaseInput: a resumed run against the uninterrupted one.

    python3 checkResume.py RESUMED REFERENCE TR

RESUMED: a case of hearthCase -run interrupted (SIGINT) after its time TR
was written, then hearthCase -resume; REFERENCE: the same dictionary run
whole. Both on 2 ranks (decomposed).

1. Fields T, TMax, liquidWater at every time written after TR (the same
   time names in both): within 5e-3 K (T, TMax) and 1e-5 (liquidWater, a
   volume fraction ~0.05). Why not equal: a restart changes the first
   iterate of its first step (ahcFoam's extrapolation from the last steps'
   enthalpy rates is not written), and the step controller's state (the
   last step's change of T and iterations) is not written either: the
   first step after TR is the stored deltaT, shortened to land on the
   write time (58.6 s), where the run went on with its full 60 s; the steps
   after TR fall at other times until the next write time, which both land
   on. The fields then differ by the change of backward Euler's error with
   the step sequence (steps <= maxDeltaT 60 s, up to 2.5 K per step in the
   hottest cells): measured, restarted at 1800 s (30 min writes), 1.19e-3
   K at 3600 s, 6.5e-4 at 5400 s, 1.7e-4 at 10800 s (liquidWater 2.2e-6);
   restarted at 3600 s (1 h writes) 6.7e-5 K; the hostile testing of
   2026-12-05 measured 2e-4 K on a restart. The test restarts at 1800 s or
   later (the earliest, the hottest changes: the largest difference
   measured); 5e-3 K is 4 times it. A resume from a wrong time (the fire's
   clock restarted, a time lost) differs by kelvins.
2. The merged sensor history postProcessing/thermocouples/0/sensors.csv:
   its rows up to TR are the reference's, byte for byte (the same run up
   to there, on the same 2 ranks); after TR, one row per step of the
   resumed solver (the 'Time = ' lines of log.ahcFoam, in order: no time
   missing, none twice), strictly increasing, to the end time; at the
   write times (both runs land on them) within 5e-3 K (as 1; 6.5e-4
   measured), between them within 5e-3 K plus the error of the linear
   interpolation of the reference at the resumed times, |T''| h^2/8 over
   the reference's interval h, T'' its second divided differences at both
   ends of the interval (3e-4 K beyond that measured).
3. summary.csv (the balances added up over the two logs: the interrupted
   one kept as log.ahcFoam.TR): heat in, stored, water within 1e-5
   relative (3.5e-7, 3.5e-7, 5.5e-7 measured: the difference of 1 over
   the heated soil); peaks within 5e-3 K and depths within 5e-3 cm (as
   1); the peak times within one maxDeltaT (60 s). Summed over one log
   only (the summary before -resume), heat in is that since TR: 3.15
   instead of 5.11 MJ (TR 1800 s). The water evaporated adds each part's
   own, from its start (0.1171 kg to 1800 s, 0.1675 kg after; 0.2845 kg
   uninterrupted, 2026-12-05); the summary before 2026-12-05 took the first
   write's water minus the last's and gave 0.1675 kg for the uninterrupted
   run: what evaporated by the first write was missing.
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
TOL_T = 5e-3

# 1. fields
times = [os.path.basename(d) for d in ht.time_dirs(ref)
         if float(os.path.basename(d)) > float(tr)]
c.true('reference: times written after %s s' % tr, len(times) >= 2,
       ' '.join(times))
for t in times:
    for f, tol in (('T', TOL_T), ('TMax', TOL_T), ('liquidWater', 1e-5)):
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
        c.le('summary %s: relative difference' % k, d/abs(fRef[k]), 1e-5)
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
