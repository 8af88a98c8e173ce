"""fireTemperature boundary condition: a measured fire history on the fire
patch of a 1-D column of dry clay, 100 cells of 2 mm, fixed steps of 15 s.

The reference is the history itself. With the rows (tau_i, theta_i) of
constant/fire.csv (minutes, C) and the offset of 300 s (the logger was
started 5 min before ignition),

    t_i = 60 tau_i - 300 [s],   T_i = theta_i + 273.15 [K],
    T_fire(t) = T_i + (T_{i+1} - T_i)(t - t_i)/(t_{i+1} - t_i)

held at T_N after the last row. Every t_i is a multiple of the step, so a
step lands on each row in the run (9 rows in (0, 3600] s; the rows at -300,
-105 and 0 s lie before the first step), and on 291 other steps in between
or after the end. The patch temperature is read at every step from the
surfaceFieldValue areaAverage of T on the fire patch (one face: the face
value, written with 17 digits).

Tolerances: at the rows the condition returns T_i itself, and the only
round-off is that of areaAverage (T A / A) and of printing: 1e-10 K is
1e-13 of T, a few ulp. Between the rows the interpolation here and in the
condition are the same formula; 1e-10 K again. The route through
OpenFOAM's uniformFixedValue + tableFile interpolates with weights
(w0 T_i + (1 - w0) T_{i+1}): a round-off difference of some 1e-13 K; the
soil temperatures it drives differ by what the linear solver (tolerance
1e-12) propagates: 1e-9 K allowed for both.
"""
import math
import os
import re
import sys

import hearthcheck as hc

TOL_EXACT = 1e-10     # K: the history at the rows, between, after the end
TOL_ROUTES = 1e-9     # K: fireTemperature against uniformFixedValue


def read_field_value(path):
    """(times, values) of a surfaceFieldValue .dat file."""
    times, values = [], []
    with open(path) as f:
        for line in f:
            if line.startswith('#') or not line.strip():
                continue
            v = line.split()
            times.append(float(v[0]))
            values.append(float(v[1]))
    return times, values


def patch_history(case, start='0'):
    return read_field_value(os.path.join(
        case, 'postProcessing', 'firePatch', start, 'surfaceFieldValue.dat'))


def probe_history(case, start='0', pp='postProcessing'):
    _, times, cols = hc.read_probes(os.path.join(case, pp, 'probes',
                                                 start, 'T'))
    return times, cols


def interpolate(rows, t):
    """The piecewise-linear history, first and last values held."""
    if t <= rows[0][0]:
        return rows[0][1]
    if t >= rows[-1][0]:
        return rows[-1][1]
    for (t0, T0), (t1, T1) in zip(rows[:-1], rows[1:]):
        if t0 <= t < t1:
            if t == t0:
                return T0
            return T0 + (t - t0)/(t1 - t0)*(T1 - T0)
    raise ValueError(t)


def csv_rows(path):
    rows = []
    with open(path) as f:
        lines = f.readlines()
    for line in lines[1:]:
        if line.strip():
            v = line.split(',')
            rows.append((60*float(v[0]) - 300, float(v[1]) + 273.15))
    return rows


def logger_rows(path):
    rows = []
    with open(path) as f:
        lines = f.read().split('\n')
    for line in lines[2:]:
        s = line.strip()
        if s and not s.startswith('#'):
            v = s.split()
            rows.append((3600*float(v[0]), float(v[2])))
    return rows


def fire_entry(path):
    """The text of the fire patch entry of a written T."""
    with open(path) as f:
        txt = f.read()
    m = re.search(r'\n\s*fire\s*\{(.*?)\n\s*\}', txt, re.S)
    return m.group(1) if m else ''


c = hc.Check('fireHistory')
scratch = sys.argv[1] if len(sys.argv) > 1 else '.'
csv = os.path.join(scratch, 'csv')
rows = csv_rows(os.path.join(csv, 'constant', 'fire.csv'))
tEnd = 4500.0

# ---------------------------------------------------------------- (a)
times, Tp = patch_history(csv)
c.true('(a) one patch value per step of 15 s up to %g s' % tEnd,
       len(times) == 300 and abs(times[-1] - tEnd) < 1e-9
       and all(abs(t - 15*(i + 1)) < 1e-9 for i, t in enumerate(times)),
       '%d steps, last %g s' % (len(times), times[-1] if times else -1))

rowTimes = [t for t, _ in rows]
eRows, eBetween, eAfter = [], [], []
for t, T in zip(times, Tp):
    err = abs(T - interpolate(rows, t))
    if t > rows[-1][0]:
        eAfter.append(err)
    elif any(t == tr for tr in rowTimes):
        eRows.append(err)
    else:
        eBetween.append(err)
nRowsInRun = sum(1 for t in rowTimes if 0 < t <= tEnd)
print('  (a) %d rows in the run, %d steps between rows, %d after the end'
      % (len(eRows), len(eBetween), len(eAfter)))
c.true('(a) every CSV time in (0, %g] s is a step' % tEnd,
       len(eRows) == nRowsInRun == 9, '%d of %d' % (len(eRows), nRowsInRun))
c.le('(a) max |T_patch - CSV value| at the CSV times [K]',
     max(eRows), TOL_EXACT)
c.le('(a) max |T_patch - linear interpolation| between them [K]',
     max(eBetween), TOL_EXACT)
c.le('(a) max |T_patch - last CSV value| after the end (held) [K]',
     max(eAfter), TOL_EXACT)
# Sanity of the coupling (the exactness is checked above): about 35 min
# near 700 C heat dry clay (a = 3.9e-7 m2/s) to roughly 580 C at 1 cm
# (erfc(0.01/(2 sqrt(a t))) ~ 0.85); the peak must exceed 400 C
t1, T1 = probe_history(csv)[0], probe_history(csv)[1][0]
c.true('(a) the history heats the soil (peak at 1 cm > 400 C)',
       max(T1) > 673.15,
       '%.2f K at t = %g s' % (max(T1), t1[T1.index(max(T1))]))
with open(os.path.join(csv, 'log.ahcFoam')) as f:
    log = f.read()
c.true('(a) summary in the log: 12 rows, 1 header line skipped, t from'
       ' -300 s', '12 row(s)' in log and '1 header line(s) skipped' in log
       and 't = -300 to 3600 s' in log)

# ---------------------------------------------------------------- (b)
# uniformFixedValue + tableFile (K, s) against fireTemperature + CSV
tb, Tb = patch_history(os.path.join(scratch, 'tableFile'))
c.true('(b) tableFile: same steps', tb == times, '%d steps' % len(tb))
ePatch = max(abs(a - b) for a, b in zip(Tp, Tb))
eRowsB = max(abs(a - b) for t, a, b in zip(times, Tp, Tb) if t in rowTimes)
_, pa = probe_history(csv)
_, pb = probe_history(os.path.join(scratch, 'tableFile'))
eSoil = max(abs(x - y) for ca, cb in zip(pa, pb) for x, y in zip(ca, cb))
print('  (b) fireTemperature (CSV, C, min, offset) vs uniformFixedValue'
      ' tableFile (K, s): patch %.3g K (%.3g K at the CSV times), soil %.3g K'
      % (ePatch, eRowsB, eSoil))
c.le('(b) max |T_patch(CSV) - T_patch(tableFile)|, every step [K]',
     ePatch, TOL_ROUTES)
c.le('(b) max |T_soil(CSV) - T_soil(tableFile)| at 1, 2, 5 cm [K]',
     eSoil, TOL_ROUTES)

# ---------------------------------------------------------------- (c)
ti, Ti = patch_history(os.path.join(scratch, 'inline'))
_, pi = probe_history(os.path.join(scratch, 'inline'))
eInline = max([abs(a - b) for a, b in zip(Tp, Ti)]
              + [abs(x - y) for ca, ci in zip(pa, pi) for x, y in zip(ca, ci)])
c.true('(c) inline table: same steps', ti == times)
c.le('(c) max |T(CSV) - T(inline table)|, patch and soil [K]', eInline, 0.0)

# ---------------------------------------------------------------- (d)
logger = os.path.join(scratch, 'logger')
lrows = logger_rows(os.path.join(logger, 'constant', 'logger.dat'))
tl, Tl = patch_history(logger)
eLogger = max(abs(T - interpolate(lrows, t)) for t, T in zip(tl, Tl))
before = [T for t, T in zip(tl, Tl) if t < lrows[0][0]]
after = [T for t, T in zip(tl, Tl) if t > lrows[-1][0]]
c.true('(d) logger: 5 rows read (t = 180 to 2700 s), %d steps before,'
       ' %d after' % (len(before), len(after)),
       len(lrows) == 5 and lrows[0][0] == 180 and len(before) == 11
       and len(after) == 120)
c.le('(d) max |T_patch - logger history| (whitespace, h, K, column 2,'
     ' CRLF) [K]', eLogger, TOL_EXACT)
c.le('(d) before its first time: its first value held [K]',
     max(abs(T - lrows[0][1]) for T in before), TOL_EXACT)
c.le('(d) after its last time: its last value held [K]',
     max(abs(T - lrows[-1][1]) for T in after), TOL_EXACT)

# ---------------------------------------------------------------- (e)
restart = os.path.join(scratch, 'restart')
entry = fire_entry(os.path.join(restart, '1800', 'T'))
want = ['type            fireTemperature;', 'file            "<constant>/fire.csv";',
        'timeUnit        min;', 'temperatureUnit C;', 'timeOffset      300;',
        'value           uniform 978.19310344827579;']
missing = [w for w in want if w not in entry]
c.true('(e) written 1800/T: the entry as given, and the value at 1800 s',
       not missing, 'missing: %s' % missing if missing else '')
c.le('(e) |value written at 1800 s - history| [K]',
     abs(float(re.search(r'value\s+uniform\s+(\S+);', entry).group(1))
         - interpolate(rows, 1800.0)), TOL_EXACT)
tr, Tr = patch_history(restart, '1800')
_, pr = probe_history(restart, '1800')
cont = {t: (T, [col[i] for col in pa]) for i, (t, T) in
        enumerate(zip(times, Tp))}
c.true('(e) restarted run: steps 1815 to 4500 s',
       len(tr) == 180 and tr[0] == 1815 and tr[-1] == tEnd)
eRestartPatch = max(abs(T - cont[t][0]) for t, T in zip(tr, Tr))
eRestartSoil = max(abs(col[i] - cont[t][1][k]) for i, t in enumerate(tr)
                   for k, col in enumerate(pr))
print('  (e) restart at 1800 s against the continuous run: patch %.3g K,'
      ' soil %.3g K' % (eRestartPatch, eRestartSoil))
c.le('(e) max |T_patch restarted - continuous| [K]', eRestartPatch, 0.0)
# The soil: the first iterate after a restart is not extrapolated in time;
# dry clay is linear, so only the linear solver's tolerance separates them
c.le('(e) max |T_soil restarted - continuous| [K]', eRestartSoil, 1e-8)

# ---------------------------------------------------------------- (f)
parallel = os.path.join(scratch, 'parallel')
tq, Tq = patch_history(parallel)
c.true('(f) parallel: same steps', tq == times)
c.le('(f) max |T_patch parallel - serial| [K]',
     max(abs(a - b) for a, b in zip(Tp, Tq)), 0.0)
values0 = []
for proc in ('processor0', 'processor1'):
    e = fire_entry(os.path.join(parallel, proc, '0', 'T'))
    c.true('(f) %s/0/T: written by fireTemperature' % proc,
           'type            fireTemperature;' in e
           and '"<constant>/fire.csv"' in e)
    m = re.search(r'value\s+uniform\s+(\S+);', e)
    if m:
        values0.append(float(m.group(1)))
c.true('(f) the fire face on one processor', len(values0) == 1,
       '%d' % len(values0))
# The value at t = 0 computed at construction: the CSV row at 5 min (20 C)
c.le('(f) value at t = 0 written by decomposePar - CSV row at 5 min [K]',
     abs(values0[0] - (20.0 + 273.15)) if values0 else 1e30, TOL_EXACT)

c.done()
