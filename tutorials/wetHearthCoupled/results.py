#!/usr/bin/env python3
"""wetHearthCoupled: the figures of the runs in run/ (see Allrun).

For each run: the times at which T reaches 290 C (reddening) and 100 C at
the sensors (interpolated between time steps), the 100 C plateau (time
from 95 C to 105 C, as ../flatHearthPendular), the peak T at the sensors
(flat hearth), the depths reached by TMax = 100 C and 290 C at the end of
the fire (6 h) and at the end of the run (interpolated between cell
centres), and for pendularFoam the largest relative water, air and energy
imbalance of its log. For the runs expected to stop (alpha_l0 near 1),
the time reached and the exit status.

Writes results.txt (the tables of the README) and figures.csv (every
figure at full precision, name,value,unit).
"""

import math
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                '..', '..', 'etc', 'python'))
import hearthTutorial as ht

os.chdir(os.path.dirname(os.path.abspath(__file__)))

HOUR = 3600.0
figs = ht.Figures()
out = []


def say(s=''):
    out.append(s)


def profile_at(case, t):
    """(depth [cm], TMax [C]) down the column at time t"""
    d = os.path.join(case, 'postProcessing', 'axisProfile', '%g' % t)
    depth, f = ht.read_axis_set(d)
    return depth, [x - ht.T0 for x in f['TMax']]


def plateau(t, T):
    """minutes from 95 C to 105 C (None if 105 C is not reached)"""
    a, b = ht.crossing(t, T, 95.0), ht.crossing(t, T, 105.0)
    return None if a is None or b is None else (b - a)/60.0


def analyse(name, endTime, sensors, peaks):
    """The figures of run/NAME; returns a dict of them"""
    case = os.path.join('run', name)
    s = ht.sensors_of(case)
    t = s['time_s']
    if abs(t[-1] - endTime) > 1e-6*endTime:
        raise SystemExit('results.py: run/%s stopped at t = %g s, not %g'
                         % (name, t[-1], endTime))
    r = {}
    for sen in sensors:
        r['t290_' + sen] = ht.crossing(t, s['d' + sen], 290.0)
        r['t100_' + sen] = ht.crossing(t, s['d' + sen], 100.0)
        r['plateau_' + sen] = plateau(t, s['d' + sen])
        if peaks:
            r['peak_' + sen] = ht.peak(t, s['d' + sen])[0]
    for key, time in (('6h', 21600.0), ('end', endTime)):
        depth, TMax = profile_at(case, time)
        r['d290_' + key] = ht.depth_reached(depth, TMax, 290.0)
        r['d100_' + key] = ht.depth_reached(depth, TMax, 100.0)
    for k, v in r.items():
        if k.startswith('t'):
            figs.add('%s.%s' % (name, k), None if v is None else v/HOUR, 'h')
        elif k.startswith('plateau'):
            figs.add('%s.%s' % (name, k), v, 'min')
        elif k.startswith('peak'):
            figs.add('%s.%s' % (name, k), v, 'C')
        else:
            figs.add('%s.%s' % (name, k), v, 'cm')
    log = os.path.join(case, 'log.pendularFoam')
    if os.path.exists(log):
        for kind, v in ht.worst_pendular_imbalances(log).items():
            r['balance_' + kind] = v
            figs.add('%s.balance_%s' % (name, kind), v, '-')
    else:
        b = ht.energy_balance(os.path.join(case, 'log.ahcFoam'))
        r['balance_energy'] = abs(b['relative'])
        figs.add('%s.balance_energy' % name, r['balance_energy'], '-')
        r['bottomLoss'] = -b['in_bottom']/b['in_fire']
        figs.add('%s.bottomLoss' % name, 100*r['bottomLoss'], '%')
    return r


fmt = ht.fmt


def table(title, runs, rows):
    ht.table(say, title, runs, rows)


nCells = int(open('run/nCells').read())
say('wetHearthCoupled: 1-D column under the centre of the fire, %d cells'
    % nCells)
say()

# ---- the flat hearth
hearth = [('ahcFoam, saturated (alpha_l0 = 1)',
           analyse('hearth_ahc_1', 86400.0, ('1.5cm', '2.5cm', '3.5cm'), True))]
for a0 in ('0.3', '0.5'):
    hearth.append(('ahcFoam, alpha_l0 = %s' % a0,
                   analyse('hearth_ahc_' + a0, 86400.0,
                           ('1.5cm', '2.5cm', '3.5cm'), True)))
    for K in ('1e-14', '1e-16', '1e-18')[:3 if a0 == '0.3' else 2]:
        hearth.append(('pendularFoam, alpha_l0 = %s, K = %s' % (a0, K),
                       analyse('hearth_pend_%s_%s' % (a0, K), 86400.0,
                               ('1.5cm', '2.5cm', '3.5cm'), True)))
rowsT = [('290 C at %s [h]' % d, 't290_' + d, 1/HOUR, '%.2f')
         for d in ('1.5cm', '2.5cm', '3.5cm')]
rowsP = [('95-105 C at %s [min]' % d, 'plateau_' + d, 1, '%.1f')
         for d in ('1.5cm', '2.5cm', '3.5cm')] \
    + [('peak at %s [C]' % d, 'peak_' + d, 1, '%.1f')
       for d in ('1.5cm', '2.5cm', '3.5cm')]
rowsD = [('TMax 290 C, 6 h [cm]', 'd290_6h', 1, '%.2f'),
         ('TMax 290 C, 24 h [cm]', 'd290_end', 1, '%.2f'),
         ('TMax 100 C, 6 h [cm]', 'd100_6h', 1, '%.2f'),
         ('TMax 100 C, 24 h [cm]', 'd100_end', 1, '%.2f')]
rowsB = [('water', 'balance_water', 1, '%.1e'),
         ('air', 'balance_air', 1, '%.1e'),
         ('energy', 'balance_energy', 1, '%.1e')]
say('Flat hearth (../flatHearthAxi: phi = 0.15, 700 C for 6 h, 24 h)')
say()
table('Reddening times', hearth, rowsT)
table('100 C plateau and peaks', hearth, rowsP)
table('Depths reached', hearth, rowsD)

# What vapour and liquid transport change: pendularFoam minus ahcFoam at
# the same initial water
for a0 in ('0.3', '0.5'):
    ahc = dict(hearth)['ahcFoam, alpha_l0 = %s' % a0]
    for K in ('1e-14', '1e-16', '1e-18')[:3 if a0 == '0.3' else 2]:
        pend = dict(hearth)['pendularFoam, alpha_l0 = %s, K = %s' % (a0, K)]
        for k, unit, sc in (('d290_6h', 'cm', 1), ('d290_end', 'cm', 1),
                            ('t290_3.5cm', 'h', 1/HOUR)):
            figs.add('hearth_pend_%s_%s.minusAhc.%s' % (a0, K, k),
                     (pend[k] - ahc[k])*sc, unit)

# The same with the vapour's diffusion factor of Millington & Quirk (1961)
# (Allrun: runs hearth_pendMQ_*): the runs that reach their end, and the
# stop time of the others
def reached_end(name):
    st = os.path.join('run', name, 'status')
    return not os.path.exists(st) or int(open(st).read()) == 0


SENS_H = ('1.5cm', '2.5cm', '3.5cm')
hearthMQ = []
stoppedMQ = []
for a0, K in (('0.3', '1e-14'), ('0.5', '1e-14'), ('0.5', '1e-16'),
              ('0.9', '1e-14'), ('0.9', '1e-16'), ('0.99', '1e-14'),
              ('0.999', '1e-14')):
    name = 'hearth_pendMQ_%s_%s' % (a0, K)
    if reached_end(name):
        hearthMQ.append((a0, K, 'pendularFoam MQ, alpha_l0 = %s, K = %s'
                         % (a0, K), analyse(name, 86400.0, SENS_H, True)))
    else:
        stoppedMQ.append((name, 'alpha_l0 = %s, K = %s' % (a0, K)))
runsMQ = [hearth[0]] + [(label, r) for _, _, label, r in hearthMQ]
say('Flat hearth, pendularFoam with vapourDiffusionModel millingtonQuirk')
say()
table('Reddening times', runsMQ, rowsT)
table('100 C plateau and peaks', runsMQ, rowsP)
table('Depths reached', runsMQ, rowsD)
table('Largest relative imbalance (every write)', runsMQ, rowsB)
# What transport changes with MQ: minus ahcFoam at the same alpha_l0
# (0.3, 0.5) and minus the SATURATED ahcFoam (the flagship's soil), and
# MQ minus the constant tortuosity at the same alpha_l0 and K
say('pendularFoam (MQ) minus ahcFoam [cm, cm, h]:')
ahcOf = {'0.3': dict(hearth)['ahcFoam, alpha_l0 = 0.3'],
         '0.5': dict(hearth)['ahcFoam, alpha_l0 = 0.5']}
for a0, K, label, r in hearthMQ:
    refs = [('sat', hearth[0][1])]
    if a0 in ahcOf:
        refs.append(('same', ahcOf[a0]))
    for tag, ref in refs:
        # (None: 290 C does not reach 3.5 cm)
        d = [None if r[k] is None else (r[k] - ref[k])*sc
             for k, sc in (('d290_6h', 1), ('d290_end', 1),
                           ('t290_3.5cm', 1/HOUR))]
        for k, v in zip(('d290_6h', 'd290_end', 't290_3.5cm'), d):
            figs.add('hearth_pendMQ_%s_%s.minusAhc%s.%s'
                     % (a0, K, 'Sat' if tag == 'sat' else '', k), v,
                     'h' if k.startswith('t') else 'cm')
        say('  %s minus ahcFoam %s: 290 C depth 6 h %s, 24 h %s,'
            ' 290 C at 3.5 cm %s'
            % (label, 'saturated' if tag == 'sat' else 'alpha_l0 = ' + a0,
               fmt(d[0], '%+.2f'), fmt(d[1], '%+.2f'), fmt(d[2], '%+.2f')))
    cname = 'pendularFoam, alpha_l0 = %s, K = %s' % (a0, K)
    if cname in dict(hearth):
        c = dict(hearth)[cname]
        for k, sc in (('d290_6h', 1), ('d290_end', 1), ('t290_3.5cm', 1/HOUR)):
            figs.add('hearth_pendMQ_%s_%s.minusConstant.%s' % (a0, K, k),
                     None if r[k] is None else (r[k] - c[k])*sc,
                     'h' if k.startswith('t') else 'cm')
say()

# The 1-D column against the axis of ../flatHearthAxi (its README's
# figures, checked by tests/tutorialFlatHearthAxi): 1-D minus axisymmetric
AXI = {'d290_6h': 3.58, 'd290_end': 3.71, 'd100_6h': 5.85, 'd100_end': 6.68}
sat = hearth[0][1]
say('1-D column minus the axis of ../flatHearthAxi (ahcFoam, saturated):')
for k, v in AXI.items():
    figs.add('axi.minus1D.' + k, sat[k] - v, 'cm')
    say('  %s: %.2f cm (1-D %.2f, axisymmetric %.2f)' % (k, sat[k] - v, sat[k], v))
say()

table('Largest relative imbalance (every write)', hearth, rowsB)
say('Heat out through the bottom (60 cm) in the saturated ahcFoam run: '
    '%.2f %% of the heat in through the fire'
    % (100*hearth[0][1]['bottomLoss']))
say()

# ---- the runs near saturation, expected to stop
def stops(name, label):
    """The run expected to stop: where it stopped"""
    d = os.path.join('run', name)
    status = int(open(os.path.join(d, 'status')).read())
    with open(os.path.join(d, 'log.pendularFoam')) as f:
        log = f.read()
    times = re.findall(r'^Time = (\S+)', log, re.M)
    reached = float(times[-1]) if times else 0.0
    stopped = 'Nonlinear iterations failed' in log
    say('  %s: %s at t = %.0f s (exit status %d)'
        % (label, 'stops (Newton not converged, deltaT below minDeltaT)'
           if stopped else 'still running after 60 s wall', reached,
           status))
    if stopped:
        figs.add(name + '.stopsAt', reached, 's')


say('pendularFoam near saturation (flat hearth, K = 1e-14 m2):')
for a0 in ('0.9', '0.99', '0.999'):
    stops('hearth_pend_%s_1e-14' % a0, 'alpha_l0 = ' + a0)
# The diagnosis of those stops: the Fick diffusion nearly off
name = 'hearth_pend_0.9_1e-14_tau1e-3'
with open(os.path.join('run', name, 'log.pendularFoam')) as f:
    times = re.findall(r'^Time = (\S+)', f.read(), re.M)
say('  alpha_l0 = 0.9, tortuosity 1e-3 (Fick diffusion nearly off): runs'
    ' to t = %.0f s' % float(times[-1]))
figs.add(name + '.end', float(times[-1]), 's')
for kind, v in ht.worst_pendular_imbalances(
        os.path.join('run', name, 'log.pendularFoam')).items():
    figs.add('%s.balance_%s' % (name, kind), v, '-')
say('pendularFoam (MQ) near saturation, flat hearth:')
for name, label in stoppedMQ:
    stops(name, label)
say('pendularFoam, flat hearth, alpha_l0 = 0.5, K = 1e-18 m2:')
stops('hearth_pend_0.5_1e-18', 'K = 1e-18')
say()

# The flagship's own saturated soil with the saturated zone (Allrun: runs
# hearth_pendSat_1_*, saturatedZone, MQ, started at rest): its figures
# against the saturated ahcFoam column, or where it stops; and the liquid
# near the critical point: the hottest cell holding liquid (alpha_l > 0)
# and the hottest liquid-only cell at the writes (hourly), and the
# sub-steps the solver rejected for liquid near the critical point
# (pendularMedium::liquidNearCritical) in its log
def wet_cells(case):
    """(largest T of a cell with alpha_l > 0, largest T of a liquid-only
    cell) over the written times but 0 [C], the largest gas pressure
    [bar] and the number of liquid-only cells at each written time"""
    wet, liquidOnly, pMax, nLiquidOnly = -ht.T0, -ht.T0, 0.0, {}
    for d in ht.time_dirs(case):
        if float(os.path.basename(d)) == 0:
            continue
        T = ht.read_internal_field(os.path.join(d, 'T'))
        a = ht.read_internal_field(os.path.join(d, 'alphaL'))
        g = ht.read_internal_field(os.path.join(d, 'gasPresent'))
        p = ht.read_internal_field(os.path.join(d, 'p'))
        a, g, p = [f*len(T) if len(f) == 1 else f for f in (a, g, p)]
        for Tc, ac, gc, pc in zip(T, a, g, p):
            if ac > 0:
                wet = max(wet, Tc - ht.T0)
            if gc < 0.5:
                liquidOnly = max(liquidOnly, Tc - ht.T0)
            else:
                pMax = max(pMax, pc/1e5)
        nLiquidOnly[float(os.path.basename(d))] = sum(gc < 0.5 for gc in g)
    return wet, liquidOnly, pMax, nLiquidOnly


def saturated_zone(name, label, endTime, sensors, peaks, ref, diffs):
    """The figures of a saturated-zone run (hearth_pendSat_*, pit_pendSat_*)
    if it reaches endTime, with DIFFS (figure keys) minus REF (the
    saturated ahcFoam column's), or where it stops; then its liquid near
    the critical point, largest gas pressure and liquid-only cells at the
    hourly writes. Returns the figures (None if it stops)"""
    r = None
    if reached_end(name):
        r = analyse(name, endTime, sensors, peaks)
        for k in diffs:
            sc = 1/HOUR if k.startswith('t') else 1
            figs.add('%s.minusAhcSat.%s' % (name, k),
                     None if r[k] is None or ref[k] is None
                     else (r[k] - ref[k])*sc,
                     'h' if k.startswith('t') else 'cm')
    else:
        say('pendularFoam with the saturated zone:')
        stops(name, label)
    case = os.path.join('run', name)
    wet, liquidOnly, pMax, nLiquidOnly = wet_cells(case)
    with open(os.path.join(case, 'log.pendularFoam')) as f:
        critical = f.read().count('near the critical point')
    figs.add(name + '.TwetMax', wet, 'C')
    figs.add(name + '.TliquidOnlyMax', liquidOnly, 'C')
    figs.add(name + '.criticalRejections', critical, '-')
    figs.add(name + '.pgMax', pMax, 'bar')
    hours = [t for t in (3600.0, 21600.0, 86400.0) if t <= endTime]
    for t in hours:
        figs.add('%s.liquidOnlyCells_%gh' % (name, t/HOUR),
                 nLiquidOnly.get(t), '-')
    say('  %s: largest gas pressure at the writes %.2f bar; liquid-only'
        ' cells at %s h: %s' % (label, pMax,
                                ', '.join('%g' % (t/HOUR) for t in hours),
                                ', '.join(str(nLiquidOnly.get(t))
                                          for t in hours)))
    say('  %s: hottest cell holding liquid at the writes %.1f C, hottest'
        ' liquid-only cell %.1f C; sub-steps rejected for liquid near the'
        ' critical point: %d' % (label, wet, liquidOnly, critical))
    return r


hearthSat = []
for K in ('1e-14', '1e-16'):
    name = 'hearth_pendSat_1_%s' % K
    if not os.path.isdir(os.path.join('run', name)):
        continue
    label = 'pendularFoam saturatedZone, alpha_l0 = 1, K = %s' % K
    r = saturated_zone(name, label, 86400.0, SENS_H, True, hearth[0][1],
                       ('d290_6h', 'd290_end', 't290_3.5cm'))
    if r is not None:
        hearthSat.append((label, r))
if hearthSat:
    runsSat = [hearth[0]] + hearthSat
    say('Flat hearth, the saturated soil with the saturated zone (MQ)')
    say()
    table('Reddening times', runsSat, rowsT)
    table('100 C plateau and peaks', runsSat, rowsP)
    table('Depths reached', runsSat, rowsD)
    table('Largest relative imbalance (every write)', hearthSat, rowsB)
say()

# ---- the pit
pit = [('ahcFoam, saturated (alpha_l0 = 1)',
        analyse('pit_ahc_1', 21600.0, ('2cm', '4cm'), False)),
       ('ahcFoam, alpha_l0 = 0.5',
        analyse('pit_ahc_0.5', 21600.0, ('2cm', '4cm'), False))]
for K in ('1e-14', '1e-16'):
    pit.append(('pendularFoam, alpha_l0 = 0.5, K = %s' % K,
                analyse('pit_pend_0.5_' + K, 21600.0, ('2cm', '4cm'), False)))
say('Wet pit (../pitDuration: phi = 0.10, 700 C from t = 0, 6 h)')
say()
table('Times and depth', pit,
      [('290 C at 2 cm [h]', 't290_2cm', 1/HOUR, '%.2f'),
       ('290 C at 4 cm [h]', 't290_4cm', 1/HOUR, '%.2f'),
       ('100 C at 2 cm [h]', 't100_2cm', 1/HOUR, '%.2f'),
       ('100 C at 4 cm [h]', 't100_4cm', 1/HOUR, '%.2f'),
       ('TMax 290 C, 6 h [cm]', 'd290_6h', 1, '%.2f')])
table('Largest relative imbalance (every write)', pit, rowsB)
ahc = pit[1][1]
for K, (_, pend) in zip(('1e-14', '1e-16'), pit[2:]):
    for k in ('t290_2cm', 't290_4cm'):
        figs.add('pit_pend_0.5_%s.minusAhc.%s' % (K, k), (pend[k] - ahc[k])/HOUR, 'h')
# The pit with millingtonQuirk
pitMQ = []
for a0 in ('0.5', '0.9', '0.99'):
    name = 'pit_pendMQ_%s_1e-14' % a0
    if not os.path.isdir(os.path.join('run', name)):
        continue
    if reached_end(name):
        r = analyse(name, 21600.0, ('2cm', '4cm'), False)
        pitMQ.append(('pendularFoam MQ, alpha_l0 = %s, K = 1e-14' % a0, r))
        for tag, ref in (('Sat', pit[0][1]),) + \
                ((('', ahc),) if a0 == '0.5' else ()):
            for k in ('t290_2cm', 't290_4cm'):
                figs.add('%s.minusAhc%s.%s' % (name, tag, k),
                         (r[k] - ref[k])/HOUR, 'h')
    else:
        say('pendularFoam (MQ), pit:')
        stops(name, 'alpha_l0 = ' + a0)
if pitMQ:
    table('Pit, pendularFoam with millingtonQuirk', [pit[0], pit[1]] + pitMQ,
          [('290 C at 2 cm [h]', 't290_2cm', 1/HOUR, '%.2f'),
           ('290 C at 4 cm [h]', 't290_4cm', 1/HOUR, '%.2f'),
           ('100 C at 2 cm [h]', 't100_2cm', 1/HOUR, '%.2f'),
           ('100 C at 4 cm [h]', 't100_4cm', 1/HOUR, '%.2f'),
           ('TMax 290 C, 6 h [cm]', 'd290_6h', 1, '%.2f')])
    table('Largest relative imbalance (every write)', pitMQ, rowsB)
# The pit's saturated soil with the saturated zone (Allrun: runs
# pit_pendSat_1_*, as hearth_pendSat_1_*): minus the saturated ahcFoam
# column (pit_ahc_1, the seed's minimal duration: 290 C at 4 cm)
pitSat = []
for K in ('1e-14', '1e-16'):
    name = 'pit_pendSat_1_%s' % K
    if not os.path.isdir(os.path.join('run', name)):
        continue
    label = 'pendularFoam saturatedZone, pit, alpha_l0 = 1, K = %s' % K
    r = saturated_zone(name, label, 21600.0, ('2cm', '4cm'), False,
                       pit[0][1], ('t290_2cm', 't290_4cm', 'd290_6h',
                                   'd100_6h'))
    if r is not None:
        pitSat.append((label, r))
if pitSat:
    table('Pit, the saturated soil with the saturated zone (MQ)',
          [pit[0]] + pitSat,
          [('290 C at 2 cm [h]', 't290_2cm', 1/HOUR, '%.2f'),
           ('290 C at 4 cm [h]', 't290_4cm', 1/HOUR, '%.2f'),
           ('100 C at 2 cm [h]', 't100_2cm', 1/HOUR, '%.2f'),
           ('100 C at 4 cm [h]', 't100_4cm', 1/HOUR, '%.2f'),
           ('TMax 290 C, 6 h [cm]', 'd290_6h', 1, '%.2f'),
           ('TMax 100 C, 6 h [cm]', 'd100_6h', 1, '%.2f')])
    table('Largest relative imbalance (every write)', pitSat, rowsB)
say('pendularFoam, pit, alpha_l0 = 0.5, K = 1e-18 m2:')
stops('pit_pend_0.5_1e-18', 'K = 1e-18')
say()

open('results.txt', 'w').write('\n'.join(out) + '\n')
figs.write('figures.csv')
print('\n'.join(out))
