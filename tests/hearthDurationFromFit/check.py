"""hearthDuration reads hearthFit's posterior (uncertainty { fitPosterior
"<file>"; }).

- posterior.dict against the fit's other outputs: value = scale x estimate
  and sd = |scale| x standard error of parameters.csv (12 significant
  digits there: relative 1e-11); the correlation against report.txt's
  (printed to 4 significant digits: 5e-5 for |r| < 1); the values of
  the case written by -writeCase equal the posterior's (both 17 digits:
  relative 1e-15).
- the interval from the posterior equals the one from the same numbers
  written by hand: every field of result.csv and sensitivities.csv
  identical (the same doubles give the same runs; the files print 6-11
  digits), and the printed line identical.
- sd of d* = sqrt(g^T C g) recomputed from sensitivities.csv and the
  posterior's sds and correlation, within the 8 decimals (h) of
  result.csv; the correlation counts (the uncorrelated sd printed as the
  plausible wrong one differs by more than 5 %).
- bad inputs: FatalIOError with the file and the keyword, no run, no
  crash.
- the README's figures: sd 0.00040 h, 0.17 h without the correlation
  (over 400-fold), correlation 0.99999 (half a unit of the printed digit)."""
import csv
import math
import re
import hearthcheck as hc

c = hc.Check('hearthDurationFromFit')

post = open('fit/postProcessing/hearthFit/posterior.dict').read()
pars = re.findall(r'\n    (\w+)\n    \{\n\s*file\s+"([^"]+)";\n\s*entry\s+"([^"]+)";'
                  r'\n\s*value\s+(\S+);\n\s*sd\s+(\S+);', post)
rows = re.search(r'\ncorrelation\n\((.*?)\n\);', post, re.S).group(1)
R = [[float(v) for v in r.strip().strip('()').split()]
     for r in rows.strip().split('\n')]
names = [p[0] for p in pars]
value = {p[0]: float(p[3]) for p in pars}
sd = {p[0]: float(p[4]) for p in pars}
scale = {'ks': 1.0, 'rhoCs': 6.666666666666666667e-4}
c.true('posterior.dict: ks and rhoCs in order', names == ['ks', 'rhoCs'],
       str(names))

with open('fit/postProcessing/hearthFit/parameters.csv') as f:
    est = {r['name']: r for r in csv.DictReader(f)}
for n in names:
    c.le('%s: value %.10g = scale x estimate (parameters.csv) (rel.)'
         % (n, value[n]),
         abs(value[n]/(scale[n]*float(est[n]['estimate'])) - 1), 1e-11)
    c.le('%s: sd %.6g = scale x std error (parameters.csv) (rel.)'
         % (n, sd[n]),
         abs(sd[n]/(scale[n]*float(est[n]['std_error'])) - 1), 1e-11)
rep = open('fit/postProcessing/hearthFit/report.txt').read()
m = re.search(r'\ncorrelation matrix\n(\S+)\s+(\S+)\s+(\S+)\n(\S+)\s+(\S+)'
              r'\s+(\S+)\n', rep)
r12 = float(m.group(3))
c.le('correlation %.8f = report.txt %.4g' % (R[0][1], r12),
     abs(R[0][1] - r12), 5e-5)
c.true('correlation symmetric, unit diagonal',
       R[0][0] == 1 and R[1][1] == 1 and R[0][1] == R[1][0], str(R))

soil = open('fitted/constant/soilProperties').read()
solid = re.search(r'solid\s*\{([^}]*)\}', soil).group(1)
kw = dict(re.findall(r'(\w+)\s+([^;\s]+);', solid))
for n, key in (('ks', 'kappa'), ('rhoCs', 'Cp')):
    c.le('written case: solid/%s %s = posterior value (rel.)' % (key, kw[key]),
         abs(float(kw[key])/value[n] - 1), 1e-15)


def read(case, name):
    with open(case + '/postProcessing/hearthDuration/' + name) as f:
        return list(csv.DictReader(f))


for name in ('result.csv', 'sensitivities.csv'):
    a, b = read('fitted', name), read('hand', name)
    c.true('%s: fitPosterior = the same numbers by hand (every field)' % name,
           a == b, '%s | %s' % (a, b))


def printed(case):
    log = open(case + '/log.hearthDuration').read()
    m = re.search(r'The fire burned at least .*\n.*standard deviation.*', log)
    return m.group(0) if m else None


pf, ph = printed('fitted'), printed('hand')
c.true('printed result: fitPosterior = by hand', pf is not None and pf == ph,
       (pf or 'not found').split('\n')[0])

res = read('fitted', 'result.csv')[0]
sens = {r['parameter']: float(r['ddstar_dp_h_per_unit'])
        for r in read('fitted', 'sensitivities.csv')}
g = [sens[n]*sd[n] for n in names]
var = sum(g[i]*R[i][j]*g[j] for i in range(2) for j in range(2))
sdh = float(res['sd_h'])
c.le('|sd %.8f h - sqrt(g^T C g)| [h] (C from posterior.dict)' % sdh,
     abs(sdh - math.sqrt(var)), 1e-8)
unc = math.sqrt(g[0]**2 + g[1]**2)
c.true('the correlation counts: sd without it differs by > 5 %',
       abs(unc/sdh - 1) > 0.05, 'sd %.5f h, uncorrelated %.5f h' % (sdh, unc))

# The README's figures (printed digits, half a unit)
c.le('README: sd %.6f h = 0.00040 h' % sdh, abs(sdh - 0.00040), 5e-6)
c.le('README: uncorrelated sd %.4f h = 0.17 h' % unc, abs(unc - 0.17), 0.005)
c.le('README: correlation %.7f = 0.99999' % R[0][1], abs(R[0][1] - 0.99999),
     5e-6)
c.true('README: over 400-fold without the correlation', unc/sdh > 400,
       '%.0f' % (unc/sdh))

for line in open('bad.txt'):
    name, status, key, crash = line.strip().split('|')
    log = open('bad_%s/log.hearthDuration' % name).read()
    c.true('bad input %s: FatalIOError naming the file and %s, no run'
           % (name, key),
           status != '0' and 'FOAM FATAL IO ERROR' in log and key in log
           and re.search(r'^file: ', log, re.M) is not None
           and not re.search(r'^run +1:', log, re.M)
           and crash == 'no',
           ' '.join(log[log.find('-->'):].split()[:40]))
c.done()
