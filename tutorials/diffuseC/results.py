#!/usr/bin/env python3
"""diffuseC: the figures of the runs in run/ (see Allrun).

For each run: T at the 5 cm sensor at 1, 2, 3, 5, 10 h (a fire of
duration D under the constant 300 C surface is the heating curve up to D),
the times at which it reaches 60, 80, 90, 100 C (interpolated between
time steps; 'not reached' in 10 h), and for pendularFoam the largest
relative water, air and energy imbalance of its log and the highest gas
pressure [bar]. For each pendularFoam run, against ahcFoam with the same water
(alpha_l0): T(5 cm) coupled minus AHC at 1, 2, 3, 5, 10 h and the delay
of the times of 60, 80, 90 C. A run that stops: the time it reached.

Writes results.txt (the tables of the README) and figures.csv (every
figure at full precision, name,value,unit).
"""

import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                '..', '..', 'etc', 'python'))
import hearthTutorial as ht

os.chdir(os.path.dirname(os.path.abspath(__file__)))

HOUR = 3600.0
HOURS = (1, 2, 3, 5, 10)
LEVELS = (60, 80, 90, 100)
END = 10*HOUR
figs = ht.Figures()
out = []


def say(s=''):
    out.append(s)


def fmt(x, f='%.2f', none='n.r.'):
    return none if x is None else f % x


def signed(x, f='%+.2f'):
    return 'n.r.' if x is None else f % x


def log_of(name):
    return os.path.join('run', name, 'log.' + (
        'ahcFoam' if name.startswith('ahc') else 'pendularFoam'))


def last_time(log):
    t = 0.0
    with open(log) as f:
        for line in f:
            m = re.match(r'^Time = (\S+)', line)
            if m:
                t = float(m.group(1))
    return t


def max_gas_pressure(log):
    p = None
    with open(log) as f:
        for line in f:
            m = re.search(r'p_g (\S+) to (\S+) Pa', line)
            if m:
                p = max(p or 0.0, float(m.group(2)))
    return p


def sensor(name):
    s = ht.sensors_of(os.path.join('run', name))
    return s['time_s'], s['d5cm']


def figures_of(name):
    """dict of the run's figures (None: not reached), or None if it stopped"""
    log = log_of(name)
    tEnd = last_time(log)
    status = open(os.path.join('run', name, 'status')).read().strip()
    if status != '0' or tEnd < END:
        figs.add(name + '.stopAt', tEnd, 's')
        return None
    t, T = sensor(name)
    r = {}
    for h in HOURS:
        r['T_%dh' % h] = ht.interpolate(t, T, h*HOUR)
        figs.add(name + '.T_%dh' % h, r['T_%dh' % h], 'C')
    for v in LEVELS:
        c = ht.crossing(t, T, v)
        r['t%d' % v] = None if c is None else c/HOUR
        figs.add(name + '.t%d' % v, r['t%d' % v], 'h')
    if 'pendularFoam' in log:
        b = {'water': 0.0, 'air': 0.0, 'energy': 0.0}
        for blk in ht.pendular_balances(log):
            for k in b:
                b[k] = max(b[k], abs(blk[k]['relative']))
        for k in b:
            figs.add(name + '.balance_' + k, b[k], '-')
        r['balance'] = max(b.values())
        r['pMax'] = max_gas_pressure(log)/1e5
        figs.add(name + '.pMax', r['pMax'], 'bar')
    return r


nCells = open('run/nCells').read().strip()


def order(n):
    """ahcFoam, then pendularFoam by alpha_l0 and K, the diagnoses last"""
    a = n.split('_')
    kind = ('ahc', 'pend', 'split', 'immobile').index(a[0])
    K = float(a[2]) if kind in (1, 3) else 0.0
    return (kind, a[1], K)


runs = sorted((d for d in os.listdir('run') if os.path.isdir('run/' + d)),
              key=order)
res = dict((n, figures_of(n)) for n in runs)

say('diffuseC: 300 C at the surface from t = 0, T at 5 cm (%s cells)'
    % nCells)
say()
say('## T at 5 cm and the times it reaches 60, 80, 90, 100 C')
say()
say('| run | alpha_l0 | K liquid, gas [m2] | '
    + ' | '.join('T %d h [C]' % h for h in HOURS) + ' | '
    + ' | '.join('%d C at [h]' % v for v in LEVELS)
    + ' | p_g max [bar] | worst balance |')
say('|' + '---|'*(3 + len(HOURS) + len(LEVELS) + 2))


def describe(n):
    a = n.split('_')
    if a[0] == 'ahc':
        return 'ahcFoam', a[1], '-'
    if a[0] == 'pend':
        return 'pendularFoam', a[1], a[2]
    if a[0] == 'split':
        return 'pendularFoam', '0.99', '%s, %s' % (a[1][2:], a[2][2:])
    return 'pendularFoam, no liquidFlow', a[1], a[2]


for n in runs:
    solver, a0, K = describe(n)
    r = res[n]
    if r is None:
        say('| %s (%s) | %s | %s | stops at t = %.1f s |'
            % (solver, n, a0, K, last_time(log_of(n))))
        continue
    say('| %s (%s) | %s | %s | ' % (solver, n, a0, K)
        + ' | '.join('%.1f' % r['T_%dh' % h] for h in HOURS) + ' | '
        + ' | '.join(fmt(r['t%d' % v]) for v in LEVELS) + ' | '
        + ('%.2f | %.1e |' % (r['pMax'], r['balance'])
           if 'pMax' in r else '- | - |'))
say()
say('n.r.: not reached in 10 h')
say()
say('## Coupled minus AHC (the same alpha_l0): T(5 cm) [K] and the delay'
    ' of 60, 80, 90 C [h]')
say()
say('| run | ' + ' | '.join('dT %d h' % h for h in HOURS) + ' | '
    + ' | '.join('delay %d C' % v for v in LEVELS[:3]) + ' |')
say('|' + '---|'*(1 + len(HOURS) + 3))
for n in runs:
    r = res[n]
    if n.startswith('ahc') or r is None:
        continue
    a0 = describe(n)[1]
    ref = res.get('ahc_' + a0)
    if ref is None:
        continue
    row = []
    for h in HOURS:
        d = r['T_%dh' % h] - ref['T_%dh' % h]
        figs.add(n + '.dT_%dh' % h, d, 'K')
        row.append('%+.1f' % d)
    for v in LEVELS[:3]:
        if r['t%d' % v] is None or ref['t%d' % v] is None:
            d = None
        else:
            d = r['t%d' % v] - ref['t%d' % v]
        figs.add(n + '.delay%d' % v, d, 'h')
        row.append(signed(d))
    say('| %s | ' % n + ' | '.join(row) + ' |')

figs.write('figures.csv')
with open('results.txt', 'w') as f:
    f.write('\n'.join(out) + '\n')
