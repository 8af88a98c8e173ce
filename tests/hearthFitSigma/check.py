"""A given sigma is the noise (tests/hearthFitSigma/run), from the printed
report and parameters.csv of each fit:
- the estimates do not depend on sigma (a constant factor of the cost):
  sigma 0.5 and 1 within 1e-5 relative (both converged with tolStep 1e-6
  on the relative step: each stops within a few 1e-6 of the minimum);
- sigma 1 vs 0.5: standard errors and interval half-widths in ratio 2
  within 1e-3 (the covariance is (J^T J)^-1 with J proportional to
  1/sigma; 2e-3 allowed: the estimates' own 1e-5 and the final
  Jacobian's difference step);
- sigma 1 (the noise of the data): s^2 inside the band the report prints,
  which is [chi2_0.025, chi2_0.975]/dof (recomputed here with the
  Wilson-Hilferty approximation, 1e-3 relative at these dof), no warning;
- sigma 0.5: s^2 = 4 x that of sigma 1 (1e-5: the cost is flat at the
  minimum, so the estimates' 1e-5 changes it far less), outside the band, and a
  warning naming model error and a wrong sigma;
- no sigma: 'sigma not given', the intervals scaled by s^2 with the t
  quantile: std errors = sqrt(s^2) x those of sigma 1 (1e-3)."""
import csv
import math
import os
import re
import sys
import hearthcheck as hc

scratch = sys.argv[1]
c = hc.Check('hearthFitSigma')


def params(name):
    with open(os.path.join(scratch, name,
                           'postProcessing/hearthFit/parameters.csv')) as f:
        return {r['name']: {k: float(v) for k, v in r.items() if k != 'name'}
                for r in csv.DictReader(f)}


def log(name):
    return open(os.path.join(scratch, name, 'log.hearthFit')).read()


def s2(text):
    m = re.search(r'dof (\d+), s\^2 (\S+)', text)
    return int(m.group(1)), float(m.group(2))


def band(text):
    m = re.search(r's\^2 lies in \[(\S+), (\S+)\]', text)
    return (float(m.group(1)), float(m.group(2))) if m else None


def chi2quantile(p, k):
    """Wilson-Hilferty: chi2_p(k) ~ k (1 - 2/(9k) + z_p sqrt(2/(9k)))^3"""
    z = {0.025: -1.959963985, 0.975: 1.959963985}[p]
    return k*(1 - 2/(9*k) + z*math.sqrt(2/(9*k)))**3


p1, p05, pn = params('sigma1'), params('sigma05'), params('noSigma')
l1, l05, ln = log('sigma1'), log('sigma05'), log('noSigma')
for name, text in (('sigma1', l1), ('sigma05', l05), ('noSigma', ln)):
    c.true('%s: converged' % name, '(converged)' in text)
for k in ('rhoCs', 'ks', 'phi'):
    c.le('%s: estimates sigma 0.5 vs 1, relative' % k,
         abs(p05[k]['estimate'] - p1[k]['estimate'])/abs(p1[k]['estimate']),
         1e-5)
    c.le('%s: std error ratio sigma 1 / sigma 0.5 (%.6g) - 2' % (
        k, p1[k]['std_error']/p05[k]['std_error']),
        abs(p1[k]['std_error']/p05[k]['std_error'] - 2), 2e-3)
    w1 = p1[k]['upper'] - p1[k]['lower']
    w05 = p05[k]['upper'] - p05[k]['lower']
    c.le('%s: interval width ratio (%.6g) - 2' % (k, w1/w05),
         abs(w1/w05 - 2), 2e-3)
dof, s21 = s2(l1)
_, s205 = s2(l05)
b = band(l1)
c.true('sigma1: the report prints the chi-square band (%s)' % (b,),
       b is not None)
lo, hi = chi2quantile(0.025, dof)/dof, chi2quantile(0.975, dof)/dof
c.le('sigma1: band lower vs Wilson-Hilferty (%.6g, %.6g), relative'
     % (b[0], lo), abs(b[0] - lo)/lo, 1e-3)
c.le('sigma1: band upper vs Wilson-Hilferty (%.6g, %.6g), relative'
     % (b[1], hi), abs(b[1] - hi)/hi, 1e-3)
c.true('sigma1: s^2 %.4g inside [%.4g, %.4g]' % (s21, b[0], b[1]),
       b[0] <= s21 <= b[1])
c.true('sigma1: no warning', 'WARNING: s^2' not in l1)
c.le('sigma05: s^2 / (4 s^2 of sigma 1) - 1', abs(s205/(4*s21) - 1), 1e-5)
c.true('sigma05: s^2 %.4g outside the band' % s205, s205 > b[1])
c.true('sigma05: warning names model error and a wrong sigma',
       re.search(r'WARNING: s\^2 = \S+ is outside its 95 % chi-square band'
                 r'.*model error.*sigma too small', l05) is not None)
c.true('noSigma: says sigma not given', 'sigma not given' in ln)
_, s2n = s2(ln)
for k in ('rhoCs', 'ks', 'phi'):
    c.le('%s: noSigma std error / (sqrt(s^2) x sigma 1 std error) - 1' % k,
         abs(pn[k]['std_error']/(math.sqrt(s2n)*p1[k]['std_error']) - 1),
         1e-3)
c.done()
