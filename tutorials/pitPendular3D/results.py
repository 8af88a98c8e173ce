#!/usr/bin/env python3
"""pitPendular3D: summary of a finished (reconstructed) run.

    python3 results.py NPROCS WALL_SECONDS

Reads sensors.csv (the thermocouples, C), postProcessing/probes/0/alphaL
and log.pendularFoam (steps, balances); prints the summary (results.txt).
Standard library only.
"""

import re
import sys

SECTORS = 4     # quarter domain


def first_time(rows, col, level):
    prev = None
    for r in rows:
        if r[col] >= level:
            if prev is None:
                return r[0]
            f = (level - prev[col])/(r[col] - prev[col])
            return prev[0] + f*(r[0] - prev[0])
        prev = r
    return None


def fmt_h(t):
    return '%.1f min' % (t/60) if t is not None else '-'


def main():
    nprocs, wall = sys.argv[1], sys.argv[2]
    with open('sensors.csv') as f:
        names = f.readline().strip().split(',')[1:]
        rows = [[float(x) for x in l.split(',')] for l in f if l.strip()]
    log = open('log.pendularFoam').read()
    steps = re.findall(r'pendularFoam: deltaT = \S+, iterations = (\d+), '
                       r'sub-steps = (\d+), rejected = (\d+)', log)
    iters = sum(int(s[0]) for s in steps)
    rejected = sum(int(s[2]) for s in steps)
    out = []
    p = out.append
    p('pitPendular3D: pendularFoam, %s rank(s), %s s wall time (mesh to'
      ' reconstructPar)' % (nprocs, wall))
    p('  %d steps, %d nonlinear iterations (%.1f per step), %d rejected'
      ' sub-steps' % (len(steps), iters, iters/max(len(steps), 1), rejected))
    p('')
    p('Sensors: t(95 C), t(105 C), time between (the 100 C plateau), T at'
      ' the end (%.1f h)' % (rows[-1][0]/3600))
    p('%-12s %10s %10s %10s %9s' % ('sensor', 't95', 't105', 'plateau',
                                    'T_end'))
    for i, n in enumerate(names, start=1):
        t95, t105 = first_time(rows, i, 95), first_time(rows, i, 105)
        pl = ('%6.1f min' % ((t105 - t95)/60) if t95 is not None
              and t105 is not None else '-')
        p('%-12s %10s %10s %10s %7.1f C' % (n, fmt_h(t95), fmt_h(t105), pl,
                                         rows[-1][i]))
    # liquid fraction under the floor: the condensation peak at each probe
    try:
        with open('postProcessing/probes/0/alphaL') as f:
            depths, data = [], []
            for line in f:
                m = re.match(r'#\s*Probe\s+\d+\s+\((\S+) (\S+) (\S+)\)', line)
                if m:
                    depths.append(-100*(float(m.group(3)) + 0.25))
                elif not line.startswith('#') and line.strip():
                    data.append([float(x) for x in line.split()])
        p('')
        p('alpha_l under the centre of the floor (initially 0.01): largest'
          ' value (condensation ahead of the front), its time, value at the'
          ' end')
        for j, d in enumerate(depths, start=1):
            mx = max(data, key=lambda r: r[j])
            p('  %4.0f cm: max %.4f at %.2f h, end %.4f'
              % (d, mx[j], mx[0]/3600, data[-1][j]))
    except OSError:
        pass
    # balances at the last write time
    blocks = log.split('Water balance at t = ')
    if len(blocks) > 1:
        last = blocks[-1]
        t = last.split()[0]
        water = last.split('Air balance')[0]
        energy = last.split('Energy balance')[1] if 'Energy balance' in last \
            else ''
        p('')
        p('Balances at t = %s s (whole pit, x %d the quarter):' % (t, SECTORS))
        for m in re.finditer(r'out through (\S+) = (\S+)', water):
            if m.group(1).startswith('proc'):
                continue
            p('  water out through %-10s %8.3f kg' % (m.group(1),
                                                     SECTORS*float(m.group(2))))
        m = re.search(r'imbalance\s+= \S+ \(relative (\S+)\)', water)
        if m:
            p('  water imbalance (relative) %s' % m.group(1))
        eout = {m.group(1): float(m.group(2)) for m in re.finditer(
            r'out through (\S+) = (\S+)', energy)
            if not m.group(1).startswith('proc')}
        fire = [k for k in ('floor', 'wallsLower', 'walls') if k in eout]
        p('  energy in through the fire (%s): %.2f MJ'
          % (' + '.join(fire), -SECTORS*sum(eout[k] for k in fire)/1e6))
        for k in eout:
            if k not in fire:
                p('  energy out through %-10s %.3f MJ'
                  % (k, SECTORS*eout[k]/1e6))
        m = re.search(r'imbalance\s+= \S+ \(relative (\S+)\)', energy)
        if m:
            p('  energy imbalance (relative) %s' % m.group(1))
        m = re.search(r'Pendular range: (\d+) cells', last)
        if m:
            p('  cells above the pendular limit (alpha_l > 0.05): %s'
              % m.group(1))
    print('\n'.join(out))


if __name__ == '__main__':
    main()
