"""Calibration of the intervals of hearthFit over 10 noise seeds (see run).
For each seed: z_j = (estimate_j - truth_j)/std error_j and the joint
Mahalanobis distance d2 = dp^T C^-1 dp, C = the reported covariance
(standard errors and correlation matrix of report.txt). If the reported
covariance is the true one (and the model nearly linear over the
scatter), each z_j is ~ Student t (dof 717: ~ normal) and d2 ~ chi2(3).
Checks (false alarm below ~0.3 % each if the intervals are honest):
- every fit converged;
- the mean of d2 over the 10 seeds: the sum is chi2(30), its 0.1 % and
  99.9 % quantiles 11.5 and 59.8 (Wilson-Hilferty): mean in [1.15, 5.98].
  Standard errors 2x too small would give a mean of 12, 2x too large
  0.75: both fail;
- per parameter, at most 3 of the 10 truths outside the 95 % interval
  (binomial(10, 0.05): P(>= 4) = 0.1 %);
- per parameter, the root mean square of z_j (10 z^2
  ~ chi2(10): 0.1 % and 99.9 % quantiles 1.38 and 29.8 (Wilson-Hilferty):
  rms z in [0.37, 1.73]).
Measured once over 40 other seeds (1..40): coverage 92.5, 90, 92.5 %,
rms z 1.06, 1.18, 1.05, mean d2 3.55 (README, hearthFit section)."""
import csv
import glob
import math
import re
import hearthcheck as hc

c = hc.Check('hearthFitCoverage')
truth = {'rhoCs': 1.95e6, 'ks': 0.756, 'phi': 0.20}
names = list(truth)


def solve(A, b):
    n = len(b)
    M = [list(A[i]) + [b[i]] for i in range(n)]
    for i in range(n):
        p = max(range(i, n), key=lambda r: abs(M[r][i]))
        M[i], M[p] = M[p], M[i]
        for r in range(n):
            if r != i:
                f = M[r][i]/M[i][i]
                M[r] = [a - f*x for a, x in zip(M[r], M[i])]
    return [M[i][n]/M[i][i] for i in range(n)]


seeds = sorted(glob.glob('seed*'), key=lambda s: int(s[4:]))
c.true('10 seeds', len(seeds) == 10)
zs, d2s, outside = {n: [] for n in names}, [], {n: 0 for n in names}
for s in seeds:
    wd = s + '/postProcessing/hearthFit/'
    with open(wd + 'parameters.csv') as f:
        p = {r['name']: r for r in csv.DictReader(f)}
    with open(wd + 'report.txt') as f:
        rep = f.read()
    c.true('%s: converged' % s, '(converged)' in rep)
    corr = rep.split('correlation matrix')[1]
    R = []
    for n in names:
        m = re.search(r'^%s((?:\s+\S+){3})\s*$' % n, corr, re.M)
        R.append([float(v) for v in m.group(1).split()])
    se = [float(p[n]['std_error']) for n in names]
    dp = [float(p[n]['estimate']) - truth[n] for n in names]
    C = [[se[i]*se[j]*R[i][j] for j in range(3)] for i in range(3)]
    d2 = sum(a*b for a, b in zip(dp, solve(C, dp)))
    d2s.append(d2)
    for j, n in enumerate(names):
        zs[n].append(dp[j]/se[j])
        if not float(p[n]['lower']) <= truth[n] <= float(p[n]['upper']):
            outside[n] += 1
    print('%s: z %s, d2 %.2f' % (s, ' '.join('%s %+.2f' % (n, zs[n][-1])
                                             for n in names), d2))

mean = sum(d2s)/len(d2s)
c.true('mean Mahalanobis d2 over %d seeds %.3f in [1.15, 5.98] (chi2(3): 3)'
       % (len(d2s), mean), 1.15 <= mean <= 5.98)
for n in names:
    c.true('%s: %d of %d truths outside the 95 %% interval (<= 3)'
           % (n, outside[n], len(seeds)), outside[n] <= 3)
    rms = math.sqrt(sum(z*z for z in zs[n])/len(zs[n]))
    c.true('%s: rms of (estimate - truth)/std error %.3f in [0.37, 1.73]'
           % (n, rms), 0.37 <= rms <= 1.73)
c.done()
