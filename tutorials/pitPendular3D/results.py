#!/usr/bin/env python3
"""pitPendular3D: summary of a finished (reconstructed) run.

    python3 results.py NPROCS WALL_SECONDS

Reads sensors.csv (the thermocouples, C), postProcessing/probes/0/alphaL
and log.pendularFoam (steps, balances); prints the summary (results.txt)
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


def main():
    nprocs, wall = sys.argv[1], sys.argv[2]
    fig = ht.Figures()
    sensors = ht.read_sensors('sensors.csv')
    times = sensors['time_s']
    names = [n for n in sensors if n != 'time_s']
    steps, rejected, _, _ = ht.log_stats('log.pendularFoam')
    with open('log.pendularFoam') as f:
        iters = sum(int(m) for m in re.findall(
            r'^pendularFoam: deltaT = \S+, iterations = (\d+)', f.read(),
            re.M))
    out = []
    p = out.append
    p('pitPendular3D: pendularFoam, %s rank(s), %s s wall time (mesh to'
      ' reconstructPar)' % (nprocs, wall))
    p('  %d steps, %d nonlinear iterations (%.1f per step), %d rejected'
      ' sub-steps' % (steps, iters, iters/max(steps, 1), rejected))
    fig.add('steps', steps, '1')
    fig.add('rejected', rejected, '1')
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
        fig.add('t95_' + n, t95 and t95/60, 'min')
        fig.add('t105_' + n, t105 and t105/60, 'min')
        fig.add('plateau_' + n, pl, 'min')
        fig.add('Tend_' + n, T[-1], 'C')
    # liquid fraction under the floor: the condensation peak at each probe
    locs, ptimes, cols = ht.read_probes('postProcessing/probes/0/alphaL')
    p('')
    p('alpha_l under the centre of the floor (initially 0.01): largest'
      ' value (condensation ahead of the front), its time, value at the'
      ' end')
    for loc, c in zip(locs, cols):
        d = -100*(loc[2] + 0.25)
        a, ta = ht.peak(ptimes, c)
        p('  %4.0f cm: max %.4f at %.2f h, end %.4f' % (d, a, ta/3600, c[-1]))
        fig.add('probeAlphaLMax_%gcm' % round(d), a, '1')
        fig.add('probeAlphaLMaxTime_%gcm' % round(d), ta/3600, 'h')
        fig.add('probeAlphaLMaxRatio_%gcm' % round(d), a/0.01, '1')
        fig.add('probeAlphaLEnd_%gcm' % round(d), c[-1], '1')
    # balances at the last write time, and the largest over the writes
    bal = ht.pendular_balances('log.pendularFoam')
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
            fig.add('waterOut_' + k, SECTORS*v, 'kg')
        fig.add('waterOut', SECTORS*water['out'], 'kg')
        fig.add('waterInitial', SECTORS*(water['inDomain'] - water['stored']),
                'kg')
        fire = [k for k in ('floor', 'wallsLower', 'walls') if k in wout]
        fig.add('waterOutFireFraction', 100*sum(wout[k] for k in fire)
                / water['out'], '%')
        p('  water imbalance (relative) %g' % water['relative'])
        eout = dict((k[4:], v) for k, v in energy.items()
                    if k.startswith('out_') and not k[4:].startswith('proc'))
        p('  energy in through the fire (%s): %.2f MJ'
          % (' + '.join(fire), -SECTORS*sum(eout[k] for k in fire)/1e6))
        fig.add('heatInFire', -SECTORS*sum(eout[k] for k in fire)/1e6, 'MJ')
        for k in eout:
            if k not in fire:
                p('  energy out through %-10s %.3f MJ'
                  % (k, SECTORS*eout[k]/1e6))
                fig.add('energyOut_' + k, SECTORS*eout[k]/1e6, 'MJ')
        p('  energy imbalance (relative) %g' % energy['relative'])
        fig.add('relativeImbalanceEnergy', energy['relative'], '1')
        fig.add('relativeImbalanceWater', water['relative'], '1')
        fig.add('largestRelativeImbalanceEnergy',
                max(abs(b['energy']['relative']) for b in bal), '1')
        fig.add('largestRelativeImbalanceWater',
                max(abs(b['water']['relative']) for b in bal), '1')
        p('  cells above the pendular limit (alpha_l > 0.05): %d; largest '
          'alpha_l %.4g' % (last['nOutside'], last['alphaLMax']))
        fig.add('cellsOutsideRange', max(b['nOutside'] for b in bal), '1')
        fig.add('alphaLMaxWrites', max(b['alphaLMax'] for b in bal), '1')
    fig.write('figures.csv')
    print('\n'.join(out))


if __name__ == '__main__':
    main()
