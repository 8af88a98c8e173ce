#!/usr/bin/env python3
"""ahcFoam (postProcessing/thermocouples/0/sensors.csv, every step) against
quadrupoleTemperature (100 uniform-gamma layers, and 2) at the sensor
depths, every 5 min: writes comparison.csv (time_h; per depth the ahcFoam
value linearly interpolated in time, the quadrupole values) and
results.txt (peaks, times of the peaks, largest differences) and
figures.csv (name,value,unit of the figures README.md states, checked by
tests/tutorialGradedSoil), and prints results.txt. Standard library and
etc/python/hearthTutorial.py only."""
import bisect
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                '..', '..', 'etc', 'python'))
import hearthTutorial as ht       # noqa: E402

rows = ht.read_csv


fvHead, fv = rows('postProcessing/thermocouples/0/sensors.csv')
qHead, q = rows('postProcessing/quadrupoleTemperature/temperature.csv')
_, q2 = rows('postProcessing/quadrupoleTemperature/temperature_2layers.csv')
names = fvHead[1:]
depths = [float(h[2:-1]) for h in qHead[2:]]
assert len(names) == len(depths)
times = [r[0] for r in fv]


def fv_at(t, j):
    i = bisect.bisect_left(times, t)
    if i < len(times) and times[i] == t:
        return fv[i][j + 1]
    w = (t - times[i - 1])/(times[i] - times[i - 1])
    return (1 - w)*fv[i - 1][j + 1] + w*fv[i][j + 1]


with open('comparison.csv', 'w') as f:
    f.write('time_h,' + ','.join('ahcFoam_%gcm,quadrupole_%gcm,'
                                 'quadrupole2_%gcm' % (100*d, 100*d, 100*d)
                                 for d in depths) + '\n')
    for r, r2 in zip(q, q2):
        f.write('%.6g,' % (r[0]/3600) + ','.join(
            '%.6f,%.6f,%.6f' % (fv_at(r[0], j), r[j + 2], r2[j + 2])
            for j in range(len(depths))) + '\n')

out = ['Graded soil (water 7 % -> 38 % over 1 m) under the fire record of'
       ' constant/fire.csv, 24 h',
       'ahcFoam (1-D, 2 mm cells, no phase change) vs quadrupoleTemperature'
       ' (100 uniform-gamma layers; 2 layers), every 5 min',
       '',
       '%-7s %10s %8s %10s %8s %13s %13s' % (
           'depth', 'peak FV', 'at [h]', 'peak quad', 'at [h]',
           'max|FV-quad|', 'max|2L-quad|'),
       '%-7s %10s %8s %10s %8s %13s %13s' % ('[cm]', '[C]', '', '[C]', '',
                                             '[K]', '[K]')]
fig = ht.Figures()
for j, d in enumerate(depths):
    fvs = [(fv_at(r[0], j), r[0]) for r in q]
    qs = [(r[j + 2], r[0]) for r in q]
    pf, pq = max(fvs), max(qs)
    diff = max(abs(a[0] - b[0]) for a, b in zip(fvs, qs))
    diff2 = max(abs(r2[j + 2] - r[j + 2]) for r, r2 in zip(q, q2))
    out.append('%-7g %10.2f %8.2f %10.2f %8.2f %13.3f %13.3f' % (
        100*d, pf[0], pf[1]/3600, pq[0], pq[1]/3600, diff, diff2))
    cm = '%gcm' % (100*d)
    fig.add('peakFV_' + cm, pf[0], 'C')
    fig.add('peakQuad_' + cm, pq[0], 'C')
    fig.add('peakTime_' + cm, pq[1]/3600, 'h')
    fig.add('peakTimeFV_' + cm, pf[1]/3600, 'h')
    fig.add('maxDiffFVQuad_' + cm, diff, 'K')
    fig.add('maxDiff2Layers_' + cm, diff2, 'K')
fig.add('comparisonTimes', len(q), '1')
fig.write('figures.csv')
with open('results.txt', 'w') as f:
    f.write('\n'.join(out) + '\n')
print('\n'.join(out))
