"""hearthFit with the fire as unknown (see run). Checks:
- knots, regularised (second differences, discrepancy principle): the
  weight printed with chi^2 = N (the number of data) on the linearisation
  (the model is linear: bisection to 1e-6 in log w, so chi^2 within 1e-3
  relative); the imposed history (the fire law's ramp, plateau and
  exponential cooling, computed here at the knots) within the reported
  95 % band at >= 90 % of the 25 knots (the band is the posterior of the
  smoothness prior: its bias at the two corners of the law, end of ramp
  and extinction, may put those knots outside);
- the weight's linearisation (26 runs) reused by the fit, 25 runs fewer
  than before; the data-only chi^2 at the estimate printed, = N within
  1e-3 (linear model), no warning; identifiability (knots' fixed scale,
  no regularisation rows) the same for the regularised and unregularised
  fits;
- a knot reported not identifiable has a larger se than every
  identifiable knot (not a Celsius-value verdict);
- a fixed weight 100 x the discrepancy weight: chi^2 at the estimate
  outside N -/+ 2 sqrt(2N), warned, the discrepancy weight at the
  estimate suggested (= the weight of 1, linear model); a 26th knot after
  the run's end not identifiable (regularisation rows left out);
- knots, not regularised (rule none): visibly unstable: its RMS error
  against the truth, the oscillation of its error (second differences
  |L2 (T - T_true)|) and its variance (trace of the covariance) each
  >= 2.5 x the regularised estimate's (measured x3.2, x3.0, x3.4);
- L-curve: its weight inside the searched range (not at an end) and its
  RMS error below half the unregularised one (the truth within its band
  at 19 of 25 knots: the corner smooths more than the discrepancy
  principle here, chi^2 151 for N = 120; not checked);
- law: the fire duration (truth 1 h) and plateau temperature (700 C)
  within their 95 % intervals;
- bad input: each case of run step 4 refused with its message, no
  scratch copy."""
import csv
import math
import os
import re
import hearthcheck as hc

scratch = os.environ.get('scratch', '.')
c = hc.Check('hearthFitFire')


def truth(t):
    """The fire law of truthT: ramp 20 -> 700 C over 0.5 h, 700 C until
    1 h, then 20 + 680 exp(-(t - 1 h)/1 h) [C], t in s."""
    if t <= 1800:
        return 20 + 680*t/1800
    if t <= 3600:
        return 700.0
    return 20 + 680*math.exp(-(t - 3600)/3600)


def params(case):
    with open(os.path.join(scratch, case, 'postProcessing/hearthFit/parameters.csv')) as f:
        return list(csv.DictReader(f))


def second_roughness(v):
    return math.sqrt(sum((v[i+1] - 2*v[i] + v[i-1])**2 for i in range(1, len(v) - 1)))


knots = [300.0*k for k in range(25)]
T = [truth(t) for t in knots]

# 1. Regularised
log = open(os.path.join(scratch, 'knots/log.hearthFit')).read()
m = re.search(r'weight w = (\S+) s\^3/K\^2: chi\^2 = (\S+) \(N = (\d+) data; '
              r'unregularised (\S+)\)', log)
c.true('regularisation weight printed (discrepancy)', m is not None,
       m.group(0) if m else '')
if m:
    w, chi2, N = float(m.group(1)), float(m.group(2)), int(m.group(3))
    c.le('|chi^2/N - 1| at the chosen weight', abs(chi2/N - 1), 1e-3)
    c.true('N = 2 sensors x 60 readings', N == 120, str(N))
reg = params('knots')
c.true('25 knot parameters', len(reg) == 25, str(len(reg)))
inside = [float(r['lower']) <= t <= float(r['upper']) for r, t in zip(reg, T)]
for r, t, ok in zip(reg, T, inside):
    print('    %-9s truth %8.2f estimate %8.2f +- %5.2f %s'
          % (r['name'], t, float(r['estimate']), float(r['std_error']),
             '' if ok else 'OUTSIDE'))
c.true('truth within the 95 % band at >= 90 % of the knots',
       sum(inside) >= 0.9*len(T), '%d of %d' % (sum(inside), len(T)))

# 1b. The weight's linearisation reused by the fit; chi^2 at the estimate;
#     identifiability


def report(case):
    return open(os.path.join(scratch, case,
                             'postProcessing/hearthFit/report.txt')).read()


def reused(case):
    m = re.search(r'forward runs reused (\d+)', report(case))
    return int(m.group(1)) if m else -1


def runs(case):
    m = re.search(r'forward runs (\d+) \(', report(case))
    return int(m.group(1)) if m else -1


def chi2_estimate(text):
    m = re.search(r'at the estimate: data-only chi\^2 = (\S+) \(N = (\d+)', text)
    return (float(m.group(1)), int(m.group(2))) if m else (None, None)


def identifiability(case):
    m = re.search(r'identifiability \(subset selection.*?\): rank (\d+) of '
                  r'(\d+).*?ranking: (.*)', report(case))
    return (int(m.group(1)), m.group(3).strip()) if m else (None, None)


def not_identifiable(case):
    rank, ranking = identifiability(case)
    names = [x.split()[0] for x in re.split(r' > | \| ', ranking or '')]
    return names[rank:] if rank is not None else None


# The linearisation's n + 1 = 26 runs (initial values and the forward
# differences of the 25 knots, the fit's own steps) are the fit's first
# evaluation and Jacobian: all reused (before: the initial run only,
# reused 1, and 127 runs made; the unregularised fit, which chooses no
# weight, reuses none)
nReused, nRuns = reused('knots'), runs('knots')
print('    knots: forward runs %d, reused %d (rule none: %d runs, reused %d)'
      % (nRuns, nReused, runs('none'), reused('none')))
c.true('the linearisation\'s 26 runs reused by the fit', nReused >= 26,
       'reused %d' % nReused)
c.true('runs made: 25 fewer than before (127)', nRuns <= 127 - 25,
       '%d' % nRuns)
chi2e, Ne = chi2_estimate(log)
c.true('data-only chi^2 at the estimate printed', chi2e is not None)
if chi2e is not None:
    # the model is linear: the estimate's chi^2 is the linearisation's
    # chi^2(w) = N up to the Gauss-Newton stop and the finite differences
    print('    discrepancy: data-only chi^2 at the estimate %.4f (N = %d)'
          % (chi2e, Ne))
    c.le('|chi^2_data/N - 1| at the estimate (linear model)',
         abs(chi2e/Ne - 1), 1e-3)
c.true('discrepancy: no warning at the estimate',
       'at the estimate, ' not in log)
# Identifiability from the data rows (regularisation rows left out) with
# the knots' fixed scale (not |T| in C): the regularised and the
# unregularised fits, whose estimates differ (Tfire_1 10.5 C against
# -13 C ...), have the same data Jacobian (linear model) and so the same
# verdicts and ranking; with |p| scaling, or the regularisation rows in,
# they differ
idr, idn = identifiability('knots'), identifiability('none')
print('    identifiability, regularised: rank %s; %s' % idr)
print('    identifiability, not regularised: rank %s; %s' % idn)
c.true('identifiability printed', idr[0] is not None and idn[0] is not None)
c.true('identifiability: same rank and ranking with and without'
       ' regularisation', idr == idn)
# The verdicts follow the standard errors, not the knots' Celsius values:
# a knot declared not identifiable has a larger standard error than every
# identifiable one (measured: all 25 identifiable; with |T| in C as the
# scale and the regularisation rows in, Tfire_1, estimate 10.5 C and se
# 12.5 K, was declared not identifiable while Tfire_25, se 36 K, was.
# The planted bugs identifiabilityCelsiusScale and
# identifiabilityWithRegularisationRows, each alone, pass this check and
# are caught by the heavy case's: with |T| in C Tfire_1, at 17.8 C, is
# declared not identifiable; with the regularisation rows in, Tfire_26 is
# identifiable)
se = {r['name']: float(r['std_error']) for r in reg}
ni = not_identifiable('knots') or []
ok_se = [n for n in se if n not in ni]
c.true('regularised: a knot not identifiable has a larger se than every'
       ' identifiable one',
       not ni or min(se[n] for n in ni) > max(se[n] for n in ok_se),
       'not identifiable: %s' % (', '.join('%s (se %.1f K)' % (n, se[n])
                                           for n in ni) or 'none'))

# 2c. A fixed weight 100 x the discrepancy weight
hlog = open(os.path.join(scratch, 'heavy/log.hearthFit')).read()
chi2h, Nh = chi2_estimate(hlog)
c.true('heavy weight: data-only chi^2 at the estimate printed',
       chi2h is not None)
if chi2h is not None:
    band = 2*math.sqrt(2*Nh)
    warned = 'at the estimate, ' in hlog
    print('    heavy weight: data-only chi^2 at the estimate %.2f (band %d'
          ' -/+ %.1f), warned %s' % (chi2h, Nh, band, warned))
    c.true('heavy weight: chi^2 outside N -/+ 2 sqrt(2N)',
           abs(chi2h - Nh) > band, '%.2f' % chi2h)
    c.true('heavy weight: warned at the estimate', warned)
    # the 26th knot (7500 s, after the run's 7200 s): no data row sees
    # it; only the regularisation rows (left out) would identify it
    nih = not_identifiable('heavy')
    c.true('heavy: Tfire_26 (after the run) not identifiable, every other'
           ' knot identifiable', nih == ['Tfire_26'], str(nih))
    mw = re.search(r'estimate gives w = (\S+) s\^3/K\^2', hlog)
    c.true('heavy weight: the discrepancy weight at the estimate suggested',
           mw is not None)
    if mw and m:
        # linear model: the linearisation at the estimate is the one at
        # the initial values up to the finite differences' noise (central
        # there, forward here): measured 1.06e-3; the weight moved by
        # 3.3e-3 when only the steps of the linearisation changed (old
        # 1e-3 max(|p|, 100) against the fit's): 1 % allowed
        c.le('suggested weight = the discrepancy weight of 1 (rel.)',
             abs(float(mw.group(1))/w - 1), 1e-2)

# 2. Not regularised
none = params('none')
nlog = open(os.path.join(scratch, 'none/log.hearthFit')).read()
c.true('no regularisation weight chosen (rule none)',
       'weight w =' not in nlog)


def rms_error(rows):
    return math.sqrt(sum((float(r['estimate']) - t)**2 for r, t in zip(rows, T))/len(T))


def oscillation(rows):
    """|L2 (T_estimate - T_truth)|: the second differences of the error,
    its knot-to-knot oscillation [C]"""
    return second_roughness([float(r['estimate']) - t for r, t in zip(rows, T)])


def variance(rows):
    """The trace of the covariance, sum of the knots' variances [C^2]"""
    return sum(float(r['std_error'])**2 for r in rows)


er, en = rms_error(reg), rms_error(none)
orr, on = oscillation(reg), oscillation(none)
vr, vn = variance(reg), variance(none)
print('    RMS error [C]: regularised %.3f, not regularised %.3f' % (er, en))
print('    oscillation |L2 (T - T_true)| [C]: regularised %.2f, not %.2f'
      % (orr, on))
print('    trace of the covariance [C^2]: regularised %.1f, not %.1f'
      % (vr, vn))
# Measured 2026-12-02: RMS error 5.39 vs 17.04 (x3.2), oscillation 69.3
# vs 211.1 (x3.0), variance 2.73e3 vs 9.24e3 (x3.4); required x2.5 each
# (with readings every 5 min instead of 2, N = 48: RMS error x15, but the
# band then holds the truth at only 19 of 25 knots: the discrepancy
# principle over-smooths the two corners of the law)
c.true('unregularised RMS error >= 2.5 x regularised', en >= 2.5*er,
       '%.3f vs %.3f' % (en, er))
c.true('unregularised oscillation >= 2.5 x regularised', on >= 2.5*orr,
       '%.2f vs %.2f' % (on, orr))
c.true('unregularised variance (trace) >= 2.5 x regularised', vn >= 2.5*vr,
       '%.1f vs %.1f' % (vn, vr))

# 2b. L-curve
llog = open(os.path.join(scratch, 'lcurve/log.hearthFit')).read()
m = re.search(r'weight w = (\S+) s\^3/K\^2: chi\^2 = (\S+) \(N', llog)
c.true('L-curve weight printed', m is not None, m.group(0) if m else '')
if m:
    wl = float(m.group(1))
    # the searched range is [1e-12, 1e12] in 240 log steps of 10^0.1: an
    # end means the corner was not found (measured: 3.98e5 s^3/K^2, chi^2
    # 150.1; 0.0158 1/K^2 with plain differences, chi^2 151.4)
    c.true('L-curve weight inside (1.3e-12, 8e11)', 1.3e-12 < wl < 8e11,
           '%.4g' % wl)
    # The band holds the noise's variance only: a warning iff the weight
    # leaves chi^2 above N + 2 sqrt(2N) (the regularisation's bias then
    # exceeds the noise); none at the discrepancy weight (chi^2 = N)
    chi2 = float(m.group(2))
    N = int(re.search(r'\(N = (\d+) data', llog).group(1))
    band = N + 2*math.sqrt(2*N)
    warned = "above the noise's band" in llog
    c.true('L-curve: bias warning iff chi^2 %.1f > N + 2 sqrt(2N) = %.1f'
           % (chi2, band), warned == (chi2 > band), 'warned %s' % warned)
    dlog = open(os.path.join(scratch, 'knots/log.hearthFit')).read()
    c.true('discrepancy: no bias warning', "above the noise's band" not in dlog)
lc = params('lcurve')
el = rms_error(lc)
print('    L-curve: RMS error %.3f C, truth in band at %d of 25 knots'
      % (el, sum(float(r['lower']) <= t <= float(r['upper'])
                 for r, t in zip(lc, T))))
c.true('L-curve RMS error < half the unregularised', el < 0.5*en,
       '%.3f vs %.3f' % (el, en))

# 3. Law: duration and plateau
law = {r['name']: r for r in params('law')}
for name, t in (('fireDuration', 1.0), ('fireTemperature', 700.0)):
    r = law.get(name)
    c.true('%s estimated' % name, r is not None)
    if r:
        lo, hi = float(r['lower']), float(r['upper'])
        c.true('%s truth %g within [%.5g, %.5g] (estimate %.6g)'
               % (name, t, lo, hi, float(r['estimate'])), lo <= t <= hi)

# 4. Bad input
c.true('every bad input refused',
       not os.path.exists(os.path.join(scratch, 'badFailed')))
c.done()
