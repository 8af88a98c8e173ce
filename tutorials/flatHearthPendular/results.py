#!/usr/bin/env python3
"""flatHearthPendular: CSV files and a summary of the two runs.

Run in the tutorial directory after both solvers (called by ./Allrun):

    python3 results.py [WALL_PENDULAR WALL_CONDUCTION NPROCS]

Reads, for CASE in pendular (pendularFoam) and conduction (ahcFoam),
    CASE/postProcessing/thermocouples/0/sensors.csv   T [C] every step
    CASE/postProcessing/axisProfile/<t>/axis_*.xy     fields down the axis
    CASE/log.*Foam                                    water balance
and writes sensors_pendular.csv, sensors_conduction.csv (copies),
sensors_difference.csv (T of pendularFoam - T of ahcFoam, K) and
figures.csv (name,value,unit of every result figure README.md states,
checked by tests/tutorialFlatHearthPendular), and prints the summary
(results.txt). Standard library and etc/python/hearthTutorial.py only.
"""

import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                '..', '..', 'etc', 'python'))
import hearthTutorial as ht       # noqa: E402

SECTOR = 360.0/5.0      # the 5-degree wedge: x 72 for the whole hearth
PHI, ALPHA0, RHOL = 0.26, 0.01, 1000.0
W0 = PHI*ALPHA0*RHOL    # initial liquid water, kg/m3


def read_csv(path):
    header, rows = ht.read_csv(path)
    return header[1:], rows


def first_time(rows, col, level):
    """First time [s] at which sensor col reaches level [C], interpolated"""
    return ht.crossing([r[0] for r in rows], [r[col] for r in rows], level)


def value_at(rows, col, t):
    return ht.interpolate([r[0] for r in rows], [r[col] for r in rows], t)


def axis_profile(case):
    """Last write time, {field: [(depth_cm, value)]} down the axis"""
    t = ht.time_dirs(os.path.join(case, 'postProcessing/axisProfile'))[-1]
    depth, fields = ht.read_axis_set(t)
    return (float(os.path.basename(t)),
            dict((f, list(zip(depth, v))) for f, v in fields.items()))


def crossing(profile, level, from_above=True):
    """Depth [cm] where a profile (top down) first falls below level"""
    for (z0, a), (z1, b) in zip(profile, profile[1:]):
        if (a >= level > b) if from_above else (a <= level < b):
            return z0 + (level - a)/(b - a)*(z1 - z0)
    return None


def water_balance(log):
    """Last water balance of pendularFoam: {patch: kg out}, stored change"""
    b = ht.pendular_balances(log)
    if not b:
        return {}, None
    w = b[-1]['water']
    return (dict((k[4:], v) for k, v in w.items()
                 if k.startswith('out_') and not k[4:].startswith('proc')),
            w.get('stored'))


def fmt_h(t):
    return '%.1f min' % (t/60) if t is not None else '-'


def main():
    fig = ht.Figures()
    walls = sys.argv[1:4]
    names, pend = read_csv('pendular/postProcessing/thermocouples/0/sensors.csv')
    names_c, cond = read_csv('conduction/postProcessing/thermocouples/0/sensors.csv')
    assert names == names_c, 'different sensors in the two cases'
    for case, rows in (('pendular', pend), ('conduction', cond)):
        with open('sensors_%s.csv' % case, 'w') as f:
            f.write('time_s,' + ','.join(names) + '\n')
            for r in rows:
                f.write(','.join('%.8g' % x for x in r) + '\n')
    tEnd = min(pend[-1][0], cond[-1][0])
    # T(pendular) - T(ahc) at the times of pendularFoam
    with open('sensors_difference.csv', 'w') as f:
        f.write('time_s,' + ','.join(names) + '\n')
        for r in pend:
            if r[0] <= tEnd:
                f.write(','.join(['%.8g' % r[0]] + [
                    '%.6g' % (r[i] - value_at(cond, i, r[0]))
                    for i in range(1, len(names) + 1)]) + '\n')

    out = []
    p = out.append
    p('flatHearthPendular: 300 C hot plate (r < 15 cm) for %.1f h on sand'
      % (tEnd/3600))
    p('(phi = 0.26, alpha_l = %.3f: %.1f kg/m3 of water), pendularFoam'
      ' vs ahcFoam' % (ALPHA0, W0))
    if walls:
        p('wall time: pendularFoam %s s, ahcFoam %s s (%s rank(s))'
          % tuple(walls))
    p('')
    p('Sensors: t(95 C), t(105 C), time between (the "100 C plateau"),'
      ' T at the end')
    p('%-17s %-10s %10s %10s %10s %9s' % ('sensor', 'model', 't95', 't105',
                                          'plateau', 'T_end'))
    for i, n in enumerate(names, start=1):
        for model, rows in (('pendular', pend), ('ahc', cond)):
            t95 = first_time(rows, i, 95.0)
            t105 = first_time(rows, i, 105.0)
            plateau = ('%6.1f min' % ((t105 - t95)/60)
                       if t95 is not None and t105 is not None else '-')
            p('%-17s %-10s %10s %10s %10s %7.1f C'
              % (n, model, fmt_h(t95), fmt_h(t105), plateau,
                 value_at(rows, i, tEnd)))
            fig.add('t95_%s_%s' % (model, n), t95 and t95/60, 'min')
            fig.add('t105_%s_%s' % (model, n), t105 and t105/60, 'min')
            fig.add('plateau_%s_%s' % (model, n),
                    (t105 - t95)/60 if t95 is not None and t105 is not None
                    else None, 'min')
            fig.add('Tend_%s_%s' % (model, n), value_at(rows, i, tEnd), 'C')
    p('')
    p('T(pendular) - T(ahc) at each sensor: largest and smallest, when, and'
      ' the pendular T then')
    for i, n in enumerate(names, start=1):
        d = [(r[i] - value_at(cond, i, r[0]), r[0], r[i]) for r in pend]
        hi, lo = max(d), min(d)
        p('  %-17s %+6.2f K at %5.2f h (%5.1f C)   %+6.2f K at %5.2f h'
          ' (%5.1f C)' % (n, hi[0], hi[1]/3600, hi[2], lo[0], lo[1]/3600,
                          lo[2]))
        fig.add('diffMax_' + n, hi[0], 'K')
        fig.add('diffMaxTime_' + n, hi[1]/3600, 'h')
        fig.add('diffMaxT_' + n, hi[2], 'C')
        fig.add('diffMin_' + n, lo[0], 'K')
        fig.add('diffMinT_' + n, lo[2], 'C')
    # the pendular soil cooler than ahcFoam's, on the axis: the range of
    # the largest deficits and of the temperatures at which they occur
    lows = [min((r[i] - value_at(cond, i, r[0]), r[i]) for r in pend)
            for i, n in enumerate(names, start=1) if n.startswith('axis')]
    if lows:
        fig.add('coolingAxisSmallest', min(-d for d, _ in lows), 'K')
        fig.add('coolingAxisLargest', max(-d for d, _ in lows), 'K')
        fig.add('coolingAxisTLowest', min(T for _, T in lows), 'C')
        fig.add('coolingAxisTHighest', max(T for _, T in lows), 'C')
    p('')

    # Down the axis at the last write time
    tp, prof = axis_profile('pendular')
    tc, profc = axis_profile('conduction')
    TpC = [(z, T - 273.15) for z, T in prof['T']]
    TcC = [(z, T - 273.15) for z, T in profc['T']]
    p('Down the axis at t = %.1f h:' % (tp/3600))
    p('  depth of 100 C: pendular %.2f cm, ahc %.2f cm'
      % (crossing(TpC, 100.0), crossing(TcC, 100.0)))
    fig.add('depth100_pendular', crossing(TpC, 100.0), 'cm')
    fig.add('depth100_ahc', crossing(TcC, 100.0), 'cm')
    alpha = prof['alphaL']
    zmax, amax = max(alpha, key=lambda x: x[1])
    dry = crossing(alpha, 0.5*ALPHA0, from_above=False)
    dryc = None
    if 'liquidWater' in profc:
        lw = profc['liquidWater']
        dryc = crossing(lw, 0.5*max(a for _, a in lw), from_above=False)
    p('  dried zone (alpha_l < %.3f): pendular to %s cm, ahc (liquid water'
      ' < half) to %s cm'
      % (0.5*ALPHA0, '%.2f' % dry if dry else '-',
         '%.2f' % dryc if dryc else '-'))
    T_at = None
    for (z, a), (_, T) in zip(alpha, TpC):
        if z == zmax:
            T_at = T
    wet = [z for z, a in alpha if a > 1.05*ALPHA0]
    fig.add('dryDepth_pendular', dry, 'cm')
    fig.add('dryDepthT_pendular', dry and ht.interpolate(
        [z for z, _ in TpC], [T for _, T in TpC], dry), 'C')
    fig.add('dryDepth_ahc', dryc, 'cm')
    fig.add('alphaLMaxAxis', amax, '1')
    fig.add('alphaLMaxAxisRatio', amax/ALPHA0, '1')
    fig.add('alphaLMaxAxisDepth', zmax, 'cm')
    fig.add('alphaLMaxAxisT', T_at, 'C')
    fig.add('condensationTop', min(wet) if wet else None, 'cm')
    fig.add('condensationBottom', max(wet) if wet else None, 'cm')
    p('  condensation ahead of the front: alpha_l up to %.4f (%.2f x the'
      ' initial) at %.2f cm (T = %.1f C);' % (amax, amax/ALPHA0, zmax, T_at))
    if wet:
        p('  alpha_l > 1.05 x initial from %.2f to %.2f cm'
          % (min(wet), max(wet)))

    # Water
    wout, stored = water_balance('pendular/log.pendularFoam')
    if stored is not None:
        p('')
        p('Water (whole hearth, x %.0f the wedge) at the last write time:'
          % SECTOR)
        p('  pendularFoam: lost %.3f kg; out through %s'
          % (-stored*SECTOR, ', '.join('%s %.3f kg' % (k, v*SECTOR)
                                      for k, v in wout.items())))
        fig.add('waterLost_pendular', -stored*SECTOR, 'kg')
        for k, v in wout.items():
            fig.add('waterOut_%s' % k, v*SECTOR, 'kg')
    # ahcFoam's last balance: the liquid water at the start and the water
    # evaporated since
    eb = ht.energy_balance('conduction/log.ahcFoam')
    if eb and 'evaporated' in eb:
        p('  ahcFoam:      evaporated %.3f kg (initial %.3f kg)'
          % (eb['evaporated']*SECTOR, eb['initialLiquidWater']*SECTOR))
        fig.add('waterLost_ahc', eb['evaporated']*SECTOR, 'kg')
        if stored is not None:
            fig.add('waterLostRatio', -stored/eb['evaporated'], '1')
        fig.add('waterInitial', eb['initialLiquidWater']*SECTOR, 'kg')
    # heat through the fire disc
    for case, log, pat in (
            ('pendularFoam', 'pendular/log.pendularFoam',
             r'Energy balance at t = [^\n]*\n\s*out through fire = (\S+)'),
            ('ahcFoam', 'conduction/log.ahcFoam',
             r'heat in through fire = (\S+)')):
        with open(log) as f:
            found = re.findall(pat, f.read())
        if found:
            q = float(found[-1])*(-1 if case == 'pendularFoam' else 1)
            p('  heat in through the fire disc, %-12s %.2f MJ'
              % (case + ':', q*SECTOR/1e6))
            fig.add('heatFire_' + case, q*SECTOR/1e6, 'MJ')

    # The axis probes of pendularFoam: condensation wave and drying
    locs, times, cols = ht.read_probes(
        'pendular/postProcessing/probes/0/alphaL')
    p('')
    p('alpha_l at the probes of pendularFoam: largest (when), dry '
      '(alpha_l < %.3f) at' % (0.5*ALPHA0))
    for loc, c in zip(locs, cols):
        if loc[0] > 0.01:
            continue            # the axis probes only
        name = 'axis_%gcm' % round(-100*loc[2], 3)
        a, ta = ht.peak(times, c)
        k = c.index(a)
        tdry = next((t for t, x in zip(times[k:], c[k:])
                     if x < 0.5*ALPHA0), None)
        p('  %-10s %.4f at %.2f h, dry at %s' % (
            name, a, ta/3600, '%.2f h' % (tdry/3600) if tdry else '-'))
        fig.add('probeAlphaLMax_' + name, a, '1')
        fig.add('probeAlphaLMaxTime_' + name, ta/3600, 'h')
        fig.add('probeDry_' + name, tdry and tdry/3600, 'h')

    # Balances and steps of pendularFoam
    bal = ht.pendular_balances('pendular/log.pendularFoam')
    steps, rejected, _, _ = ht.log_stats('pendular/log.pendularFoam')
    p('')
    p('pendularFoam: %d steps, %d rejected; at the %d write times: largest '
      'alpha_l %.4g, cells above the pendular range %d; largest relative '
      'imbalance: energy %.2g, water %.2g, air %.2g'
      % (steps, rejected, len(bal), max(b['alphaLMax'] for b in bal),
         max(b['nOutside'] for b in bal),
         max(abs(b['energy']['relative']) for b in bal),
         max(abs(b['water']['relative']) for b in bal),
         max(abs(b['air']['relative']) for b in bal)))
    fig.add('steps_pendular', steps, '1')
    fig.add('rejected_pendular', rejected, '1')
    fig.add('alphaLMaxWrites', max(b['alphaLMax'] for b in bal), '1')
    fig.add('cellsOutsideRange', max(b['nOutside'] for b in bal), '1')
    for q in ('energy', 'water', 'air'):
        fig.add('largestRelativeImbalance_' + q,
                max(abs(b[q]['relative']) for b in bal), '1')
    fig.write('figures.csv')
    print('\n'.join(out))


if __name__ == '__main__':
    main()
