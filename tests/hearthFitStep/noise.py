"""Accuracy of the simulated temperatures of the test case:
    python3 noise.py coarse/sensors.csv converged/sensors.csv
prints max over the readings (every 60 s) and sensors of
|T_coarse - T_converged| [K]."""
import csv
import sys


def load(p):
    with open(p) as f:
        rows = list(csv.reader(f))
    return [[float(v) for v in r] for r in rows[1:]]


def at(d, t, c):
    for i in range(1, len(d)):
        if d[i][0] >= t:
            a, b = d[i - 1], d[i]
            w = (t - a[0])/(b[0] - a[0])
            return a[c] + w*(b[c] - a[c])
    raise ValueError('time %g after the end' % t)


a, b = load(sys.argv[1]), load(sys.argv[2])
end = min(a[-1][0], b[-1][0])
m, k = 0.0, 1
while 60*k <= end + 1e-9:
    for c in range(1, len(a[0])):
        m = max(m, abs(at(a, 60*k, c) - at(b, 60*k, c)))
    k += 1
print('%.6g' % m)
