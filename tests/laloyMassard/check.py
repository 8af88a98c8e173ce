"""Checks of tests/laloyMassard (see run).

Tolerance of the ahcFoam case: the estimate for a sensor is the a that
best fits T(z,t) = Ti + (T0 - Ti) erfc(z/(2 sqrt(a t))) to its history.
With r_k = T_ahcFoam - T_erfc(a_true) (the discretisation error of the
0.5 mm / <= 5 s backward-Euler run plus the finite 0.3 m column) and
j_k = a dT/da at a_true, the linearised estimate error is
d(ln a) = sum j r / sum j^2, bounded by sqrt(sum r^2 / sum j^2)
(Cauchy-Schwarz). Each sensor (and the median) must lie within twice
that bound of the truth."""
import math, re
import hearthcheck as hc

c = hc.Check('laloyMassard')

def estimates(log):
    per, med, rec, init = {}, None, None, {}
    for line in open(log):
        m = re.match(r'\s+(\S+): depth (\S+) m, diffusivity a = (\S+) m2/s', line)
        if m: per[m.group(1)] = (float(m.group(2)), float(m.group(3)))
        m = re.match(r'first estimate: diffusivity a = (\S+) m2/s', line)
        if m: med = float(m.group(1))
        m = re.search(r'printed recipe \S+ geometric-mean approximation\) a = (\S+)', line)
        if m: rec = float(m.group(1))
        m = re.match(r'\s+initial (\S+) = (\S+) x a = (\S+) \(', line)
        if m: init[m.group(1)] = float(m.group(3))
    return per, med, rec, init

# 1. Exact data
aTrue = 2.5e-7
per, med, rec, init = estimates('exact/log.hearthFit')
c.true('exact: 4 sensors estimated', len(per) == 4, str(sorted(per)))
for s, (z, a) in sorted(per.items()):
    c.le('exact: |a/a_true - 1| sensor %s (z %.5f m)' % (s, z), abs(a/aTrue - 1), 1e-6)
c.le('exact: |median/a_true - 1|', abs(med/aTrue - 1), 1e-6)
c.le('exact: offered initial a (initialFrom laloyMassard), rel. error',
     abs(init.get('ks', 0)/aTrue - 1), 1e-6)
print('  (printed recipe 5.6 on exact data: a = %.4g, %+.1f %%: the bias of'
      ' its geometric-mean approximation)' % (rec, 100*(rec/aTrue - 1)))
c.true('exact: no forward run', not __import__('os').path.exists('exact/forwardRun'))

# 2. ahcFoam column
aTrue = 0.756/(1500*1300)
T0, Ti = 700.0, 20.0
rows = [l.strip().split(',') for l in open('column/measured.csv')]
names = rows[0][1:]
data = [[float(x) for x in r] for r in rows[1:] if r and r[0]]
per, med, rec, init = estimates('column/log.hearthFit')
c.true('column: 4 sensors estimated', len(per) == 4, str(sorted(per)))
worst = 0
for s, (z, a) in sorted(per.items()):
    i = names.index(s) + 1
    srr = sjj = 0
    for row in data:
        t = row[0]
        if t < 600 or t > 21600: continue
        x = z/(2*math.sqrt(aTrue*t))
        r = row[i] - (Ti + (T0 - Ti)*math.erfc(x))
        j = (T0 - Ti)/math.sqrt(math.pi)*math.exp(-x*x)*x
        srr += r*r; sjj += j*j
    bound = math.sqrt(srr/sjj)
    worst = max(worst, bound)
    c.le('column: |ln(a/a_true)| sensor %s (bound %.2e)' % (s, bound),
         abs(math.log(a/aTrue)), 2*bound)
c.le('column: |ln(median/a_true)|', abs(math.log(med/aTrue)), 2*worst)
fitLog = open('column/log.hearthFit').read()
c.true('column: the estimate is printed before the fit',
       0 <= fitLog.find('first estimate: diffusivity') < fitLog.find('iter '))
m = re.search(r'^\s+0\s+\S+\s+(\S+)\s+\S+\s+\S+\s+\d+\s+initial', fitLog, re.M)
k0 = float(m.group(1)) if m else 0
c.le('column: fit starts from 1.95e6 x median a (rel.)',
     abs(k0/(1.95e6*med) - 1), 1e-7)
m = re.search(r'^ks\s+(\S+)', fitLog, re.M)
c.le('column: fitted k_s vs 0.756 (rel.)',
     abs(float(m.group(1))/0.756 - 1) if m else 1, 1e-6)

# 3. Bad input
for log, what in (('bad/log.badSensor', 'firstEstimate: sensor nowhere'),
                  ('bad/log.badFrom', 'initialFrom guess')):
    txt = open(log).read()
    c.true('bad input: %s: clear error' % what,
           what in txt and 'accepted' not in txt)
c.true('bad input: no forward run', not __import__('os').path.exists('bad/forwardRun'))
c.done()
