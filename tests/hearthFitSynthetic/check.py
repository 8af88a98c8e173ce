"""hearthFit on synthetic data of the theses' wet clay (see run). Checks:
- noiseless: the three estimates within 0.5 % of the truth (rhoCs 1.95e6,
  ks 0.756, phi 0.20), converged; fitted.csv has the measured and fitted
  histories of the 4 sensors at the 180 readings and they agree (0.05 C);
  one progress line per iteration in progress.csv (with cost, the
  parameters, damping, elapsed time, runs); the report has the estimates,
  intervals, correlation matrix, singular values and RMS per sensor; the
  case was not modified and the scratch copies were removed; the case
  copy written by -writeCase holds the estimates (Cp = rhoCs/1500);
- 5 C noise: the truth inside each reported 95 % interval; RMS residual of
  every sensor within 4..6 C;
- failing runs: at least one forward run failed and the fit still
  recovers the truth within 0.5 %;
- bad input: each of the 6 cases of run step 5 failed with its message and
  made no scratch copy (badInput.txt)."""
import csv
import math
import os
import re
import hearthcheck as hc

c = hc.Check('hearthFitSynthetic')
truth = {'rhoCs': 1.95e6, 'ks': 0.756, 'phi': 0.20}


def params(case):
    with open(case + '/postProcessing/hearthFit/parameters.csv') as f:
        return {r['name']: r for r in csv.DictReader(f)}


def report(case):
    with open(case + '/postProcessing/hearthFit/report.txt') as f:
        return f.read()


# 1. Noiseless
p = params('exact')
for k, v in truth.items():
    c.le('exact: |%s - truth|/truth (estimate %s)' % (k, p[k]['estimate']),
         abs(float(p[k]['estimate']) - v)/v, 0.005)
rep = report('exact')
c.true('exact: converged', '(converged)' in rep)
for what in ('correlation matrix', 'singular values', 'RMS residual per sensor',
             'lower 95%', 'upper 95%', 'std error'):
    c.true('exact: report has "%s"' % what, what in rep)
with open('exact/postProcessing/hearthFit/fitted.csv') as f:
    rows = list(csv.DictReader(f))
sensors = ('z1', 'z2', 'z4', 'z6')
c.true('exact: fitted.csv has 180 readings of 4 sensors', len(rows) == 180
       and all(s + '_measured' in rows[0] and s + '_fitted' in rows[0]
               for s in sensors))
c.le('exact: max |fitted - measured| [C]',
     max(abs(float(r[s + '_fitted']) - float(r[s + '_measured']))
         for r in rows for s in sensors), 0.05)
with open('exact/postProcessing/hearthFit/progress.csv') as f:
    prog = list(csv.DictReader(f))
iters = [int(r['iteration']) for r in prog]
c.true('exact: one progress line per iteration 0..%d' % iters[-1],
       iters == list(range(len(iters))) and len(iters) > 2)
c.true('exact: progress has cost, parameters, damping, elapsed_s, runs',
       all(k in prog[0] for k in ('cost', 'rhoCs', 'ks', 'phi', 'damping',
                                  'elapsed_s', 'runs')))
c.true('exact: case unchanged (0, constant, system, measured.csv)',
       os.path.isfile('exact/unchanged'))
c.true('exact: scratch copies removed',
       not [d for d in os.listdir('exact/postProcessing/hearthFit')
            if d.startswith('scratch')])
with open('best/constant/porousProperties') as f:
    txt = f.read()
solid = re.search(r'solid\s*\{([^}]*)\}', txt).group(1)
cp = float(re.search(r'\bCp\s+([^;]+);', solid).group(1))
ks = float(re.search(r'\bkappa\s+([^;]+);', solid).group(1))
phi = float(re.search(r'^porosity\s+([^;]+);', txt, re.M).group(1))
# (parameters.csv has 12 significant digits)
c.le('writeCase: |1500 Cp - rhoCs estimate|/rhoCs',
     abs(1500*cp - float(p['rhoCs']['estimate']))/1.95e6, 1e-10)
c.le('writeCase: |kappa - ks estimate|/ks',
     abs(ks - float(p['ks']['estimate']))/0.756, 1e-10)
c.le('writeCase: |porosity - phi estimate|/phi',
     abs(phi - float(p['phi']['estimate']))/0.2, 1e-10)
c.true('writeCase: mesh copied', os.path.isfile('best/constant/polyMesh/faces'))

# 2. Noise
p = params('noisy')
for k, v in truth.items():
    lo, hi = float(p[k]['lower']), float(p[k]['upper'])
    c.true('noisy: truth %s = %g inside the 95 %% interval [%.6g, %.6g] '
           '(estimate %.6g, relative error %.3g %%)'
           % (k, v, lo, hi, float(p[k]['estimate']),
              100*(float(p[k]['estimate']) - v)/v), lo <= v <= hi)
rep = report('noisy')
c.true('noisy: converged', '(converged)' in rep)
rms = re.findall(r'^\s+(z\d)\s+(\S+)$', rep, re.M)
c.true('noisy: RMS residual of the 4 sensors within 4..6 C (%s)'
       % ', '.join('%s %.3f' % (s, float(v)) for s, v in rms),
       len(rms) == 4 and all(4 < float(v) < 6 for s, v in rms))

# 3. Failing runs
p = params('failing')
rep = report('failing')
m = re.search(r'forward runs (\d+) \((\d+) failed\)', rep)
c.true('failing: some forward runs failed (%s)' % (m.group(0) if m else '?'),
       m is not None and int(m.group(2)) > 0)
c.true('failing: converged', '(converged)' in rep)
for k, v in truth.items():
    c.le('failing: |%s - truth|/truth (estimate %s)' % (k, p[k]['estimate']),
         abs(float(p[k]['estimate']) - v)/v, 0.005)

# 4. Bad input
with open('badInput.txt') as f:
    bad = f.read().splitlines()
c.true('bad input: 6 cases', len(bad) == 6)
for line in bad:
    c.true('bad input: ' + line, line.split(': ', 1)[1].startswith('ok'))

c.done()
