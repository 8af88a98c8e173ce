#!/usr/bin/env python3
"""bronzeAgePit: the summary results.txt of a finished (reconstructed) run.

    python3 results.py NPROCS SECONDS > results.txt      (called by ./Allrun)

Reads sensors.csv (the thermocouples, C), alteration.csv (hearthAlteration's
summary at the last time), log.ahcFoam (steps, clock time, energy balance)
and log.checkMesh (cells). Standard library only.
"""

import csv
import re
import sys

nProcs, allrunSeconds = sys.argv[1], sys.argv[2]

# Thermocouples: maximum over the run and when
with open('sensors.csv') as f:
    rows = list(csv.reader(f))
names, data = rows[0][1:], [[float(x) for x in r] for r in rows[1:] if r]
times = [r[0] for r in data]

# Alteration depths
with open('alteration.csv') as f:
    alt = list(csv.reader(f))
lineNames = [h[len('depth_'):-len('_m')] for h in alt[0][2:]]
thresholds = [float(r[0]) for r in alt[1:]]
depths = [[float(x) for x in r[2:]] for r in alt[1:]]
volumes = [float(r[1]) for r in alt[1:]]

def depth(line, thr):
    return depths[thresholds.index(thr)][lineNames.index(line)]

# Log: steps, clock time, last energy balance
log = open('log.ahcFoam').read()
steps = len(re.findall(r'^ahcFoam: deltaT', log, re.M))
rejected = len(re.findall(r'step rejected', log))
clock = re.findall(r'ClockTime = (\S+) s', log)[-1]
balance = log[log.rfind('Energy balance'):].split('\n\n')[0]
cells = re.search(r'^\s*cells:\s*(\d+)', open('log.checkMesh').read(), re.M)

T115 = data and max(r[names.index('floor_11.5cm') + 1] for r in data)

print('bronzeAgePit: Muhieddine (2009) §5.3, 500 C floor / 300 C walls '
      '(to 20 cm), 3.5 h')
print('mesh: %s cells (quarter domain); %s rank(s); %d steps (%d rejected); '
      'ahcFoam %s s clock time, Allrun %s s'
      % (cells.group(1) if cells else '?', nProcs, steps, rejected, clock,
         allrunSeconds))
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
for i, n in enumerate(names):
    col = [r[i + 1] for r in data]
    k = max(range(len(col)), key=lambda j: col[j])
    print('  %-16s %7.1f  (%.2f h)' % (n, col[k], times[k]/3600))
print()
print('Depth reached by TMax >= threshold [cm], from hearthAlteration '
      '(volume: quarter domain)')
print('  %9s' % 'threshold' + ''.join('%14s' % l for l in lineNames)
      + '%14s' % 'volume [m3]')
for thr, d, v in zip(thresholds, depths, volumes):
    print('  %7g C' % thr + ''.join('%14.2f' % (100*x) for x in d)
          + '%14.4g' % v)
print()
print('Last energy balance of log.ahcFoam (quarter domain):')
for l in balance.split('\n'):
    print('  ' + l.strip() if not l.startswith('Energy') else l)
