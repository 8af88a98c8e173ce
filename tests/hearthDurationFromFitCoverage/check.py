"""Coverage of hearthDuration's interval from hearthFit's posterior over
15 noise seeds (see run). For each seed z = (d* - d*_truth)/sd, d* and
sd from the duration's result.csv (sd from the fit's posterior by the
first-order propagation), d*_truth from a search at the true k_s. If the
sd are right (and d*(k_s) linear over the scatter) z ~ N(0, 1):
- at most 3 of the 15 truths outside the 95 % interval
  (binomial(15, 0.05): P(>= 4) = 0.5 %);
- rms of z: 15 z^2 ~ chi2(15), its 0.1 % and 99.9 % quantiles 3.48 and
  37.7: rms z in [0.48, 1.59] (sds 2x too small give an rms near 2, 2x
  too large near 0.5).
- the sd must dominate what the interval leaves out: the searches'
  tolerance (0.003 h: 10.8 s, the least allowed) and the ~5 s the
  adaptive time steps' noise moves d*: median sd > 0.015 h (5 tolerances);
  the README's ~0.019 h within half a unit."""
import csv
import glob
import math
import statistics
import hearthcheck as hc

c = hc.Check('hearthDurationFromFitCoverage')


def result(case):
    with open(case + '/postProcessing/hearthDuration/result.csv') as f:
        return next(csv.DictReader(f))


truth = float(result('truthDuration')['duration_h'])
print('    truth d* = %.6f h' % truth)
cases = sorted(glob.glob('duration*'), key=lambda s: int(s[8:]))
c.true('15 seeds', len(cases) == 15, str(len(cases)))
zs, sds, outside = [], [], 0
for case in cases:
    r = result(case)
    d, sd = float(r['duration_h']), float(r['sd_h'])
    lo, hi = float(r['intervalLower_h']), float(r['intervalUpper_h'])
    zs.append((d - truth)/sd)
    sds.append(sd)
    outside += not (lo <= truth <= hi)
    print('    %-12s d* %.5f h  sd %.5f h  [%.5f, %.5f]  z %+.2f'
          % (case, d, sd, lo, hi, zs[-1]))
rms = math.sqrt(sum(z*z for z in zs)/len(zs))
c.le('truths outside the 95 % interval (binomial bound)', outside, 3)
c.le('rms z %.3f >= 0.48' % rms, 0.48, rms)
c.le('rms z %.3f <= 1.59' % rms, rms, 1.59)
c.true('median sd %.4f h > 0.015 h (search tolerance, time-step noise)'
       % statistics.median(sds), statistics.median(sds) > 0.015)
c.le('README: median sd %.4f h ~ 0.019 h' % statistics.median(sds),
     abs(statistics.median(sds) - 0.019), 0.0005)
c.done()
