#!/usr/bin/env python3
"""mansourPlate: the figures of the runs in run/ (see Allrun).

For each run and each sensor depth (1.4, 2.3, 3.2, 6.2, 10.6 cm): the 100 C
plateau (start: T reaches 95 C; end: T reaches 105 C; its length in
minutes; times interpolated between time steps, None if not reached), T at
1, 3 and 6 h, and the peak T over the 6 h; for pendularFoam the largest
relative water, air and energy imbalance of its log, for ahcFoam the
relative energy imbalance. Then pendularFoam minus the ahcFoam run of the
same sand and water (PAIRS) for each figure, and where the run expected to
stop stopped.

Writes results.txt (the tables of the README) and figures.csv (every
figure at full precision, name,value,unit).
"""

import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                '..', '..', 'etc', 'python'))
import hearthTutorial as ht

os.chdir(os.path.dirname(os.path.abspath(__file__)))

HOUR = 3600.0
END = 21600.0
SENSORS = ('1.4cm', '2.3cm', '3.2cm', '6.2cm', '10.6cm')
RUNS = (('plate_ahc', 'ahcFoam (AHC conduction)'),
        ('plate_pend', 'pendularFoam, no liquid flow'),
        ('plate_ahc_sat', 'ahcFoam, phi 0.3585, alpha_l0 0.99'),
        ('plate_pend_sat', 'pendularFoam, phi 0.3585, alpha_l0 0.99'),
        ('plate_pend_lf', 'pendularFoam, liquidFlow + gravity'))
# pendularFoam run -> the ahcFoam run with the same sand and water
PAIRS = (('plate_pend', 'plate_ahc'), ('plate_pend_sat', 'plate_ahc_sat'),
         ('plate_pend_lf', 'plate_ahc'))
# What the liquid's flow changes: the liquidFlow run minus the run with
# the liquid immobile (same sand, water, plate)
LF_PAIR = ('plate_pend_lf', 'plate_pend')
figs = ht.Figures()
out = []


def say(s=''):
    out.append(s)


fmt = ht.fmt


def end_time(case):
    """endTime of the run's controlDict (6 h; 1 h for the liquidFlow run
    of Allrun -liquidFlow1h)"""
    import re
    with open(os.path.join(case, 'system', 'controlDict')) as f:
        return float(re.search(r'\nendTime\s+(\S+);', f.read()).group(1))


def analyse(name):
    """The figures of run/NAME. A run to less than 6 h (-liquidFlow1h)
    gives only what it determines: T at the hours it reached, the
    plateau edges it reached; not the peak."""
    case = os.path.join('run', name)
    s = ht.sensors_of(case)
    t = s['time_s']
    end = end_time(case)
    if abs(t[-1] - end) > 1e-6*end:
        raise SystemExit('results.py: run/%s stopped at t = %g s, not %g'
                         % (name, t[-1], end))
    full = abs(end - END) <= 1e-6*END
    r = {}
    for sen in SENSORS:
        T = s['d' + sen]
        a, b = ht.crossing(t, T, 95.0), ht.crossing(t, T, 105.0)
        r['start_' + sen] = None if a is None else a/60.0
        r['end_' + sen] = None if b is None else b/60.0
        r['plateau_' + sen] = None if a is None or b is None else (b - a)/60.0
        if not full:
            for k in ('start', 'end', 'plateau'):
                if r[k + '_' + sen] is None:
                    del r[k + '_' + sen]
        for h in (1, 3, 6):
            if h*HOUR <= end*(1 + 1e-9):
                r['T%dh_%s' % (h, sen)] = ht.interpolate(t, T, h*HOUR)
        if full:
            r['peak_' + sen] = ht.peak(t, T)[0]
    log = os.path.join(case, 'log.pendularFoam')
    if os.path.exists(log):
        r.update(('balance_' + k, v) for k, v in
                 ht.worst_pendular_imbalances(log).items())
    else:
        b = ht.energy_balance(os.path.join(case, 'log.ahcFoam'))
        r['balance_energy'] = abs(b['relative'])
    for k, v in r.items():
        unit = 'min' if k.split('_')[0] in ('start', 'end', 'plateau') \
            else '-' if k.startswith('balance') else 'C'
        figs.add('%s.%s' % (name, k), v, unit)
    return r


nCells = int(open('run/nCells').read())
say('mansourPlate: 1-D column under the centre of the 400 C plate, %d cells'
    % nCells)
say()
res = [(name, label, analyse(name)) for name, label in RUNS
       if os.path.isdir(os.path.join('run', name))]

for sen in SENSORS:
    say('Sensor at %s' % sen)
    say('| run | 95 C [min] | 105 C [min] | plateau [min] | T 1 h [C] '
        '| T 3 h [C] | T 6 h [C] | peak [C] |')
    say('|---|---|---|---|---|---|---|---|')
    for name, label, r in res:
        say('| %s | %s | %s | %s | %s | %s | %s | %s |' % (
            label, fmt(r.get('start_' + sen), '%.0f'),
            fmt(r.get('end_' + sen), '%.0f'),
            fmt(r.get('plateau_' + sen), '%.0f'),
            fmt(r.get('T1h_' + sen), '%.1f'),
            fmt(r.get('T3h_' + sen), '%.1f'),
            fmt(r.get('T6h_' + sen), '%.1f'),
            fmt(r.get('peak_' + sen), '%.1f')))
    say()

def minus(r, ref, prefix, title):
    """The figures of run r minus those of the reference run ref (each
    plateau edge, plateau, T at 1, 3, 6 h, peak that both have) as
    figures PREFIX.<key>_<sensor>, and their line of results.txt"""
    say(title)
    for sen in SENSORS:
        d = {}
        for k in ('start', 'end', 'plateau', 'T1h', 'T3h', 'T6h', 'peak'):
            if k + '_' + sen not in r:
                d[k] = None
                continue
            a, b = ref[k + '_' + sen], r[k + '_' + sen]
            d[k] = None if a is None or b is None else b - a
            figs.add('%s.%s_%s' % (prefix, k, sen), d[k],
                     'min' if k in ('start', 'end', 'plateau') else 'C')
        say('  %-6s: 95 C %s min, 105 C %s min, plateau %s min, '
            'T 1/3/6 h %s/%s/%s C, peak %s C' % (
                sen, fmt(d['start'], '%+.0f'), fmt(d['end'], '%+.0f'),
                fmt(d['plateau'], '%+.0f'), fmt(d['T1h'], '%+.1f'),
                fmt(d['T3h'], '%+.1f'), fmt(d['T6h'], '%+.1f'),
                fmt(d['peak'], '%+.1f')))
    say()


# What the coupled model changes: pendularFoam minus ahcFoam
byName = dict((name, r) for name, _, r in res)
for name, label, r in res:
    if name in dict(PAIRS):
        minus(r, byName[dict(PAIRS)[name]], name + '.minusAhc',
              '%s minus ahcFoam:' % label)

# What the liquid's flow changes: the liquidFlow run minus the run with
# the liquid immobile
if LF_PAIR[0] in byName and LF_PAIR[1] in byName:
    minus(byName[LF_PAIR[0]], byName[LF_PAIR[1]], LF_PAIR[0] + '.minusPend',
          'liquidFlow minus the liquid immobile (pendularFoam):')


def water_distribution(name):
    """Where the water of the liquidFlow run goes, at 0, 1, 3, 6 h: the
    height of the saturated zone (liquid-only cells, gasPresent 0, from
    the closed bottom up to the first cell with gas), the water out
    through the plate (the balance pendularFoam prints) and the water in
    the column, in kg per m2 of the column's cross-section."""
    import equilibrium
    case = os.path.join('run', name)
    faces = equilibrium.distinct_y(case)
    xs, zs = equilibrium.extent(case)
    area = xs*zs
    bal = dict((round(b['time']), b['water'])
               for b in ht.pendular_balances(os.path.join(case,
                                                          'log.pendularFoam')))
    say('Where the water goes (%s): saturated zone from the bottom, '
        'water out through the plate and in the column [kg/m2]' % name)
    # the water at the start: in the domain minus its stored change at
    # the first balance pendularFoam prints
    first = bal[min(bal)]
    w0 = (first['inDomain'] - first['stored'])/area
    figs.add('%s.waterInColumn_0h' % name, w0, 'kg/m2')
    say('  at the start: %.2f kg/m2 in the column' % w0)
    end = end_time(case)
    for h in (h for h in (0, 1, 3, 6) if h*HOUR <= end*(1 + 1e-9)):
        t = '0' if h == 0 else '%d' % (h*HOUR)
        gas = ht.read_internal_field(os.path.join(case, t, 'gasPresent'))
        gas = gas*(len(faces) - 1) if len(gas) == 1 else gas
        k = 0
        while k < len(gas) and gas[k] < 0.5:
            k += 1
        height = 100*(faces[k] - faces[0])
        figs.add('%s.saturatedHeight_%dh' % (name, h), height, 'cm')
        if h > 0:
            w = bal[round(h*HOUR)]
            out_ = w['out_plate']/area
            figs.add('%s.waterOutPlate_%dh' % (name, h), out_, 'kg/m2')
            say('  %d h: saturated %.2f cm, out through the plate %.2f, '
                'in the column %.2f' % (h, height, out_,
                                        w['inDomain']/area))
        else:
            say('  0 h: saturated %.2f cm' % height)
    say()


if LF_PAIR[0] in byName:
    water_distribution(LF_PAIR[0])

# The equilibrium start kept isothermal 20 s (Allrun with -liquidFlow*):
# the largest change of alpha_l over the cells, and where
REST = 'plate_pend_rest'
if os.path.isdir(os.path.join('run', REST)):
    case = os.path.join('run', REST)
    a0 = ht.read_internal_field(os.path.join(case, '0', 'alphaL'))
    a1 = ht.read_internal_field(os.path.join(case, '20', 'alphaL'))
    d = [abs(x - y) for x, y in zip(a1, a0)]
    k = max(range(len(d)), key=lambda i: d[i])
    figs.add(REST + '.alphaLChange_20s', d[k], '-')
    dInner = max(d[:k] + d[k + 1:]) if len(d) > 1 else 0.0
    figs.add(REST + '.alphaLChangeOthers_20s', dInner, '-')
    say('%s: the equilibrium start isothermal for 20 s: alpha_l changes '
        'by at most %.2g (cell %d of %d from the bottom), %.2g in the '
        'other cells' % (REST, d[k], k + 1, len(d), dInner))
    say()

# The water out through the plate of the immobile-liquid run (to compare)
if LF_PAIR[1] in byName:
    import equilibrium
    case = os.path.join('run', LF_PAIR[1])
    xs, zs = equilibrium.extent(case)
    bal = dict((round(b['time']), b['water']) for b in
               ht.pendular_balances(os.path.join(case, 'log.pendularFoam')))
    outs = []
    for h in (1, 3, 6):
        v = bal[round(h*HOUR)]['out_plate']/(xs*zs)
        figs.add('%s.waterOutPlate_%dh' % (LF_PAIR[1], h), v, 'kg/m2')
        outs.append('%.2f' % v)
    say('%s: water out through the plate at 1, 3, 6 h: %s kg/m2'
        % (LF_PAIR[1], ', '.join(outs)))
    say()

say('Largest relative imbalance (every write)')
say('| run | water | air | energy |')
say('|---|---|---|---|')
for name, label, r in res:
    say('| %s | %s | %s | %s |' % (
        label, fmt(r.get('balance_water'), '%.1e'),
        fmt(r.get('balance_air'), '%.1e'), fmt(r.get('balance_energy'), '%.1e')))
say()

# The run expected to stop: where it stopped (README, "What does not run")
for name in ('plate_pend_sat999',):
    log = os.path.join('run', name, 'log.pendularFoam')
    if not os.path.exists(log):
        continue
    times = [float(l.split()[2]) for l in open(log) if l.startswith('Time = ')]
    status = int(open(os.path.join('run', name, 'status')).read())
    figs.add(name + '.stopTime', times[-1] if times else 0.0, 's')
    figs.add(name + '.status', status, '-')
    say('%s: stopped at t = %.1f s (exit status %d)'
        % (name, times[-1] if times else 0.0, status))
say()

open('results.txt', 'w').write('\n'.join(out) + '\n')
figs.write('figures.csv')
