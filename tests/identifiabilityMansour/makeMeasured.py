"""Measurements every 10 s (Mansour 2015 §4.5.3) from the truth run's
thermocouples CSV: python3 makeMeasured.py sensors.csv out.csv
(linear interpolation between the solver's steps)."""
import csv
import sys

with open(sys.argv[1]) as f:
    rows = list(csv.reader(f))
header, data = rows[0], [[float(v) for v in r] for r in rows[1:]]
out, i = [], 1
for k in range(1, 2161):
    t = 10.0*k
    while data[i][0] < t:
        i += 1
    a, b = data[i - 1], data[i]
    w = (t - a[0])/(b[0] - a[0])
    out.append([t] + [a[c] + w*(b[c] - a[c]) for c in range(1, len(header))])
with open(sys.argv[2], 'w') as f:
    f.write(','.join(header) + '\n')
    for r in out:
        f.write('%g,' % r[0] + ','.join('%.12g' % v for v in r[1:]) + '\n')
