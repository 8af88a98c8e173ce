#!/usr/bin/env python3
"""Summarise the ahcFoam / laplacianFoam benchmark run by Allrun.

    analyse.py RUNDIR NSTEPS
    analyse.py --median SUMMARY.json...   (medians over repeated runs)

Each case RUNDIR/<case> holds log.<solver> and wall.<solver> (stamp.py).
The timed window runs from the end of the first step (start-up, first
assembly) to the end of step NSTEPS - 1 (the last step also writes the fields
and, in ahcFoam, reports the energy balance), i.e. NSTEPS - 2 steps.
The ratios and iteration counts go to RUNDIR/summary.json."""
import json
import os
import re
import statistics
import sys

GOALS = {'ahcOff': 1.5, 'ahcOn': 3.0, 'ahcOnJacobian': 3.0,
         'ahcOnExactSolves': 3.0, 'ahcOnReference': 3.0}
CASES = [
    ('laplacian', 'laplacianFoam', 'laplacianFoam (DT = k/rhoC)'),
    ('ahcOff', 'ahcFoam', 'ahcFoam, phase change off'),
    ('ahcOn', 'ahcFoam', 'ahcFoam, phase change on'),
    ('ahcOnJacobian', 'ahcFoam', 'ahcFoam, on, k Jacobian'),
    ('ahcOnExactSolves', 'ahcFoam', 'ahcFoam, on, linearRelTol 0'),
    ('ahcOnReference', 'ahcFoam', 'ahcFoam REFERENCE, on'),
]

if sys.argv[1] == '--median':
    runs = [json.load(open(f)) for f in sys.argv[2:]]
    print()
    print('Median over %d runs (CPU per step, ratio to laplacianFoam of the '
          'same run; nonlinear iterations per step in the timed window):'
          % len(runs))
    for case, _, label in CASES:
        rs = [r[case] for r in runs if case in r]
        if not rs:
            continue
        line = '%-29s cpu %7.1f ms' % (
            label, statistics.median(x['cpu'] for x in rs)*1e3)
        if case != 'laplacian':
            line += ', ratio %5.2fx (runs: %s)' % (
                statistics.median(x['ratioCpu'] for x in rs),
                ', '.join('%.2fx' % x['ratioCpu'] for x in rs))
        if 'picard' in rs[0]:
            line += ', %.2f it/step' % statistics.median(
                x['picard'] for x in rs)
        print(line)
    sys.exit(0)

runDir = sys.argv[1]
nSteps = int(sys.argv[2])
CASES = [c for c in CASES if os.path.isfile(
    os.path.join(runDir, c[0], 'log.' + c[1]))]

reTime = re.compile(r'^Time = (\S+)')
rePCG = re.compile(r'Solving for T, Initial residual = (\S+), '
                   r'Final residual = (\S+), No Iterations (\d+)')
reAhc = re.compile(r'^ahcFoam: deltaT = (\S+), iterations = (\d+), '
                   r'sub-steps = (\d+), rejected = (\d+)')
reExec = re.compile(r'^ExecutionTime = (\S+) s\s+ClockTime = (\S+) s')
reRej = re.compile(r'step rejected after (\d+) iterations')


def parse(case, solver):
    steps = []
    cur = None
    with open(os.path.join(runDir, case, 'log.' + solver)) as f:
        for line in f:
            m = reTime.match(line)
            if m:
                cur = dict(time=float(m.group(1)), solves=0, pcgIter=0,
                           picard=None, subSteps=None, rejected=None,
                           wasted=0)
                steps.append(cur)
                continue
            if cur is None:
                continue
            m = rePCG.search(line)
            if m:
                cur['solves'] += 1
                cur['pcgIter'] += int(m.group(3))
                continue
            m = reRej.search(line)
            if m:
                cur['wasted'] += int(m.group(1))
                continue
            m = reAhc.match(line)
            if m:
                cur['picard'] = int(m.group(2))
                cur['subSteps'] = int(m.group(3))
                cur['rejected'] = int(m.group(4))
                continue
            m = reExec.match(line)
            if m:
                cur['cpu'] = float(m.group(1))
                cur['clock'] = float(m.group(2))
    with open(os.path.join(runDir, case, 'wall.' + solver)) as f:
        start = float(f.readline().split()[1])
        wall = [float(l) for l in f if l.strip()]
    if len(steps) != nSteps or len(wall) != nSteps:
        sys.exit('%s: %d steps in the log, %d stamps, expected %d'
                 % (case, len(steps), len(wall), nSteps))
    for s, w in zip(steps, wall):
        s['wall'] = w
    return start, steps


def readT(case):
    """Internal field T of the last time directory (ascii)"""
    d = os.path.join(runDir, case)
    times = [t for t in os.listdir(d)
             if re.match(r'^[0-9.eE+-]+$', t) and float(t) > 0]
    t = max(times, key=float)
    txt = open(os.path.join(d, t, 'T')).read()
    m = re.search(r'internalField\s+nonuniform\s+List<scalar>\s*(\d+)\s*\(',
                  txt)
    n = int(m.group(1))
    vals = txt[m.end():].split(None, n)[:n]
    return t, [float(v) for v in vals]


res = {}
for case, solver, label in CASES:
    start, steps = parse(case, solver)
    timed = steps[1:nSteps - 1]
    n = len(timed)
    first, last = steps[0], steps[nSteps - 2]
    r = dict(label=label, n=n,
             startup=first['wall'] - start,
             wall=(last['wall'] - first['wall'])/n,
             cpu=(last['cpu'] - first['cpu'])/n,
             solves=sum(s['solves'] for s in timed)/n,
             pcg=sum(s['pcgIter'] for s in timed)/n)
    if solver == 'ahcFoam':
        r['picard'] = sum(s['picard'] for s in timed)/n
        r['picardAll'] = sum(s['picard'] for s in steps)/len(steps)
        r['subSteps'] = sum(s['subSteps'] for s in steps)
        r['rejected'] = sum(s['rejected'] for s in steps)
        r['picardFirst'] = steps[0]['picard']
        r['rejectedTimed'] = sum(s['rejected'] for s in timed)
        r['wastedTimed'] = sum(s['wasted'] for s in timed)/n
    res[case] = r

lap = res['laplacian']
print()
print('ahcFoam vs laplacianFoam: %d steps per solver, timed window = steps '
      '2..%d (%d steps)' % (nSteps, nSteps - 1, lap['n']))
print()
hdr = ('%-29s %11s %11s %9s %8s %9s %8s'
       % ('case', 'wall/step', 'cpu/step', 'T solves', 'PCG it', 'Picard it',
          'to end of'))
print(hdr)
print('%-29s %11s %11s %9s %8s %9s %8s'
      % ('', '[ms]', '[ms]', '/step', '/step', '/step', 'step 1 [s]'))
print('-'*len(hdr))
for case, _, _ in CASES:
    r = res[case]
    print('%-29s %11.1f %11.1f %9.2f %8.1f %9s %8.2f'
          % (r['label'], 1e3*r['wall'], 1e3*r['cpu'], r['solves'], r['pcg'],
             '%.2f' % r['picard'] if 'picard' in r else '-', r['startup']))
print()
print('%-29s %8s %8s %8s  %s' % ('ratio ahcFoam/laplacianFoam', 'wall', 'cpu',
                                 'goal', 'verdict (wall)'))
ahcCases = [c for c, _, _ in CASES if c != 'laplacian']
for case in ahcCases:
    r = res[case]
    rw, rc = r['wall']/lap['wall'], r['cpu']/lap['cpu']
    r['ratioCpu'] = rc
    g = GOALS[case]
    print('%-29s %7.2fx %7.2fx %7.1fx  %s'
          % (r['label'], rw, rc, g,
             'meets goal' if rw <= g else 'MISSES goal (%.1fx over)' % (rw/g)))
print()
for case in ahcCases:
    r = res[case]
    print('%s: %.2f nonlinear iterations/step in the timed window (of which '
          '%.2f/step in its %d rejected attempts), %.2f over all %d steps (first '
          'step %d); %d sub-steps, %d rejected'
          % (r['label'], r['picard'], r['wastedTimed'], r['rejectedTimed'],
             r['picardAll'], nSteps, r['picardFirst'], r['subSteps'],
             r['rejected']))

# Same problem? phase change off must reproduce laplacianFoam
tL, TL = readT('laplacian')
tA, TA = readT('ahcOff')
tW, TW = readT('ahcOn')
dmax = max(abs(a - b) for a, b in zip(TL, TA))
print()
print('check: max |T(ahcFoam off) - T(laplacianFoam)| at t = %s s: %.3g K '
      '(max T %.2f K); phase change on: max T %.2f K, cells above 373.15 K: '
      '%d vs %d (off)'
      % (tA, dmax, max(TL), max(TW), sum(t > 373.15 for t in TW),
         sum(t > 373.15 for t in TA)))
for case in ahcCases[2:]:
    tX, TX = readT(case)
    print('check: max |T(%s) - T(ahcOn)| at t = %s s: %.3g K'
          % (case, tX, max(abs(a - b) for a, b in zip(TX, TW))))

with open(os.path.join(runDir, 'summary.json'), 'w') as f:
    json.dump(res, f, indent=1)
