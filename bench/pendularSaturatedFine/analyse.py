#!/usr/bin/env python3
"""bench/pendularSaturatedFine: what each run reached (see run)."""
import os
import re
import sys

runDir = sys.argv[1]
testDir = sys.argv[2] if len(sys.argv) > 2 else ''
H = 0.1
V = 0.1*0.01*0.01
# tests/pendularSaturatedDrying/check.py's bounds
newtonFloor = {'Water': 1e-11*260*V,
               'Air': 0.26*0.029*1e-4*V/(8.31*293),
               'Energy': 3e6*1e-7*V}


def field(d, t, name):
    s = open(os.path.join(d, t, name)).read()
    n = int(re.search(r'nCells\s+(\d+);', open(os.path.join(
        d, 'system', 'blockMeshDict')).read()).group(1))
    m = re.search(r'internalField\s+uniform\s+(\S+);', s)
    if m:
        return [float(m.group(1))]*n
    m = re.search(r'internalField\s+nonuniform\s+List<scalar>\s*\d+\s*'
                  r'\((.*?)\)\s*;', s, re.S)
    return [float(v) for v in m.group(1).split()]


def at(values, z):
    """Linear in depth z between the centres of a uniform mesh."""
    n = len(values)
    pts = sorted(zip([H - (i + 0.5)*H/n for i in range(n)], values))
    for (z0, v0), (z1, v1) in zip(pts, pts[1:]):
        if z0 <= z <= z1:
            return v0 + (v1 - v0)*(z - z0)/(z1 - z0)
    raise ValueError(z)


def report(d, name, uniform):
    log = open(os.path.join(d, 'log.pendularFoam')).read()
    times = re.findall(r'^Time = (\S+)', log, re.M)
    steps = re.findall(r'^pendularFoam: .*?iterations = (\d+), .*?'
                       r'rejected = (\d+)', log, re.M)
    it = sum(int(a) for a, b in steps)
    rej = sum(int(b) for a, b in steps)
    osc = log.count('phase state oscillates')
    worst = 0
    blocks = re.findall(
        r'(Water|Air|Energy) balance at t = (\S+) s .*?in the domain\s+=\s+'
        r'(\S+).*?imbalance\s+=\s+(\S+) \(relative (\S+)\)', log, re.S)
    for what, t, c, imb, rel in blocks:
        imb, rel = float(imb), float(rel)
        scale = abs(imb/rel) if rel != 0 else 0
        worst = max(worst, abs(imb)/max(1e-10*scale, newtonFloor[what]))
    print('%-10s reached t = %s s; %d Newton iterations, %d sub-steps'
          ' rejected (%d: phase oscillating); %d balances, worst %.3g of'
          ' its bound' % (name, times[-1] if times else '?', it, rej, osc,
                          len(blocks), worst))
    if uniform and os.path.isdir(os.path.join(d, '600')):
        m = re.search(r'Water balance at t = 600 s \[kg\]:\s*out through '
                      r'top = (\S+)', log)
        print('           T(2 cm, 400 s) %.4f K, T(1 cm, 600 s) %.4f K,'
              ' water out through the top at 600 s %.4g kg/m2'
              % (at(field(d, '400', 'T'), 0.02),
                 at(field(d, '600', 'T'), 0.01), float(m.group(1))/1e-4))


if testDir:
    for n in (10, 20, 40):
        d = os.path.join(testDir, 'cells_%d' % n)
        if os.path.isdir(os.path.join(d, '600')):
            report(d, 'test %d' % n, True)
for name in ('cells_80', 'seed6_80', 'dT1_40', 'bubble_80', 'graded_40'):
    d = os.path.join(runDir, name)
    if os.path.isdir(d):
        report(d, name, not name.startswith('graded'))
