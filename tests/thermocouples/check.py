"""Checks of the thermocouples function object (run in tests/run/thermocouples
after ./run): cases serial/, parallel/ (2 ranks) and restart/ (serial/
continued from 1800 s to 2400 s). In each, three function objects sample T
at the five sensors of system/thermocouples.csv every minute:
  thermocouples   defaults: C, 10 significant digits
  thermocouplesK  unit K, 15 digits (loaded through 'libs')
  probes          OpenFOAM's probes, same positions, cellPoint, 15 digits

1. Layout: postProcessing/<name>/0/sensors.csv with the header
   time_s,TC1,...,TC5 (names in the order of the sensor file), a row at
   t = 0 (20 C / 293.15 K) and one a minute to 1800 s; serial and parallel
   files have the same header, times and size; in parallel only the case
   (not processor*/) has a postProcessing folder.
2. Serial = 2-rank parallel at every sensor and time to 1e-8 relative (in
   C), for the 10-digit C file and the 15-digit K file.
3. thermocouplesK = probes at every sensor and time, to round-off of the
   15-digit output (1e-13 relative), serial and parallel.
4. C = K - 273.15: the C file against the K file, within the rounding of
   10 significant digits (6e-10 relative).
5. Restart: a new file postProcessing/thermocouples/1800/sensors.csv whose
   first row (t = 1800 s, from the fields read back) equals the last row of
   the first run's file (10 digits), then rows to 2400 s; the file of the
   first run (0/) is left as it was.
6. Physics: the soil only heats, so every history is non-decreasing, and
   the sensor 5 mm under the fire is the hottest.
7. bin/plotSensors and bin/plotProfile wrote PNG files."""
import csv
import os

import hearthcheck as hc

c = hc.Check('thermocouples')

names = ['TC1', 'TC2', 'TC3', 'TC4', 'TC5']
positions = [(0.04, 0.025, -0.005), (0.04, 0.025, -0.02),
             (0.1, 0.023, -0.032), (0.15, 0.07, -0.01),
             (0.0123, 0.0877, -0.0611)]
times = [60.0*i for i in range(31)]          # 0, 60, ..., 1800 s


def read_csv(path):
    """sensors.csv -> (header, rows of floats, raw lines)."""
    with open(path) as f:
        raw = f.read().splitlines()
    rows = list(csv.reader(raw))
    header, body = rows[0], rows[1:]
    return header, [[float(v) for v in r] for r in body], raw


def rel(a, b):
    return abs(a - b)/max(abs(a), abs(b), 1e-300)


def files(case):
    return {n: os.path.join(case, 'postProcessing', n, '0', 'sensors.csv')
            for n in ('thermocouples', 'thermocouplesK')}


# 1. Layout ----------------------------------------------------------------
data = {}
for case in ('serial', 'parallel'):
    for fo, path in files(case).items():
        ok = c.true('%s: %s exists' % (case, path), os.path.isfile(path))
        if not ok:
            c.done()
        header, rows, raw = read_csv(path)
        data[case, fo] = (header, rows, raw)
        c.true('%s/%s: header' % (case, fo),
               header == ['time_s'] + names, raw[0])
        c.true('%s/%s: 6 columns in every row' % (case, fo),
               all(len(r) == 6 for r in rows), '%d rows' % len(rows))
        c.true('%s/%s: times 0, 60, ..., 1800 s' % (case, fo),
               [r[0] for r in rows] == times,
               '%g ... %g' % (rows[0][0], rows[-1][0]))
        T0 = 20.0 if fo == 'thermocouples' else 293.15
        c.true('%s/%s: t = 0 row is the initial %g' % (case, fo, T0),
               rows[0][1:] == [T0]*5, raw[1])

for fo in ('thermocouples', 'thermocouplesK'):
    s, p = data['serial', fo], data['parallel', fo]
    c.true('%s: serial and parallel: same header, times, size' % fo,
           s[0] == p[0] and [r[0] for r in s[1]] == [r[0] for r in p[1]]
           and len(s[2]) == len(p[2]))
procPP = [d for d in os.listdir('parallel') if d.startswith('processor')
          and os.path.isdir(os.path.join('parallel', d, 'postProcessing'))]
c.true('parallel: no processor*/postProcessing', not procPP, ' '.join(procPP))

# 2. Serial = parallel -----------------------------------------------------
for fo, offset in (('thermocouples', 0.0), ('thermocouplesK', 273.15)):
    err = max(rel(a - offset, b - offset)
              for rs, rp in zip(data['serial', fo][1], data['parallel', fo][1])
              for a, b in zip(rs[1:], rp[1:]))
    c.le('%s: max |serial - parallel|/|T| in C' % fo, err, 1e-8)

# 3. thermocouplesK = probes -----------------------------------------------
for case in ('serial', 'parallel'):
    locs, ptimes, cols = hc.read_probes(
        os.path.join(case, 'postProcessing', 'probes', '0', 'T'))
    c.true('%s: probes at the sensor file positions' % case,
           [tuple(l) for l in locs] == positions)
    rows = {r[0]: r[1:] for r in data[case, 'thermocouplesK'][1]}
    c.true('%s: probes times are thermocouples times' % case,
           ptimes == times[1:], '%d times' % len(ptimes))
    err = max(rel(rows[t][i], cols[i][k])
              for k, t in enumerate(ptimes) for i in range(5))
    c.le('%s: max |thermocouplesK - probes|/T [K]' % case, err, 1e-13)

# 4. C = K - 273.15 --------------------------------------------------------
for case in ('serial', 'parallel'):
    err = max(rel(a, b - 273.15)
              for rC, rK in zip(data[case, 'thermocouples'][1],
                                data[case, 'thermocouplesK'][1])
              for a, b in zip(rC[1:], rK[1:]))
    c.le('%s: max |C - (K - 273.15)|/|C| (10 digits)' % case, err, 6e-10)

# 5. Restart ---------------------------------------------------------------
first = os.path.join('restart', 'postProcessing', 'thermocouples', '0',
                     'sensors.csv')
again = os.path.join('restart', 'postProcessing', 'thermocouples', '1800',
                     'sensors.csv')
c.true('restart: %s unchanged' % first,
       open(first).read() == '\n'.join(data['serial', 'thermocouples'][2])
       + '\n')
if c.true('restart: new file %s' % again, os.path.isfile(again)):
    header, rows, raw = read_csv(again)
    c.true('restart: header', header == ['time_s'] + names)
    c.true('restart: times 1800, 1860, ..., 2400 s',
           [r[0] for r in rows] == [1800.0 + 60*i for i in range(11)],
           '%d rows' % len(rows))
    last = data['serial', 'thermocouples'][1][-1]
    c.le('restart: max |first row - last row of the first run|/|T|',
         max(rel(a, b) for a, b in zip(rows[0][1:], last[1:])), 6e-10)

# 6. Physics ---------------------------------------------------------------
rows = data['serial', 'thermocouplesK'][1]
c.true('histories non-decreasing',
       all(b[i] >= a[i] for a, b in zip(rows, rows[1:]) for i in range(1, 6)))
c.true('TC1 (5 mm under the fire) hottest at 1800 s',
       max(rows[-1][1:]) == rows[-1][1],
       ' '.join('%s %.2f C' % (n, v - 273.15)
                for n, v in zip(names, rows[-1][1:])))

# 7. Plots ------------------------------------------------------------------
for png in ('restart/sensors.png', 'serial/profile.png'):
    ok = os.path.isfile(png) and open(png, 'rb').read(8) == b'\x89PNG\r\n\x1a\n'
    c.true('%s is a PNG file' % png, ok,
           '%d bytes' % os.path.getsize(png) if ok else '')
c.done()
