"""Priors, groups and predictions of hearthFit (tests/hearthFitPriors/run).
Tolerances:
- the fits stop at the model's precision (status noiseLevel, the
  default): the Gauss-Newton step left is at most 0.1 standard error in
  the covariance's norm, measured 1.6e-4 .. 0.026 in these fits (the
  report's status line); estimates are compared in standard errors
  within 0.05;
- a parameter the data cannot see has a Jacobian column exactly 0 (its
  runs are bitwise equal): its posterior is its prior to the optimiser's
  step (1e-3 relative asked by the issue; 1e-9 expected);
- a prior of sd = se at p + 2 se: for a linear model the posterior mean
  is p + 1 se and its sd se/sqrt(2) (Tarantola 2005 §3.2); the model's
  curvature over 1 se (2e-4 relative in k_s) changes neither by more than
  ~1e-3: 0.05 se and 1 % allowed;
- predictions: the same runs as the fit's (the -writeCase copy at the
  estimates, k_s (1 -/+ h) with the final Jacobian's h = 0.002^(2/3)),
  parameters written with 17 digits: values within 1e-6 relative,
  sensitivities within 1e-4; the interval 1.959964 x sqrt(g^T C g);
- groups: s^2 of a group of n readings with the right sigma is ~chi2(n)/n
  (less the fitted parameter's share, 1/n); 99.9 % bounds by
  Wilson-Hilferty; recomputed from fitted.csv (10 digits) within 1e-4."""
import csv
import math
import os
import re
import hearthcheck as hc

c = hc.Check('hearthFitPriors')


def params(name):
    with open(os.path.join(name, 'postProcessing/hearthFit/parameters.csv')) as f:
        return {r['name']: {k: float(v) for k, v in r.items() if k != 'name'}
                for r in csv.DictReader(f)}


def report(name):
    return open(os.path.join(name, 'postProcessing/hearthFit/report.txt')).read()


def priorRow(text, par):
    m = re.search(r'^%s\s+(\S+)\s+(\S+)\s+(\S+)\s+(\S+)\s+(\S+)\s*$' % par,
                  text.split('first-order posterior')[1], re.M)
    return [float(v) for v in m.groups()] if m else None


for name in ('unseen', 'weak', 'moderate', 'groups'):
    c.true('%s: converged' % name, '(converged)' in report(name))

# ---- 2. The parameter the data cannot see keeps its prior
pu = params('unseen')
c.le('unseen: k_l estimate vs its prior value 0.6, relative',
     abs(pu['kl']['estimate'] - 0.6)/0.6, 1e-3)
c.le('unseen: k_l posterior sd vs its prior sd 0.1, relative',
     abs(pu['kl']['std_error'] - 0.1)/0.1, 1e-3)
row = priorRow(report('unseen'), 'kl')
c.true('unseen: the report prints k_l against its prior (%s)' % row,
       row is not None)
c.le('unseen: k_l post/prior sd as reported - 1', abs(row[4] - 1), 1e-3)
ks, se = pu['ks']['estimate'], pu['ks']['std_error']
print('    data-only k_s %.8g, se %.4g' % (ks, se))
c.le('unseen: k_s (data only) vs the truth 0.45, in se',
     abs(ks - 0.45)/se, 3.29)

# ---- 3. A weak prior on k_s is ignored
pw = params('weak')
c.le('weak prior (0.3 +- 1): k_s shift, in data se',
     abs(pw['ks']['estimate'] - ks)/se, 0.05)
c.le('weak prior: k_s posterior sd / data-only sd - 1',
     abs(pw['ks']['std_error']/se - 1), 1e-3)
row = priorRow(report('weak'), 'ks')
c.le('weak prior: k_s post/prior sd as reported (data taught much)',
     row[4], 1e-3)

# ---- 4. A prior of sd se at k_s + 2 se: halfway, sd se/sqrt(2)
pm = params('moderate')
shift = (pm['ks']['estimate'] - ks)/se
print('    moderate prior: k_s moved %.4f se (a prior ignored: 0, one'
      ' taken alone: 2)' % shift)
c.le('moderate prior: k_s shift - 1 se (precision-weighted mean)',
     abs(shift - 1), 0.05)
c.le('moderate prior: posterior sd / (se/sqrt 2) - 1',
     abs(pm['ks']['std_error']*math.sqrt(2)/se - 1), 1e-2)

# ---- 5. Predictions against the runs of the -writeCase copy
def histories(name):
    with open(os.path.join(name, 'postProcessing/thermocouples/0/sensors.csv')) as f:
        rows = list(csv.reader(f))
    head = [h.strip() for h in rows[0]]
    cols = list(zip(*[[float(v) for v in r] for r in rows[1:]]))
    return {h: cols[i] for i, h in enumerate(head)}


def predictions(name):
    """TMax at z6 and at the added point, the depth where TMax first falls
    below 290 C going down the 101 added points (0 .. 0.1 m)"""
    h = histories(name)
    tmax = [max(h['depth290_%d' % i]) for i in range(101)]
    depth = float('nan')
    for i in range(1, 101):
        if tmax[i] < 290:
            z0, z1 = 0.1*(i - 1)/100, 0.1*i/100
            depth = z0 + (tmax[i - 1] - 290)/(tmax[i - 1] - tmax[i])*(z1 - z0)
            break
    return {'TMax_z6': max(h['z6']), 'TMax_8cm': max(h['TMax_8cm_TMax']),
            'depth290': depth}


with open('unseen/postProcessing/hearthFit/predictions.csv') as f:
    pr = {r['name']: r for r in csv.DictReader(f)}
c.true('three predictions reported', len(pr) == 3)
step = 0.002**(2/3)   # hRel^(2/3), hRel = 2 sqrt(solverNoise 1e-6)
p0, pp, pm_ = (predictions('pred_' + r) for r in ('centre', 'plus', 'minus'))
C = [[se**2, 0], [0, pu['kl']['std_error']**2]]
for k in ('TMax_z6', 'TMax_8cm', 'depth290'):
    v = float(pr[k]['value'])
    c.le('%s = %.6g: vs the run at the estimates (%.6g), relative'
         % (k, v, p0[k]), abs(v - p0[k])/abs(p0[k]), 1e-6)
    d = (pp[k] - pm_[k])/(2*step*ks)
    dks, dkl = float(pr[k]['d_ks']), float(pr[k]['d_kl'])
    c.le('%s: d/dk_s %.6g vs central differences %.6g, relative'
         % (k, dks, d), abs(dks - d)/abs(d), 1e-4)
    c.true('%s: d/dk_l = %g (the data cannot see k_l, nor can TMax)'
           % (k, dkl), dkl == 0)
    sd = math.sqrt(dks**2*C[0][0] + dkl**2*C[1][1])
    c.le('%s: std error vs |d/dk_s| se, relative' % k,
         abs(float(pr[k]['std_error']) - sd)/sd, 1e-6)
    half = 0.5*(float(pr[k]['upper']) - float(pr[k]['lower']))
    c.le('%s: interval half-width / (1.959964 sd) - 1' % k,
         abs(half/(1.959964*sd) - 1), 1e-6)

# ---- 6. Groups: s^2 per group, in the report and from fitted.csv
text = report('groups')
c.true('groups: sigma given (from the groups)', 'sigma given' in text)
with open('groups/postProcessing/hearthFit/fitted.csv') as f:
    fitted = list(csv.DictReader(f))


def wh(p, k):
    z = {0.0005: -3.290527, 0.9995: 3.290527}[p]
    return k*(1 - 2/(9*k) + z*math.sqrt(2/(9*k)))**3


for g, sensors, sigma in (('near', ('z1', 'z2'), 0.2), ('far', ('z4',), 1.0)):
    m = re.search(r'^%s\s+(\S+)\s+(\S+)\s+(\S+)\s+(\S+)\s*$' % g, text, re.M)
    c.true('groups: the report has group %s' % g, m is not None)
    n, s2 = int(m.group(2)), float(m.group(4))
    s2own = sum(((float(r[s + '_fitted']) - float(r[s + '_measured']))/sigma)**2
                for r in fitted for s in sensors)/n
    c.le('group %s: s^2 %.6g vs fitted.csv %.6g, relative' % (g, s2, s2own),
         abs(s2 - s2own)/s2own, 1e-4)
    lo, hi = wh(0.0005, n)/n, wh(0.9995, n)/n
    c.true('group %s: s^2 %.4f in its 99.9 %% chi-square band [%.3f, %.3f]'
           ' (one sigma 0.5 for all would give %.3f)'
           % (g, s2, lo, hi, s2*(sigma/0.5)**2), lo <= s2 <= hi)

# ---- 6b. Observation files as groups (far4.csv with sigma 2)
text = report('files')
c.true('files: converged', '(converged)' in text)
with open('files/postProcessing/hearthFit/fitted.csv') as f:
    fitted = list(csv.DictReader(f))
for g, sensors, sigma in (('default', ('z1', 'z2'), 0.2),
                          ('far', ('z4',), 2.0)):
    m = re.search(r'^%s\s+(\S+)\s+(\S+)\s+(\S+)\s+(\S+)\s*$' % g, text, re.M)
    if g == 'default' and m is None:
        # sensors of no group: s^2 of the pair from fitted.csv only
        n = sum(1 for r in fitted for s in sensors)
        s2 = sum(((float(r[s + '_fitted']) - float(r[s + '_measured']))/sigma)**2
                 for r in fitted for s in sensors)/n
    else:
        c.true('files: the report has group %s' % g, m is not None)
        n, s2 = int(m.group(2)), float(m.group(4))
        s2own = sum(((float(r[s + '_fitted']) - float(r[s + '_measured']))
                     / sigma)**2 for r in fitted for s in sensors)/n
        c.le('files group %s: s^2 %.6g vs fitted.csv %.6g, relative'
             % (g, s2, s2own), abs(s2 - s2own)/s2own, 1e-4)
    lo, hi = wh(0.0005, n)/n, wh(0.9995, n)/n
    c.true('files %s (sigma %g): s^2 %.4f in its 99.9 %% chi-square band'
           ' [%.3f, %.3f] (sigma 0.2 would give %.3f)'
           % (g, sigma, s2, lo, hi, s2*(sigma/0.2)**2), lo <= s2 <= hi)
# The cost: weights 1/sigma^2 per file (far4.csv: 1/4 of a sigma-1 file)
cost = float(re.search(r'^cost \(weighted residual sum of squares\) ([^,\s]+)',
                       text, re.M).group(1))
own = sum(((float(r[s + '_fitted']) - float(r[s + '_measured']))/sg)**2
          for r in fitted for s, sg in (('z1', 0.2), ('z2', 0.2), ('z4', 2.0)))
c.le('files: cost %.8g vs fitted.csv with weights 1/0.2^2, 1/2^2 (%.8g),'
     ' relative' % (cost, own), abs(cost - own)/own, 1e-4)
# The wrong sigma for far4.csv: its s^2 ~ (2/0.2)^2 = 100, far outside
wrong = re.search(r'^far\s+(\S+)\s+(\S+)\s+(\S+)\s+(\S+)\s*$',
                  report('filesWrongSigma'), re.M)
c.true('files, sigma 0.2 for far4.csv: s^2 of far %s above 10'
       % (wrong.group(4) if wrong else None),
       wrong is not None and float(wrong.group(4)) > 10)

# ---- 7. Bad input
lines = open('badInput.txt').read().splitlines()
c.true('17 bad inputs tried', len(lines) == 17)
for l in lines:
    c.true(l, ': ok (' in l)
c.done()
