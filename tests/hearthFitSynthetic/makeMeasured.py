"""Synthetic measurements from the truth run's thermocouples CSV:
    python3 makeMeasured.py sensors.csv out.csv [sigma seed]
linearly interpolated to one reading a minute (60 s .. end), plus, when
sigma is given, Gaussian noise of standard deviation sigma [C] (Python's
random.gauss with the given seed: reproducible)."""
import csv
import random
import sys

src, out = sys.argv[1], sys.argv[2]
sigma = float(sys.argv[3]) if len(sys.argv) > 3 else 0.0
seed = int(sys.argv[4]) if len(sys.argv) > 4 else 0
rng = random.Random(seed)

with open(src) as f:
    rows = list(csv.reader(f))
header, data = rows[0], [[float(v) for v in r] for r in rows[1:]]


def interp(t, c):
    for i in range(1, len(data)):
        if data[i][0] >= t:
            a, b = data[i - 1], data[i]
            w = (t - a[0])/(b[0] - a[0])
            return a[c] + w*(b[c] - a[c])
    raise ValueError('time %g after the end of %s' % (t, src))


end = data[-1][0]
with open(out, 'w') as f:
    f.write(','.join(header) + '\n')
    k = 1
    while 60.0*k <= end + 1e-9:
        t = 60.0*k
        vals = [interp(t, c) + (rng.gauss(0.0, sigma) if sigma > 0 else 0.0)
                for c in range(1, len(header))]
        f.write('%g,' % t + ','.join('%.10g' % v for v in vals) + '\n')
        k += 1
