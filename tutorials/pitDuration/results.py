#!/usr/bin/env python3
"""pitDuration: summary of the runs (results.txt).

    python3 results.py                          write results.txt
    python3 results.py --cross CASE SENSOR T    print the first time [h] at
                                                which SENSOR of CASE reaches
                                                T [C] (exit 1 if never)
"""
import csv
import sys


def read_sensors(case, name='thermocouples'):
    """Columns of postProcessing/<name>/0/sensors.csv: {header: [values]}"""
    with open('%s/postProcessing/%s/0/sensors.csv' % (case, name)) as f:
        rows = list(csv.reader(f))
    header = rows[0]
    cols = {h: [] for h in header}
    for r in rows[1:]:
        for h, v in zip(header, r):
            cols[h].append(float(v))
    return cols


def crossing(t, T, threshold):
    """First time [s] at which T reaches threshold (linear between the
    samples), None if never"""
    for i in range(1, len(t)):
        if T[i] >= threshold > T[i - 1]:
            return t[i - 1] + (threshold - T[i - 1])*(t[i] - t[i - 1]) \
                / (T[i] - T[i - 1])
    if T and T[0] >= threshold:
        return t[0]
    return None


if __name__ == '__main__' and len(sys.argv) > 1 and sys.argv[1] == '--cross':
    case, sensor, thr = sys.argv[2], sys.argv[3], float(sys.argv[4])
    s = read_sensors(case)
    tc = crossing(s['time_s'], s[sensor], thr)
    if tc is None:
        sys.exit(1)
    print('%.4f' % (tc/3600))
    sys.exit(0)


# ---------------------------------------------------------------------------
# The summary
# ---------------------------------------------------------------------------

import glob
import math
import os
import re

VARIANTS = [
    ('wet', 'wet clay, phi = 10 %'),
    ('wetThesis', 'wet clay, phi = 10 %, thesis AHC formula'),
    ('dry', 'dry clay, phi = 0'),
]
FLOOR = ['floor_1cm', 'floor_2cm', 'floor_3cm', 'floor_4cm', 'floor_6cm']
DRY_ALPHA = 0.756/(1500*1300)           # m2/s, the clay of Table 5.1


def hours(t):
    return '-' if t is None else '%.2f' % (t/3600)


def erfc_time(depth, T_fire=700, T0=20, threshold=290, alpha=DRY_ALPHA):
    """Time [s] at which the exact semi-infinite solution
    T = T0 + (T_fire - T0) erfc(z/(2 sqrt(alpha t))) reaches threshold at
    depth z (bisection on erfc(x) = (threshold - T0)/(T_fire - T0))"""
    target = (threshold - T0)/(T_fire - T0)
    lo, hi = 0.0, 5.0
    for _ in range(100):
        mid = 0.5*(lo + hi)
        if math.erfc(mid) > target:
            lo = mid
        else:
            hi = mid
    x = 0.5*(lo + hi)
    return (depth/(2*x))**2/alpha


def log_stats(case):
    """Steps, rejected steps, ExecutionTime and ClockTime of log.ahcFoam"""
    steps, rejected, exe, clock = 0, 0, None, None
    with open(case + '/log.ahcFoam') as f:
        for line in f:
            if line.startswith('Time = '):
                steps += 1
            m = re.search(r'rejected = (\d+)', line)
            if m:
                rejected += int(m.group(1))
            m = re.match(r'ExecutionTime = ([\d.]+) s\s+ClockTime = ([\d.]+) s',
                         line)
            if m:
                exe, clock = float(m.group(1)), float(m.group(2))
    return steps, rejected, exe, clock


def energy_balance(case):
    """The last 'Energy balance' block of log.ahcFoam"""
    with open(case + '/log.ahcFoam') as f:
        lines = f.read().splitlines()
    start = max(i for i, l in enumerate(lines)
                if l.startswith('Energy balance at t ='))
    block = [lines[start]]
    for l in lines[start + 1:]:
        if not l.strip():
            break
        block.append('  ' + l.strip())
    return block


def read_csv(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def read_file(path, default=''):
    try:
        with open(path) as f:
            return f.read().strip()
    except OSError:
        return default


def summary():
    out = []
    w = out.append
    cells = re.search(r'^\s*cells:\s*(\d+)', read_file('log.checkMesh'),
                      re.M).group(1)
    nProcs = os.environ.get('NPROCS', '?')

    w('pitDuration: Muhieddine (2009) §5.4, pit 50 x 90 cm, 25 cm deep; floor '
      'and walls at 700 C from t = 0')
    w('mesh: %s cells (quarter domain, 2 mm at the floor); %s rank(s)'
      % (cells, nProcs))
    for case, _ in VARIANTS:
        steps, rej, exe, clock = log_stats(case)
        w('  %-10s ahcFoam 6 h of fire: %4d steps (%d rejected), %s s wall '
          'time (ExecutionTime %.0f s, ClockTime %.0f s)'
          % (case, steps, rej, read_file(case + '/wallTime.ahcFoam', '?'),
             exe, clock))
    result = read_csv('wet/postProcessing/hearthDuration/result.csv')[0]
    runs = read_csv('wet/postProcessing/hearthDuration/runs.csv')
    w('  hearthDuration (wet): %s runs, %s s wall time'
      % (result['runs'], read_file('wet/wallTime.hearthDuration', '?')))
    if 'ALLRUN_SECONDS' in os.environ:
        w('  Allrun: %s s wall time up to this summary'
          % os.environ['ALLRUN_SECONDS'])
    w('')

    # Seed vs hearthFoam
    sensors = {case: read_sensors(case) for case, _ in VARIANTS}
    tmax = {case: read_sensors(case, 'thermocouplesTMax')
            for case, _ in VARIANTS}

    def t290(case, name, field=sensors):
        s = field[case]
        return crossing(s['time_s'], s[name], 290)

    w('Seed vs hearthFoam: time at which 290 C (reddening) reaches a depth '
      'under the centre of the floor [h]')
    w('  %-42s %6s %6s %11s' % ('soil', 'depth', 'seed', 'hearthFoam'))
    seed = {('wet', 2): '< 1', ('wet', 4): '4.5',
            ('wetThesis', 2): '< 1', ('wetThesis', 4): '4.5',
            ('dry', 2): '-', ('dry', 4): '~1'}
    for case, label in VARIANTS:
        for d in (2, 4):
            extra = ''
            if case == 'dry':
                extra = '   (exact 1-D erfc: %.3f)' % (erfc_time(d/100)/3600)
            w('  %-42s %4d cm %6s %11s%s'
              % (label if d == 2 else '', d, seed[(case, d)],
                 hours(t290(case, 'floor_%dcm' % d)), extra))
    w('')

    # Every sensor
    for case, label in VARIANTS:
        s, m = sensors[case], tmax[case]
        w('%s (%s/): thermocouples' % (label, case))
        w('  %-15s %12s %12s %14s %12s'
          % ('sensor', 'T=100 C [h]', 'T=290 C [h]', 'TMax=290 C [h]',
             'T at 6 h [C]'))
        for name in [h for h in s if h != 'time_s']:
            w('  %-15s %12s %12s %14s %12.1f'
              % (name, hours(crossing(s['time_s'], s[name], 100)),
                 hours(crossing(s['time_s'], s[name], 290)),
                 hours(crossing(m['time_s'], m[name], 290)), s[name][-1]))
        w('')

    # hearthDuration
    tc = t290('wet', 'floor_4cm')
    d = float(result['duration_h'])
    cool = read_file('wet/system/hearthDurationDict')
    tau = re.search(r'^\s*tau\s+([^;]+);', cool, re.M).group(1)
    followed = re.search(r'^\s*duration\s+([^;]+);', cool, re.M).group(1)
    w('hearthDuration (wet/): the shortest fire at 700 C, followed by its '
      'cooling (T = 20 + 680 exp(-t/tau), tau = %s h, followed %s h), that '
      'brings TMax 4 cm under the floor centre to 290 C' % (tau, followed))
    w('  minimal duration      %.3f h (%d min), bracket [%.4f, %.4f] h, %s runs'
      % (d, round(60*d), float(result['lower_h']), float(result['upper_h']),
         result['runs']))
    w('  continuous fire       %.3f h: time at which T reaches 290 C at 4 cm'
      % (tc/3600))
    w('  the minimal duration is shorter by %.3f h (%d min, %.1f %%): the heat'
      % (tc/3600 - d, round(60*(tc/3600 - d)), 100*(1 - d*3600/tc)))
    w('  stored in the hot soil keeps moving down after extinction, so TMax at'
      ' 4 cm')
    w('  goes on rising (a fire stopped at %.3f h gives TMax = %.1f C there, '
      'not 290 C).'
      % (float(runs[0]['duration_h']), float(runs[0]['TMax_floor_4cm_C'])))
    w('  %4s %12s %16s %10s %12s' % ('run', 'duration [h]', 'TMax 4 cm [C]',
                                     'f [K]', 'wall [s]'))
    for r in runs:
        w('  %4s %12.4f %16.2f %+10.3f %12.1f'
          % (r['run'], float(r['duration_h']), float(r['TMax_floor_4cm_C']),
             float(r['f_K']), float(r['wallTime_s'])))
    w('')

    # hearthAlteration
    w('hearthAlteration at the end of the fire (6 h): depth reached by TMax >= '
      'threshold [cm]; volume of the quarter domain [m3]')
    for case, label in VARIANTS:
        path = glob.glob(case + '/postProcessing/hearthAlteration/*/summary.csv')
        rows = read_csv(path[0])
        w('  %s' % label)
        w('  %10s %12s %10s %10s %12s'
          % ('threshold', 'floorCentre', 'longWall', 'shortWall', 'volume'))
        for r in rows:
            w('  %8s C %12.2f %10.2f %10.2f %12.4g'
              % (r['threshold_C'], 100*float(r['depth_floorCentre_m']),
                 100*float(r['depth_longWall_m']),
                 100*float(r['depth_shortWall_m']), float(r['volume_m3'])))
    w('')

    # Energy balance
    for case, label in VARIANTS:
        w('Last energy balance of %s/log.ahcFoam (quarter domain):' % case)
        out.extend('  ' + l for l in energy_balance(case))
        w('')

    with open('results.txt', 'w') as f:
        f.write('\n'.join(out) + '\n')
    print('\n'.join(out))


if __name__ == '__main__':
    summary()
