#!/usr/bin/env python3
"""pitDuration: summary of the runs (results.txt).

    python3 results.py                          write results.txt
    python3 results.py --cross CASE SENSOR T    print the first time [h] at
                                                which SENSOR of CASE reaches
                                                T [C] (exit 1 if never)
"""
import csv
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                '..', '..', 'etc', 'python'))
import hearthTutorial as ht       # noqa: E402  (etc/python/hearthTutorial.py)


def read_sensors(case, name='thermocouples'):
    """Columns of postProcessing/<name>/0/sensors.csv: {header: [values]}"""
    return ht.sensors_of(case, name)


crossing = ht.crossing      # first time at which T reaches a threshold


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
    fig = ht.Figures()
    fig.add('cells', int(cells), '1')
    for case, _ in VARIANTS:
        steps, rej, exe, clock = ht.log_stats(case + '/log.ahcFoam')
        fig.add('steps_%s' % case, steps, '1')
        fig.add('rejected_%s' % case, rej, '1')
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
            if case == 'dry':
                fig.add('erfc290_%dcm' % d, erfc_time(d/100)/3600, 'h')
    w('')

    # Every sensor
    for case, label in VARIANTS:
        s, m = sensors[case], tmax[case]
        w('%s (%s/): thermocouples' % (label, case))
        w('  %-15s %12s %12s %14s %12s'
          % ('sensor', 'T=100 C [h]', 'T=290 C [h]', 'TMax=290 C [h]',
             'T at 6 h [C]'))
        for name in [h for h in s if h != 'time_s']:
            t100 = crossing(s['time_s'], s[name], 100)
            tc290 = crossing(s['time_s'], s[name], 290)
            w('  %-15s %12s %12s %14s %12.1f'
              % (name, hours(t100), hours(tc290),
                 hours(crossing(m['time_s'], m[name], 290)), s[name][-1]))
            fig.add('t100_%s_%s' % (case, name), t100 and t100/3600, 'h')
            fig.add('t290_%s_%s' % (case, name), tc290 and tc290/3600, 'h')
            fig.add('T6h_%s_%s' % (case, name), s[name][-1], 'C')
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
        fig.add('durationRun%s' % r['run'], float(r['duration_h']), 'h')
        fig.add('TMax4cmRun%s' % r['run'], float(r['TMax_floor_4cm_C']), 'C')
    fig.add('continuous290_4cm', tc/3600, 'h')
    fig.add('minimalDuration', d, 'h')
    fig.add('minimalDurationMinutes', 60*d, 'min')
    fig.add('bracketLower', float(result['lower_h']), 'h')
    fig.add('bracketUpper', float(result['upper_h']), 'h')
    fig.add('durationRuns', float(result['runs']), '1')
    fig.add('minimalShorterBy', tc/3600 - d, 'h')
    fig.add('minimalShorterByMinutes', 60*(tc/3600 - d), 'min')
    fig.add('minimalShorterByPercent', 100*(1 - d*3600/tc), '%')
    w('')

    # hearthDuration's fit to the observed depth (wetFit/)
    fit = {r['parameter']: r
           for r in read_csv('wetFit/postProcessing/hearthDuration/fit.csv')}
    fs = read_csv('wetFit/postProcessing/hearthDuration/fitSummary.csv')[0]
    fd = fit['duration_h']
    dF, seF = float(fd['estimate']), float(fd['standardError'])
    loF, hiF = float(fd['lower']), float(fd['upper'])
    w('hearthDuration fit (wetFit/): reddening (290 C) observed 4 cm +/- 3 mm '
      'under the floor centre')
    w('  the fire burned at least %.2f h (95 %%: %.2f-%.2f h), if no hotter '
      'than 700 C; standard error %.2f h; %s runs, %s s wall time'
      % (dF, loF, hiF, seF, fs['runs'],
         read_file('wetFit/wallTime.hearthDuration', '?')))
    fig.add('fitDuration', dF, 'h')
    fig.add('fitLower', loF, 'h')
    fig.add('fitUpper', hiF, 'h')
    fig.add('fitStandardError', seF, 'h')
    fig.add('fitRelativeStandardError', 100*seF/dF, '%')
    fig.add('fitRuns', float(fs['runs']), '1')
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
            for line in ('floorCentre', 'longWall', 'shortWall'):
                fig.add('depth%s_%s_%s' % (r['threshold_C'], case, line),
                        100*float(r['depth_%s_m' % line]), 'cm')
            fig.add('volume%s_%s' % (r['threshold_C'], case),
                    float(r['volume_m3']), 'm3')
    w('')

    # Energy balance
    for case, label in VARIANTS:
        log = case + '/log.ahcFoam'
        w('Last energy balance of %s/log.ahcFoam (quarter domain):' % case)
        block = ht.energy_balance_blocks(log)[-1]
        out.extend(['  ' + block[0]] + ['    ' + l for l in block[1:]])
        w('')
        eb = ht.energy_balance(log)
        fig.add('heatIn_%s' % case, eb['in']/1e6, 'MJ')
        fig.add('farFraction_%s' % case, -100*eb['in_far']/eb['in'], '%')
        # the log's initial - now (latent/L is it only for energyConsistent:
        # about half of it for thesisCompatible's (rho_l + rho_v)/2)
        fig.add('waterEvaporated_%s' % case, eb['evaporated'], 'kg')
        fig.add('latentFraction_%s' % case, 100*eb['latent']/eb['stored'],
                '%')
        fig.add('largestRelativeImbalance_%s' % case,
                max(abs(ht.energy_balance(log, i)['relative'])
                    for i in range(len(ht.energy_balance_blocks(log)))), '1')
    fig.write('figures.csv')

    with open('results.txt', 'w') as f:
        f.write('\n'.join(out) + '\n')
    print('\n'.join(out))


if __name__ == '__main__':
    summary()
