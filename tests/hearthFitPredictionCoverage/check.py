"""Coverage of hearthFit's predictive intervals over 15 noise seeds (see
run). For each seed and prediction: z = (value - truth)/std error.
Both predictions depend on k_s alone (the only parameter), so their z
have the sign and nearly the size of k_s's error: one check, seen twice.
If the reported standard errors are right (and the model linear over the
scatter, 2e-4 relative in k_s here), z ~ N(0, 1):
- at most 3 of the 15 truths outside the 95 % interval
  (binomial(15, 0.05): P(>= 4) = 0.5 %);
- rms of z: 15 z^2 ~ chi2(15), its 0.1 % and 99.9 % quantiles 3.48 and
  37.7: rms z in [0.48, 1.59] (standard errors 2x too small give an rms
  near 2, 2x too large near 0.5).
The truth values: TMax of z6 in the truth run, and the isotherm depth
found from the truth run's 101 points as hearthFit does (first crossing
of 290 C going down, linear between points)."""
import csv
import glob
import math
import sys
import hearthcheck as hc

c = hc.Check('hearthFitPredictionCoverage')
with open(sys.argv[1]) as f:
    rows = list(csv.reader(f))
head = [h.strip() for h in rows[0]]
cols = list(zip(*[[float(v) for v in r] for r in rows[1:]]))
h = {n: cols[i] for i, n in enumerate(head)}
tmax = [max(h['depth290_%d' % i]) for i in range(101)]
depth = None
for i in range(1, 101):
    if tmax[i] < 290:
        z0, z1 = 0.1*(i - 1)/100, 0.1*i/100
        depth = z0 + (tmax[i - 1] - 290)/(tmax[i - 1] - tmax[i])*(z1 - z0)
        break
truth = {'TMax_z6': max(h['z6']), 'depth290': depth}
print('    truths: TMax_z6 %.6f C, depth290 %.7f m' % (truth['TMax_z6'], depth))

seeds = sorted(glob.glob('seed*'), key=lambda s: int(s[4:]))
c.true('15 seeds', len(seeds) == 15)
zs = {k: [] for k in truth}
outside = {k: 0 for k in truth}
for s in seeds:
    wd = s + '/postProcessing/hearthFit/'
    c.true('%s: converged' % s, '(converged)' in open(wd + 'report.txt').read())
    with open(wd + 'predictions.csv') as f:
        pr = {r['name']: r for r in csv.DictReader(f)}
    line = []
    for k in truth:
        v, se = float(pr[k]['value']), float(pr[k]['std_error'])
        zs[k].append((v - truth[k])/se)
        if not float(pr[k]['lower']) <= truth[k] <= float(pr[k]['upper']):
            outside[k] += 1
        line.append('%s z %+.2f' % (k, zs[k][-1]))
    print('%s: %s' % (s, ', '.join(line)))

for k in truth:
    c.true('%s: %d of %d truths outside the 95 %% interval (<= 3)'
           % (k, outside[k], len(seeds)), outside[k] <= 3)
    rms = math.sqrt(sum(z*z for z in zs[k])/len(zs[k]))
    c.true('%s: rms of (prediction - truth)/std error %.3f in [0.48, 1.59]'
           % (k, rms), 0.48 <= rms <= 1.59)
c.done()
