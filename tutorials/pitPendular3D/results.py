#!/usr/bin/env python3
"""pitPendular3D: summary of a finished (reconstructed) run.

    python3 results.py NPROCS WALL_SECONDS [WALL_SECONDS_FULLRANGE]

Reads sensors.csv (the thermocouples, C), postProcessing/probes/0/alphaL
and log.pendularFoam (steps, balances); with a third argument the same
of the full-range run in fullRange/ (Allrun -fullRange: its figures named
fullRange_<name>, and its differences from the pendular run, named
fullRangeDiff_<name>); prints the summary (results.txt)
and writes figures.csv (name,value,unit of every result figure README.md
states, checked by tests/tutorialPitPendular3D). Standard library and
etc/python/hearthTutorial.py only.
"""

import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                '..', '..', 'etc', 'python'))
import hearthTutorial as ht       # noqa: E402

SECTORS = 4     # quarter domain


def fmt_h(t):
    return '%.1f min' % (t/60) if t is not None else '-'


def summarise(case, title, wall, nprocs, prefix, fig, p):
    """The summary of the run in folder case: lines through p, figures
    (named prefix + name) into fig; returns the figures as a dict"""
    vals = {}

    def add(name, value, unit):
        vals[name] = value
        fig.add(prefix + name, value, unit)

    sensors = ht.read_sensors(os.path.join(case, 'sensors.csv'))
    times = sensors['time_s']
    names = [n for n in sensors if n != 'time_s']
    log = os.path.join(case, 'log.pendularFoam')
    steps, rejected, _, _ = ht.log_stats(log)
    with open(log) as f:
        iters = sum(int(m) for m in re.findall(
            r'^pendularFoam: deltaT = \S+, iterations = (\d+)', f.read(),
            re.M))
    p('pitPendular3D%s: pendularFoam, %s rank(s), %s s wall time (%s)'
      % (title, nprocs, wall, 'from the copy of the case to its plots'
         if prefix else 'mesh to reconstructPar'))
    p('  %d steps, %d nonlinear iterations (%.1f per step), %d rejected'
      ' sub-steps' % (steps, iters, iters/max(steps, 1), rejected))
    add('steps', steps, '1')
    add('rejected', rejected, '1')
    add('iterations', iters, '1')
    add('iterationsPerStep', iters/max(steps, 1), '1')
    p('')
    p('Sensors: t(95 C), t(105 C), time between (the 100 C plateau), T at'
      ' the end (%.1f h)' % (times[-1]/3600))
    p('%-12s %10s %10s %10s %9s' % ('sensor', 't95', 't105', 'plateau',
                                    'T_end'))
    for n in names:
        T = sensors[n]
        t95, t105 = ht.crossing(times, T, 95), ht.crossing(times, T, 105)
        pl = ((t105 - t95)/60 if t95 is not None and t105 is not None
              else None)
        p('%-12s %10s %10s %10s %7.1f C' % (
            n, fmt_h(t95), fmt_h(t105),
            '%6.1f min' % pl if pl is not None else '-', T[-1]))
        add('t95_' + n, t95 and t95/60, 'min')
        add('t105_' + n, t105 and t105/60, 'min')
        add('plateau_' + n, pl, 'min')
        add('Tend_' + n, T[-1], 'C')
    # liquid fraction under the floor: the condensation peak at each probe
    locs, ptimes, cols = ht.read_probes(
        os.path.join(case, 'postProcessing/probes/0/alphaL'))
    p('')
    p('alpha_l under the centre of the floor (initially 0.01): largest'
      ' value (condensation ahead of the front), its time, value at the'
      ' end')
    for loc, c in zip(locs, cols):
        d = -100*(loc[2] + 0.25)
        a, ta = ht.peak(ptimes, c)
        p('  %4.0f cm: max %.4f at %.2f h, end %.4f' % (d, a, ta/3600, c[-1]))
        add('probeAlphaLMax_%gcm' % round(d), a, '1')
        add('probeAlphaLMaxTime_%gcm' % round(d), ta/3600, 'h')
        add('probeAlphaLMaxRatio_%gcm' % round(d), a/0.01, '1')
        add('probeAlphaLEnd_%gcm' % round(d), c[-1], '1')
    # balances at the last write time, and the largest over the writes
    bal = ht.pendular_balances(log)
    if bal:
        last = bal[-1]
        water, energy = last['water'], last['energy']
        p('')
        p('Balances at t = %g s (whole pit, x %d the quarter):'
          % (last['time'], SECTORS))
        wout = dict((k[4:], v) for k, v in water.items()
                    if k.startswith('out_') and not k[4:].startswith('proc'))
        for k, v in wout.items():
            p('  water out through %-10s %8.3f kg' % (k, SECTORS*v))
            add('waterOut_' + k, SECTORS*v, 'kg')
        p('  water out in all              %8.3f kg' % (SECTORS*water['out']))
        add('waterOut', SECTORS*water['out'], 'kg')
        add('waterInitial', SECTORS*(water['inDomain'] - water['stored']),
            'kg')
        fire = [k for k in ('floor', 'wallsLower', 'walls') if k in wout]
        add('waterOutFireFraction', 100*sum(wout[k] for k in fire)
            / water['out'], '%')
        p('  water imbalance (relative) %g' % water['relative'])
        eout = dict((k[4:], v) for k, v in energy.items()
                    if k.startswith('out_') and not k[4:].startswith('proc'))
        p('  energy in through the fire (%s): %.2f MJ'
          % (' + '.join(fire), -SECTORS*sum(eout[k] for k in fire)/1e6))
        add('heatInFire', -SECTORS*sum(eout[k] for k in fire)/1e6, 'MJ')
        for k in eout:
            if k not in fire:
                p('  energy out through %-10s %.3f MJ'
                  % (k, SECTORS*eout[k]/1e6))
                add('energyOut_' + k, SECTORS*eout[k]/1e6, 'MJ')
        p('  energy imbalance (relative) %g' % energy['relative'])
        add('relativeImbalanceEnergy', energy['relative'], '1')
        add('relativeImbalanceWater', water['relative'], '1')
        add('largestRelativeImbalanceEnergy',
            max(abs(b['energy']['relative']) for b in bal), '1')
        add('largestRelativeImbalanceWater',
            max(abs(b['water']['relative']) for b in bal), '1')
        p('  cells above the pendular limit (alpha_l > 0.05): %d; largest '
          'alpha_l %.4g' % (last['nOutside'], last['alphaLMax']))
        add('cellsOutsideRange', max(b['nOutside'] for b in bal), '1')
        add('alphaLMaxWrites', max(b['alphaLMax'] for b in bal), '1')
    return vals


# The figures compared between the pendular and the full-range runs
# (full range minus pendular): the sensors' T at the end and t105, the
# condensation peaks, the water lost and its share through the fire
DIFFS = (['Tend_' + s for s in ('floor_1cm', 'floor_2cm', 'floor_4cm',
                                 'floor_7cm', 'wall_1cm', 'wall_2cm',
                                 'wall_4cm', 'ground_2cm')]
         + ['t105_' + s for s in ('floor_1cm', 'floor_2cm', 'floor_4cm',
                                  'floor_7cm', 'wall_4cm')]
         + ['probeAlphaLMax_%dcm' % d for d in (1, 2, 4, 7)]
         + ['probeAlphaLMaxTime_%dcm' % d for d in (1, 2, 4, 7)]
         + ['waterOut', 'waterOut_floor', 'waterOut_wallsLower',
            'waterOut_wallsUpper', 'waterOut_ground', 'waterOutFireFraction',
            'heatInFire', 'alphaLMaxWrites', 'iterationsPerStep'])


def main():
    nprocs, wall = sys.argv[1], sys.argv[2]
    wall_full = sys.argv[3] if len(sys.argv) > 3 else None
    fig = ht.Figures()
    out = []
    p = out.append
    pend = summarise('.', '', wall, nprocs, '', fig, p)
    if wall_full is not None:
        p('')
        p('=' * 78)
        p('Full range (fullRange/: liquidFlow with gravity, millingtonQuirk)')
        p('')
        full = summarise('fullRange', ' full range', wall_full, nprocs,
                         'fullRange_', fig, p)
        p('')
        p('Full range minus pendular:')
        p('  %-28s %12s %12s %12s' % ('figure', 'pendular', 'full range',
                                      'difference'))
        for n in DIFFS:
            a, b = pend.get(n), full.get(n)
            d = b - a if a is not None and b is not None else None
            p('  %-28s %12s %12s %12s' % (
                n, '%.4g' % a if a is not None else '-',
                '%.4g' % b if b is not None else '-',
                '%+.4g' % d if d is not None else '-'))
            fig.add('fullRangeDiff_' + n, d, '')
    fig.write('figures.csv')
    print('\n'.join(out))


if __name__ == '__main__':
    main()
