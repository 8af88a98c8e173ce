"""hearthDuration propagates the soil's uncertainty to the minimal duration.

- kappa: the tool's sensitivity dd*/dkappa (implicit-function theorem at
  the root: -(df/dkappa)/(df/dd), central differences over kappa -/+ 1 sd
  and d -/+ the duration moving f as much) against the central difference
  of two full searches at kappa -/+ 0.05. Tolerance 2 %: f(d) carries a
  noise of ~0.1 K from the adaptive time steps (the slopes between the
  search's runs scatter from 76.5 to 80.4 K/h), so each search's answer
  errs by ~0.1 K / 79 K/h = 5 s, i.e. ~0.9 % of the difference of the two
  answers (745 s); the tool's differences of ~16-20 K, ~0.6 % each; the
  truncations of both central differences over 6.6 % of kappa, ~(h/kappa)^2
  < 0.5 %, mostly common. Measured 0.36 %. The forward difference of the
  searches, (d*(kappa + h) - d*)/h, 6.4 % off, is printed as the plausible
  wrong one (a forward step of 0.1 sd with df/dd from the final bracket's
  secant was 3.4 % off: the noise).
- Cp: dry conduction with constant properties depends on kappa/(rho Cp)
  only, so kappa dd*/dkappa = -Cp dd*/dCp exactly; the tool's two
  sensitivities within 2 % (the noise of both, ~1 % in all; measured
  0.05 %).
- the interval: half-width = z sqrt(g^T C g) (z = 1.95996 at 95 %, C from
  the sds 0.05 and 100 and the correlation -0.3) recomputed here from
  sensitivities.csv, within the 6 decimals (h) of result.csv; the printed
  'The fire burned at least ... h (95 %: a-b h)' equals result.csv to its
  2 decimals; they are the README's example (1.50 h, 95 %: 1.14-1.85 h).
- bad inputs: FatalIOError with the file and the keyword, no run, no
  crash."""
import csv
import math
import re
import hearthcheck as hc

c = hc.Check('hearthDurationUncertainty')


def result(case):
    with open(case + '/postProcessing/hearthDuration/result.csv') as f:
        return next(csv.DictReader(f))


nom = result('nominal')
d0 = float(nom['duration_h'])
dm = float(result('kappa0.706')['duration_h'])
dp = float(result('kappa0.806')['duration_h'])
with open('nominal/postProcessing/hearthDuration/sensitivities.csv') as f:
    sens = {r['parameter']: r for r in csv.DictReader(f)}
gk = float(sens['kappa']['ddstar_dp_h_per_unit'])
gc = float(sens['Cp']['ddstar_dp_h_per_unit'])
kappa, cp = 0.756, 1300.0
print('d* = %.6f h; d*(kappa -/+ 0.05) = %.6f, %.6f h' % (d0, dm, dp))

central = (dp - dm)/0.1
forward = (dp - d0)/0.05
c.le('dd*/dkappa: |tool %.5f / central difference %.5f - 1| (the forward'
     ' difference %.5f: %.2f %% off)'
     % (gk, central, forward, 100*abs(forward/central - 1)),
     abs(gk/central - 1), 0.02)
c.le('|kappa dd*/dkappa %.5f / (-Cp dd*/dCp %.5f) - 1| (similarity)'
     % (kappa*gk, -cp*gc), abs(kappa*gk/(-cp*gc) - 1), 0.02)

rho = -0.3
sk, sc = 0.05, 100.0
var = (gk*sk)**2 + (gc*sc)**2 + 2*rho*gk*gc*sk*sc
z = 1.959963984540054
sd = float(nom['sd_h'])
lo, hi = float(nom['intervalLower_h']), float(nom['intervalUpper_h'])
c.le('|sd - sqrt(g^T C g)| [h]', abs(sd - math.sqrt(var)), 1e-6)
c.le('|half-width - 1.96 sqrt(g^T C g)| [h] (half-width %.5f h)'
     % (0.5*(hi - lo)), abs(0.5*(hi - lo) - z*math.sqrt(var)), 2e-6)
c.le('|interval centre - d*| [h]', abs(0.5*(hi + lo) - d0), 2e-6)
c.true('the correlation counts: sd without it differs by > 5 %',
       abs(math.sqrt((gk*sk)**2 + (gc*sc)**2)/sd - 1) > 0.05,
       'sd %.5f h, uncorrelated %.5f h'
       % (sd, math.sqrt((gk*sk)**2 + (gc*sc)**2)))

log = open('nominal/log.hearthDuration').read()
m = re.search(r'The fire burned at least (\S+) h \(95 %: (\S+)-(\S+) h\)', log)
c.true('printed result = result.csv (2 decimals)',
       m is not None and abs(float(m.group(1)) - d0) < 0.0051
       and abs(float(m.group(2)) - lo) < 0.0051
       and abs(float(m.group(3)) - hi) < 0.0051,
       m.group(0) if m else 'not found')
# The figures of the README's example line (2 decimals, half a unit)
for what, v, printed in (('d*', d0, 1.50), ('lower', lo, 1.14),
                         ('upper', hi, 1.85)):
    c.le('README: %s %.5f h = %.2f h' % (what, v, printed), abs(v - printed),
         0.005)
c.true('no TMax still rising', 'still rising' not in log)

for line in open('bad.txt'):
    name, status, key, crash = line.strip().split('|')
    log = open('bad_%s/log.hearthDuration' % name).read()
    c.true('bad input %s: FatalIOError naming the file and %s, no run'
           % (name, key),
           status != '0' and 'FOAM FATAL IO ERROR' in log and key in log
           and re.search(r'^file: ', log, re.M) is not None
           and not re.search(r'^run +1:', log, re.M)
           and crash == 'no',
           ' '.join(log[log.find('-->'):].split()[:30]))
c.done()
