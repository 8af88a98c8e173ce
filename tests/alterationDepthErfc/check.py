"""hearthAlteration on a 1-D dry clay column under a wall at 700 C.

For a constant wall temperature T(z, t) increases in time at every depth,
so TMax(z) = T(z, t) = T0 + (Tw - T0) erfc(z/(2 sqrt(alpha t))), and the
depth where TMax reaches a threshold is z* = 2 sqrt(alpha t)
erfcinv((thr - T0)/(Tw - T0)).

Tolerance on the depth, per threshold and time: the crossing is
interpolated linearly between samples of the cell-point interpolant, which
is linear between the cell centres (h = 1 mm apart) on this column: error
<= h^2/8 |T''|/|T'| (1 to 3 um here), plus the solver's temperature error
(tests/dryConductionErfc: 0.12 K at most after 1 h, allowed 0.2 K) turned
into a depth by the slope: 0.2 K/|T'| (30 to 70 um). Measured: about
0.01 mm (a hundredth of a cell).

Altered volume: whole cells of cross-section A = 1e-6 m2 are counted, those
whose centre has TMax >= thr, so V/A is the depth rounded to a cell face:
|V/A - depth| <= h/2.

Parallel (2 ranks, the processor boundary at z = -0.15 m across the lines):
every number of every CSV file equal to the serial one to 1e-9 relative.

Wedge (5 degrees, cylinder R = 0.5 m, H = 0.2 m, TMax = 500 K within
r < 0.2 m and 0.1 m of the surface, 300 K elsewhere): full-revolution
volumes pi R^2 H, pi 0.2^2 0.1 and 0 to 1e-9 relative."""
import csv
import math
import os
import re
import hearthcheck as hc

c = hc.Check('alterationDepthErfc')
alpha = 0.756/(1500*1300)
T0, Tw = 293.15, 973.15
h, A = 1e-3, 1e-6
out = 'case/postProcessing/hearthAlteration'


def erfcinv(y):
    lo, hi = 0.0, 10.0
    for _ in range(200):
        m = 0.5*(lo + hi)
        if math.erfc(m) > y:
            lo = m
        else:
            hi = m
    return 0.5*(lo + hi)


def read_csv(path):
    with open(path) as f:
        return list(csv.DictReader(f))


for t in (3600, 7200):
    s = 2*math.sqrt(alpha*t)
    summary = read_csv('%s/%d/summary.csv' % (out, t))
    c.true('summary at t = %d s: thresholds 100, 290, 500 C' % t,
           [float(r['threshold_C']) for r in summary] == [100, 290, 500])
    for row in summary:
        thr = float(row['threshold_C'])
        eta = erfcinv((thr + 273.15 - T0)/(Tw - T0))
        z = s*eta
        slope = (Tw - T0)*2/math.sqrt(math.pi)*math.exp(-eta*eta)/s
        curvature = z/(2*alpha*t)            # |T''|/|T'|
        tol = h*h/8*curvature + 0.2/slope
        for line in ('axis', 'axisFaces'):
            depth = float(row['depth_%s_m' % line])
            c.le('t = %d s, %3g C, %-9s |depth - erfc| [mm] (%.4f cm)'
                 % (t, thr, line, 100*depth),
                 1e3*abs(depth - z), 1e3*tol)
        # the per-threshold file holds the same depths
        per = read_csv('%s/%d/alteration_%gC.csv' % (out, t, thr))
        c.true('t = %d s, %3g C: alteration_%gC.csv = summary' % (t, thr, thr),
               all(float(r['depth_m']) == float(row['depth_%s_m' % r['line']])
                   for r in per) and len(per) == 2)
        depth = float(row['depth_axis_m'])
        c.le('t = %d s, %3g C: |V/A - depth| [mm]' % (t, thr),
             1e3*abs(float(row['volume_m3'])/A - depth), 1e3*h/2)


# Serial and parallel CSV files agree
def numbers(path):
    with open(path) as f:
        return [float(v) for v in re.findall(r'[-+]?\d[\d.]*(?:[eE][-+]?\d+)?',
                                              f.read())]


worst, nFiles, same = 0.0, 0, True
for t in ('3600', '7200'):
    for name in sorted(os.listdir('%s/%s' % (out, t))):
        a = numbers('%s/%s/%s' % (out, t, name))
        b = numbers('parallel/postProcessing/hearthAlteration/%s/%s' % (t, name))
        same = same and len(a) == len(b)
        worst = max([worst] + [abs(x - y)/max(abs(x), 1e-300)
                               for x, y in zip(a, b)])
        nFiles += 1
c.true('parallel run wrote the same %d files' % nFiles, same and nFiles == 8)
c.le('serial vs 2 ranks: largest relative difference', worst, 1e-9)

# Wedge
w = read_csv('wedge/postProcessing/hearthAlteration/0/summary.csv')
expected = [math.pi*0.5**2*0.2, math.pi*0.2**2*0.1, 0.0]
for row, v in zip(w, expected):
    c.le('wedge: %3g C full-revolution volume %.6g m3 (exact %.6g)'
         % (float(row['threshold_C']), float(row['volume360_m3']), v),
         abs(float(row['volume360_m3']) - v), 1e-9*expected[0])
c.true('wedge: sector volume x pi/tan(2.5 deg)',
       abs(float(w[0]['volume360_m3'])/float(w[0]['volume_m3'])
           - math.pi/math.tan(math.radians(2.5))) < 1e-6)
c.done()
