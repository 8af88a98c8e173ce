#!/usr/bin/env python3
"""mansourM2: the figures of the runs in run/ (see Allrun).

The drying interface xi(t) of a pendularFoam run: the first depth, from
the wall down, where alpha_l crosses alpha_l0/2 (half its initial value
below the dry layer), linear between cell centres, at every step; of the
ahcFoam run: the depth where T = 100 C (every 10 min; its sensors' phase
change: T = 100 C there). For each sensor
(0.75, 1.25, 2 cm) its phase change: the time at which xi(t) passes the
sensor's depth (linear between writes) and the sensor's T then. The
pressure rise at the bottom (the last cell, 19.95 cm at 200 cells), in
atm: its mean over the 4th hour and its largest value (it pulses as each
cell dries).
The cycles: sensor 1's largest T in each heating and smallest in each
cooling, xi at the end of each stage. For pendularFoam the largest
relative water, air and energy imbalance of its log (relative to what its log divides by: the net exchange
through the patches, or the change stored) and the largest air imbalance
relative to the air held in the column (the air barely moves: its net
exchange is 1e-2 of it).

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

ATM = 101325.0
ALPHA0 = 0.99
SENSORS = ('0.75cm', '1.25cm', '2cm')
DEPTHS = (0.75, 1.25, 2.0)
figs = ht.Figures()
out = []


def say(s=''):
    out.append(s)


def front(depth, f, level):
    """First depth [cm] from the top at which f rises through level,
    linear between the points; None if never"""
    for i in range(1, len(depth)):
        if f[i - 1] < level <= f[i]:
            return depth[i - 1] + (level - f[i - 1])/(f[i] - f[i - 1]) \
                * (depth[i] - depth[i - 1])
    return None


def interface(case, ahc):
    """(times [s], xi [cm]): pendularFoam at every step (the probes of
    alpha_l at every cell centre), ahcFoam at every write (T profiles)"""
    if not ahc:
        locs, ts, cols = ht.read_probes(os.path.join(
            case, 'postProcessing', 'column', '0', 'alphaL'))
        depth = [-100*l[1] for l in locs]
        xs = [front(depth, [c[k] for c in cols], 0.5*ALPHA0)
              for k in range(len(ts))]
        return ts, xs
    ts, xs = [], []
    for d in ht.time_dirs(os.path.join(case, 'postProcessing', 'axisProfile')):
        depth, f = ht.read_axis_set(d)
        # T falls with depth: the crossing of -T through -100 C
        ts.append(float(os.path.basename(d)))
        xs.append(front(depth, [-(T - ht.T0) for T in f['T']], -100.0))
    return ts, xs


def passage(ts, xs, depth):
    """Time at which xi(t) reaches depth, linear between samples"""
    return ht.crossing(ts, [-1.0 if x is None else x for x in xs], depth)


def time_mean(t, f, a, b):
    """Mean of f over a < t <= b (trapezoidal, samples as given)"""
    s, w = 0.0, 0.0
    for i in range(1, len(t)):
        if t[i - 1] >= a and t[i] <= b:
            s += 0.5*(f[i] + f[i - 1])*(t[i] - t[i - 1])
            w += t[i] - t[i - 1]
    return s/w


def analyse(name, endTime, cycles=False):
    case = os.path.join('run', name)
    ahc = os.path.exists(os.path.join(case, 'log.ahcFoam'))
    s = ht.sensors_of(case)
    t = s['time_s']
    if abs(t[-1] - endTime) > 1e-6*endTime:
        raise SystemExit('results.py: run/%s stopped at t = %g s, not %g'
                         % (name, t[-1], endTime))
    ts, xs = interface(case, ahc)
    r = {}
    if not cycles:
        r['xi_4h'] = ht.interpolate(ts, xs, 14400.0)
        figs.add(name + '.xi_4h', r['xi_4h'], 'cm')
        for sen, depth in zip(SENSORS, DEPTHS):
            # ahcFoam: T at the sensor reaches 100 C (the front passes)
            tp = ht.crossing(t, s['d' + sen], 100.0) if ahc \
                else passage(ts, xs, depth)
            r['tpc_' + sen] = tp
            r['Tpc_' + sen] = None if tp is None \
                else ht.interpolate(t, s['d' + sen], tp)
            figs.add('%s.tpc_%s' % (name, sen), None if tp is None else tp/60, 'min')
            figs.add('%s.Tpc_%s' % (name, sen), r['Tpc_' + sen], 'C')
        r['Tbottom_4h'] = s['d19.95cm'][-1]
        figs.add(name + '.Tbottom_4h', r['Tbottom_4h'], 'C')
        if not ahc:
            # the front cell at 4 h (the first with alpha_l above
            # alpha_l0/2): its alpha_l, T and vapour share of the gas
            depth, f = ht.read_axis_set(os.path.join(
                case, 'postProcessing', 'axisProfile', '14400'))
            i = next(k for k, a in enumerate(f['alphaL']) if a > 0.5*ALPHA0)
            r['front_alphaL'] = f['alphaL'][i]
            r['front_T'] = f['T'][i] - ht.T0
            r['front_pwp'] = f['pw'][i]/f['p'][i]
            figs.add(name + '.front_alphaL_4h', r['front_alphaL'], '-')
            figs.add(name + '.front_T_4h', r['front_T'], 'C')
            figs.add(name + '.front_pw_p_4h', 100*r['front_pwp'], '%')
            _, pt, pc = ht.read_probes(os.path.join(case, 'postProcessing',
                                                    'bottom', '0', 'p'))
            dp = [(p - ATM)/ATM for p in pc[0]]
            r['dp_bottom_mean'] = time_mean(pt, dp, 10800.0, 14400.0)
            r['dp_bottom_max'] = max(dp)
            figs.add(name + '.dp_bottom_mean', r['dp_bottom_mean'], 'atm')
            figs.add(name + '.dp_bottom_max', r['dp_bottom_max'], 'atm')
    else:
        stages = ((0, 3600, 'heat1'), (3600, 18000, 'cool1'),
                  (18000, 21600, 'heat2'), (21600, 36000, 'cool2'))
        T1 = s['d0.75cm']
        for a, b, key in stages:
            v = [T for ti, T in zip(t, T1) if a < ti <= b]
            r['T1_' + key] = max(v) if key.startswith('heat') else min(v)
            figs.add('%s.T1_%s' % (name, key), r['T1_' + key], 'C')
            r['xi_' + key] = 10*ht.interpolate(ts, xs, float(b))
            figs.add('%s.xi_%s' % (name, key), r['xi_' + key], 'mm')
    if not ahc:
        for kind, v in ht.worst_pendular_imbalances(
                os.path.join(case, "log.pendularFoam"), airHeld=True).items():
            r['balance_' + kind] = v
            figs.add('%s.balance_%s' % (name, kind), v, '-')
    else:
        b = ht.energy_balance(os.path.join(case, 'log.ahcFoam'))
        r['balance_energy'] = abs(b['relative'])
        figs.add('%s.balance_energy' % name, r['balance_energy'], '-')
    return r


fmt = ht.fmt


def table(title, runs, rows):
    ht.table(say, title, runs, rows)


nCells = int(open('run/nCells').read())
say('mansourM2: 20 cm column, %d cells' % nCells)
say()
base = [('Mansour (2015) §6.1.3 (M2)', {'xi_4h': 2.33, 'tpc_0.75cm': 26*60.0,
                                         'Tpc_0.75cm': 95.5,
                                         'dp_bottom_mean': 1.4e-3}),]
base.append(('pendularFoam, K_g = 1e-12 m2', analyse('base', 14400.0)))
base.append(('pendularFoam, K_g = 2e-11 m2', analyse('base_2e-11', 14400.0)))
base.append(('pendularFoam, K_g = 1e-12 m2, porosity 0.3',
             analyse('base_phi0.3', 14400.0)))
base.append(('ahcFoam (T = 100 C front)', analyse('base_ahc', 14400.0)))
rows = [('xi(4 h) [cm]', 'xi_4h', 1, '%.2f')]
for sen in SENSORS:
    rows += [('t_pc %s [min]' % sen, 'tpc_' + sen, 1/60.0, '%.1f'),
             ('T_pc %s [C]' % sen, 'Tpc_' + sen, 1, '%.1f')]
rows += [('p_bottom - 1 atm, mean 3-4 h [atm]', 'dp_bottom_mean', 1, '%.1e'),
         ('largest [atm]', 'dp_bottom_max', 1, '%.1e'),
         ('T bottom (4 h) [C]', 'Tbottom_4h', 1, '%.1f')]
table('Base case: 250 C for 4 h', base, rows)
rowsB = [('water', 'balance_water', 1, '%.1e'),
         ('air', 'balance_air', 1, '%.1e'),
         ('energy', 'balance_energy', 1, '%.1e'),
         ('air / air held', 'balance_air_held', 1, '%.1e')]

cyc = [('Mansour (2015) §6.1.3 (M2)', {'T1_heat1': 150.0, 'T1_cool1': 23.0,
                                        'T1_heat2': 178.0, 'T1_cool2': 24.5,
                                        'xi_heat1': 11.6}),
       ('pendularFoam, K_g = 1e-12 m2', analyse('cycles', 36000.0, True))]
rowsC = []
for key, label in (('heat1', 'heating 1'), ('cool1', 'cooling 1'),
                   ('heat2', 'heating 2'), ('cool2', 'cooling 2')):
    rowsC += [('T1 %s [C]' % label, 'T1_' + key, 1, '%.1f'),
              ('xi end of %s [mm]' % label, 'xi_' + key, 1, '%.1f')]
table('Cycles: sensor 1 (0.75 cm) extremes, interface at the end of each stage',
      cyc, rowsC)
table('Largest relative imbalance (every write)',
      [('base, K_g = 1e-12 m2', base[1][1]), ('base, K_g = 2e-11 m2', base[2][1]),
       ('base, porosity 0.3', base[3][1]),
       ('cycles, K_g = 1e-12 m2', cyc[1][1])], rowsB)
say('(ahcFoam energy imbalance at 4 h: %.1e)' % base[4][1]['balance_energy'])

with open('results.txt', 'w') as f:
    f.write('\n'.join(out) + '\n')
figs.write('figures.csv')
