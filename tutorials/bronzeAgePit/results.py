"""bronzeAgePit: the summary results.txt of a finished (reconstructed) run.

    python3 results.py NPROCS SECONDS > results.txt      (called by ./Allrun)

Reads sensors.csv (the thermocouples, C), alteration.csv (hearthAlteration's
summary at the last time), log.ahcFoam (steps, clock time, energy balance)
and log.checkMesh (cells); writes figures.csv (name,value,unit of every
result figure README.md states, checked by tests/tutorialBronzeAgePit).
Standard library and etc/python/hearthTutorial.py only.
"""

import csv
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                '..', '..', 'etc', 'python'))
import hearthTutorial as ht       # noqa: E402

nProcs, allrunSeconds = sys.argv[1], sys.argv[2]

sensors = ht.read_sensors('sensors.csv')
times = sensors['time_s']
names = [n for n in sensors if n != 'time_s']

with open('alteration.csv') as f:
    alt = list(csv.DictReader(f))
lineNames = [h[len('depth_'):-len('_m')] for h in alt[0]
             if h.startswith('depth_')]
thresholds = [float(r['threshold_C']) for r in alt]


def depth(line, thr):
    return ht.alteration_depth(alt, line, thr)


steps, rejected, _, clock = ht.log_stats('log.ahcFoam')
balances = ht.energy_balance_blocks('log.ahcFoam')
eb = ht.energy_balance('log.ahcFoam')
cells = re.search(r'^\s*cells:\s*(\d+)', open('log.checkMesh').read(), re.M)

T115 = max(sensors['floor_11.5cm'])
fig = ht.Figures()

print('bronzeAgePit: Muhieddine (2009) §5.3, 500 C floor / 300 C walls '
      '(to 20 cm), 3.5 h')
print('mesh: %s cells (quarter domain); %s rank(s); %d steps (%d rejected); '
      'ahcFoam %s s clock time, Allrun %s s'
      % (cells.group(1) if cells else '?', nProcs, steps, rejected,
         '%.0f' % clock if clock is not None else '?', allrunSeconds))
fig.add('cells', int(cells.group(1)) if cells else None, '1')
fig.add('steps', steps, '1')
fig.add('rejected', rejected, '1')
print()
print('Seed vs hearthFoam')
print('  max T at 11.5 cm under the floor centre: seed <= 50 C, '
      'hearthFoam %.1f C' % T115)
print('  depth of 300 C into the wall (mid-height of the hot part): '
      'seed ~1.5 cm, hearthFoam %.2f cm (290 C: %.2f cm; 1 cm above the '
      'floor: %.2f cm)'
      % (100*depth('wallMid', 300), 100*depth('wallMid', 290),
         100*depth('wallFoot', 300)))
print('    (behind a wall held at 300 C the soil stays below 300 C: see '
      'README.md)')
print()
print('Maximum temperature of each thermocouple [C] (at time [h])')
for n in names:
    Tmax, tMax = ht.peak(times, sensors[n])
    print('  %-16s %7.1f  (%.2f h)' % (n, Tmax, tMax/3600))
    fig.add('TMax_%s' % n, Tmax, 'C')
    fig.add('TMaxTime_%s' % n, tMax/3600, 'h')
print()
print('Depth reached by TMax >= threshold [cm], from hearthAlteration '
      '(volume: quarter domain)')
print('  %9s' % 'threshold' + ''.join('%14s' % l for l in lineNames)
      + '%14s' % 'volume [m3]')
for r, thr in zip(alt, thresholds):
    d = [depth(l, thr) for l in lineNames]
    print('  %7g C' % thr + ''.join('%14.2f' % (100*x) for x in d)
          + '%14.4g' % float(r['volume_m3']))
    for l, x in zip(lineNames, d):
        fig.add('depth%g_%s' % (thr, l), 100*x, 'cm')
    fig.add('volume%g' % thr, float(r['volume_m3']), 'm3')
print()
print('Last energy balance of log.ahcFoam (quarter domain):')
for l in balances[-1]:
    print(l if l.startswith('Energy') else '  ' + l)
fig.add('heatInFloor', eb['in_floor']/1e6, 'MJ')
fig.add('heatInWallsLower', eb['in_wallsLower']/1e6, 'MJ')
fig.add('heatOutFar', -eb['in_far']/1e6, 'MJ')
fig.add('stored', eb['stored']/1e6, 'MJ')
fig.add('latent', eb['latent']/1e6, 'MJ')
fig.add('waterEvaporated', eb['evaporated'], 'kg')
fig.add('waterInitial', eb['initialLiquidWater'], 'kg')
fig.add('imbalance', eb['imbalance'], 'J')
fig.add('relativeImbalance', eb['relative'], '1')
fig.add('largestRelativeImbalance',
        max(abs(ht.energy_balance('log.ahcFoam', i)['relative'])
            for i in range(len(balances))), '1')
fig.add('balanceWrites', len(balances), '1')
fig.add('heatInWholePit', 4*eb['in']/1e6, 'MJ')
fig.write('figures.csv')
