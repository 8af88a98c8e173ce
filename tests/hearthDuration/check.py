"""hearthDuration recovers the duration d0 = 1.5 h of the reference run.

The threshold is TMax at 4.1 cm of the reference run (the case run as it
is, with its hand-written fire file), so f(d0) = 0 exactly if hearthDuration
builds the same fire history (from the cooling table of its dictionary)
and runs the case the same way (the reference controlDict already has the
end as its only write time). Checks:
- the answer within the tolerance (1 min) of d0, and d0 inside the printed
  bracket [low, high] (f(low) < 0 <= f(high); f increases with d);
- the bracket narrower than the tolerance;
- the log's answer and bracket agree with result.csv, one log line per run;
- the peak of T at 4.1 cm comes after extinction (the reason for whole
  runs: heat keeps moving down) and equals TMax there;
- the case was not modified (its 0, constant, system files; no time
  directories), and the runs had no function objects;
- the same duration on 2 ranks (decomposePar, mpirun, reconstructPar)
  gives the reference TMax to 1e-6 K (PCG tolerance 1e-12);
- at most 12 runs of at most 5 s each;
- with a ramp (20 -> 700 C over 0.1667 h) and exponential cooling (Tair
  20 C, tau 0.5 h), the fire history file of a 1 h fire: the ramp and
  plateau points exact, every cooling point on Tair + (700 - 20)
  exp(-t/tau), and the linear interpolation between them within 0.05 K of
  the exponential (bound (tau/50)^2/8 |T''| = 680/20000 = 0.034 K)."""
import csv
import math
import os
import re
import sys
import hearthcheck as hc

c = hc.Check('hearthDuration')
threshold = float(sys.argv[1])
d0, tol = 1.5, 1.0/60
out = 'search/postProcessing/hearthDuration'

with open(out + '/result.csv') as f:
    res = next(csv.DictReader(f))
answer, low, high = (float(res[k]) for k in ('duration_h', 'lower_h', 'upper_h'))
with open(out + '/runs.csv') as f:
    runs = list(csv.DictReader(f))

c.le('|answer - d0| [min] (answer %.5f h)' % answer, 60*abs(answer - d0),
     60*tol)
c.true('d0 = 1.5 h inside the bracket [%.5f, %.5f] h' % (low, high),
       low < d0 <= high)
c.le('bracket width [min]', 60*(high - low), 60*tol)
f = {round(float(r['duration_h']), 6): float(r['f_K']) for r in runs}
fl, fh = f.get(round(low, 6), 1.0), f.get(round(high, 6), -1.0)
c.true('f(low) < 0 <= f(high) in runs.csv', fl < 0 <= fh,
       '%.4f K, %.4f K' % (fl, fh))
c.true('f increases with the duration over the %d runs' % len(runs),
       all(f[a] <= f[b] for a in f for b in f if a < b))

with open('search/log.hearthDuration') as fh_:
    log = fh_.read()
m = re.search(r'Minimal fire duration: (\S+) h .*\n\s+bracketed by '
              r'\[(\S+), (\S+)\] h', log)
c.true('log prints the answer and its bracket as in result.csv',
       m is not None and abs(float(m.group(1)) - answer) < 1e-4
       and abs(float(m.group(2)) - low) < 1e-4
       and abs(float(m.group(3)) - high) < 1e-4,
       ' '.join(m.group(0).split()) if m else 'not found')
c.true('log has one line per run',
       len(re.findall(r'^run +\d+: ', log, re.M)) == len(runs))
c.le('number of runs', len(runs), 12)
# a hang guard, not a speed test (0.3-0.9 s a run measured, quiet to load 8)
c.le('largest wall time of a run [s]',
     max(float(r['wallTime_s']) for r in runs), 60)
c.true('no point with TMax still rising at the end', 'still rising' not in log)

# The heat keeps moving down after extinction
locs, times, cols = hc.read_probes('reference/postProcessing/probes/0/T')
T = cols[0]
imax = max(range(len(T)), key=lambda i: T[i])
c.true('reference: peak of T at 4.1 cm after extinction (1.5 h)',
       times[imax] > 5400, '%.2f C at %.2f h' % (T[imax] - 273.15,
                                                 times[imax]/3600))
c.le('reference: |max T - TMax| at 4.1 cm [K]',
     abs(T[imax] - 273.15 - threshold), 1e-6)

c.true('case unchanged by hearthDuration (0, constant, system; no times)',
       os.path.exists('search/unchanged'))
c.true('runs without function objects (no scratch postProcessing)',
       not os.path.exists(out + '/scratchCase/postProcessing'))

with open('parallel/postProcessing/hearthDuration/runs.csv') as f:
    par = next(csv.DictReader(f))
c.le('2 ranks, 1.5 h: |TMax - reference| at 4.1 cm [K]',
     abs(float(par['TMax_d4.1cm_C']) - threshold), 1e-6)

# Ramp + exponential cooling: the file written for a 1 h fire
with open('exponential/postProcessing/hearthDuration/scratchCase/'
          'constant/fireHistory') as f_:
    txt = re.sub(r'//.*', '', f_.read())
number = r'([-+.\deE]+)'
pts = [(float(a), float(b))
       for a, b in re.findall(r'\(\s*' + number + r'\s+' + number + r'\s*\)', txt)]
ramp, d, tau, Tf, Ta = 0.1667*3600, 3600.0, 1800.0, 973.15, 293.15
c.true('fire history: (0, 20 C), (ramp, 700 C), (1 h, 700 C) first',
       len(pts) > 3 and pts[0] == (0.0, Ta) and abs(pts[1][0] - ramp) < 1e-6
       and pts[1][1] == Tf and pts[2] == (d, Tf), str(pts[:3]))
exact = lambda t: Ta + (Tf - Ta)*math.exp(-(t - d)/tau)
c.le('fire history: cooling points against the formula [K]',
     max(abs(T - exact(t)) for t, T in pts[3:]), 1e-6)
c.le('fire history: linear interpolation at midpoints [K]',
     max(abs(0.5*(a[1] + b[1]) - exact(0.5*(a[0] + b[0])))
         for a, b in zip(pts[2:], pts[3:])), 0.05)
c.true('fire history: followed 6 h after extinction',
       abs(pts[-1][0] - (d + 6*3600)) < 1e-6, '%g s' % pts[-1][0])

# 5. The same law in the fireTemperature boundary condition: its patch
# temperature at each step against hearthDuration's history of 4, linear
# between the points (what uniformFixedValue tableFile does). Both come
# from Foam::fireHistory::table; the file holds 12 significant digits
# (5e-10 K at 1000 K, times 5e-9 s): 1e-8 K allowed. A law read
# differently (tau in s, ramp missing, cooling from Tair) is off by K.
import glob
law = glob.glob('law/postProcessing/firePatch/0/surfaceFieldValue.dat')
rows = [l.split() for l in open(law[0]) if l.strip() and l[0] != '#'] \
    if law else []
def interp(t):
    if t <= pts[0][0]:
        return pts[0][1]
    for a, b in zip(pts, pts[1:]):
        if t <= b[0]:
            return a[1] + (b[1] - a[1])*(t - a[0])/(b[0] - a[0])
    return pts[-1][1]
diffs = [abs(float(r[1]) - interp(float(r[0]))) for r in rows]
c.true('fire law in the BC: steps to 3 h (ramp, plateau, cooling)',
       len(rows) > 20 and float(rows[-1][0]) >= 10800 - 60,  # maxDeltaT 60
       '%d steps' % len(rows))
c.le('fire law in the BC vs hearthDuration history: max |dT| [K]',
     max(diffs) if diffs else 1e9, 1e-8)
c.done()
