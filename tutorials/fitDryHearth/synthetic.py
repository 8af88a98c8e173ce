"""Synthetic measurements of the fitDryHearth tutorial (fixed seeds:
reproducible).

    python3 synthetic.py sensors NOMINAL TRUE TABLE [SIGMA_R_MM]
        NOMINAL: the surveyed sensor file (name, x, y, z); writes TRUE, the
        same sensors where they "really" are: each moved by Gaussian errors
        of standard deviation SIGMA_R_MM (default 1 mm) along r (x) and
        3 mm along z (seed 13; the depth errors do not depend on
        SIGMA_R_MM), and TABLE, a CSV of the true displacements (name,
        dr_mm, dz_mm)

    python3 synthetic.py measure SENSORS_CSV MEASURED SIGMA
        SENSORS_CSV: the thermocouples CSV of the run made with the true
        positions and properties; writes MEASURED: one reading every 30 s
        (30 s .. end), linearly interpolated in time, plus Gaussian noise of
        standard deviation SIGMA [C] (seed 12)
"""
import csv
import random
import sys

SIGMA_R, SIGMA_Z = 1e-3, 3e-3      # position errors [m]
SEED_POSITIONS, SEED_NOISE = 13, 12
INTERVAL = 30.0                    # s between readings


def sensors(nominal, true, table, sigmaR=SIGMA_R):
    rng = random.Random(SEED_POSITIONS)
    out, rows = [], []
    with open(nominal) as f:
        for line in f:
            s = line.strip()
            if not s or s.startswith('#') or s.startswith('name'):
                out.append(line.rstrip('\n'))
                continue
            name, x, y, z = [v.strip() for v in s.split(',')]
            dr, dz = sigmaR*rng.gauss(0, 1), rng.gauss(0, SIGMA_Z)
            out.append('%s, %.6f, %s, %.6f'
                       % (name, float(x) + dr, y, float(z) + dz))
            rows.append((name, dr, dz))
    with open(true, 'w') as f:
        f.write('\n'.join(out) + '\n')
    with open(table, 'w') as f:
        f.write('name,dr_mm,dz_mm\n')
        for name, dr, dz in rows:
            f.write('%s,%.4f,%.4f\n' % (name, 1e3*dr, 1e3*dz))


def measure(src, out, sigma):
    rng = random.Random(SEED_NOISE)
    with open(src) as f:
        rows = list(csv.reader(f))
    header = [h.strip() for h in rows[0]]
    data = [[float(v) for v in r] for r in rows[1:]]
    with open(out, 'w') as f:
        f.write(','.join(header) + '\n')
        i, k = 1, 1
        while INTERVAL*k <= data[-1][0] + 1e-9:
            t = INTERVAL*k
            while data[i][0] < t:
                i += 1
            a, b = data[i - 1], data[i]
            w = (t - a[0])/(b[0] - a[0])
            vals = [a[c] + w*(b[c] - a[c]) + rng.gauss(0, sigma)
                    for c in range(1, len(header))]
            f.write('%g,' % t + ','.join('%.3f' % v for v in vals) + '\n')
            k += 1


if sys.argv[1] == 'sensors':
    sensors(*sys.argv[2:5],
            *([1e-3*float(sys.argv[5])] if len(sys.argv) > 5 else []))
elif sys.argv[1] == 'measure':
    measure(sys.argv[2], sys.argv[3], float(sys.argv[4]))
else:
    sys.exit('usage: see the docstring of synthetic.py')
