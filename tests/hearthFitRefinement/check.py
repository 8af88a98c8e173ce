"""hearthFit's refinement check (tests/hearthFitRefinement/run).

The check predicts, by one Gauss-Newton step with the final Jacobian,
dp = -(J^T J)^-1 J^T (r_fine - r), the estimate a refit on the finer model
would give. Compared with an independent measure of the same thing: the
refit itself, a full Levenberg-Marquardt fit on the refined mesh.

Tolerances:
- predicted against real shift: the step is exact for a model linear in
  k_s over the shift; the shift of the coarse fit is 0.25 % of k_s (about
  10 se), over which the temperatures' curvature in ln k_s changes the
  step by a fraction of the same order (~0.3 %); the two fits stop on a
  relative step below tolStep 1e-6 (5e-7 in k_s, 5e-3 se each). 5 % of
  the shift allowed (measured 0.4 %; a sign error, a factor 2 or the
  covariance scaled by s^2 = 2.7 fail by 100 % or more);
- the shift of the medium mesh (80 cells) in standard errors above 0.5
  (measured 1.43) while its s^2 lies inside the 95 % chi-square band
  (measured 1.10 in [0.859, 1.151]): the intervals look right, the check
  says they are not; second-order convergence of the mesh error (measured
  shifts 1.1e-3, 1.48e-4, 3.96e-5 at 20, 80, 160 cells: ratio 3.7 from 80
  to 160 cells) puts the fine mesh at 0.38 se, below 0.5;
- the warning names the parameter exactly where |shift|/se > 0.5."""
import csv
import os
import re
import hearthcheck as hc

c = hc.Check('hearthFitRefinement')


def csvRows(name, f):
    with open(os.path.join(name, 'postProcessing/hearthFit', f)) as fh:
        return {r[list(r.keys())[0]]: r for r in csv.DictReader(fh)}


def check(name):
    return {k: float(v) for k, v in
            csvRows(name, 'refinementCheck.csv')['ks'].items()
            if k != 'parameter'}


def estimate(name):
    return float(csvRows(name, 'parameters.csv')['ks']['estimate'])


def warned(name):
    log = open(os.path.join(name, 'log.hearthFit')).read()
    return re.search(r'refinement check: parameter ks moves by', log) \
        is not None


def sigma2(name):
    rep = open(os.path.join(name, 'postProcessing/hearthFit/report.txt')).read()
    s2 = float(re.search(r' s\^2 (\S+)', rep).group(1))
    lo, hi = re.search(r's\^2 lies in \[(\S+), (\S+)\]', rep).groups()
    return s2, float(lo), float(hi)


coarse, medium, fine = check('coarse'), check('medium'), check('fine')

# 2. and 3. The coarse mesh: bias reported, and the one-step prediction
# against the refit on the refined mesh
c.le('coarse: 0.5 < |shift|/se (%.3g)' % coarse['shift_se'],
     0.5, abs(coarse['shift_se']))
c.true('coarse: a warning names ks', warned('coarse'))
real = estimate('refit') - coarse['estimate']
print('  coarse k_s %.10g, predicted on the refined mesh %.10g (shift %.4g ='
      ' %.3f se), refit %.10g (shift %.4g = %.3f se)'
      % (coarse['estimate'], coarse['refined_estimate'], coarse['shift'],
         coarse['shift_se'], estimate('refit'), real,
         real/coarse['std_error']))
c.le('coarse: |predicted - refit shift|/|refit shift|',
     abs(coarse['shift'] - real)/abs(real), 0.05)
c.le('coarse: ... in standard errors',
     abs(coarse['shift'] - real)/coarse['std_error'], 0.3)
c.true('refit: no refinement check (none asked)',
       not os.path.exists('refit/postProcessing/hearthFit/refinementCheck.csv'))

# 4. Medium: s^2 in its band, the bias still above 0.5 se
s2, lo, hi = sigma2('medium')
c.true('medium: s^2 %.4g inside its chi-square band [%.4g, %.4g]'
       % (s2, lo, hi), lo <= s2 <= hi)
c.le('medium: 0.5 < |shift|/se (%.3g)' % medium['shift_se'],
     0.5, abs(medium['shift_se']))
c.true('medium: a warning names ks', warned('medium'))

# 5. Fine enough: below 0.5 se, no warning
c.le('fine: |shift|/se', abs(fine['shift_se']), 0.5)
c.true('fine: no warning', not warned('fine'))
c.true('shift falls with the mesh (20, 80, 160 cells: %.3g, %.3g, %.3g)'
       % (coarse['shift'], medium['shift'], fine['shift']),
       abs(coarse['shift']) > abs(medium['shift']) > abs(fine['shift']))

# 5b. The time step halved in the finer copy, which then takes more steps
cd = open('timeStep/postProcessing/hearthFit/refined/system/controlDict').read()


def entry(key):
    return float(re.search(r'^%s\s+([^;\s]+);' % key, cd, re.M).group(1))


c.true('timeStep: deltaT 0.5, maxDeltaT 15, maxDeltaTemperature 2.5 in the'
       ' finer copy', (entry('deltaT'), entry('maxDeltaT'),
                       entry('maxDeltaTemperature')) == (0.5, 15, 2.5))


def steps(log):
    return len(re.findall(r'^Time = ', open(log).read(), re.M))


nFine = steps('timeStep/postProcessing/hearthFit/refined/log.run')
nFit = steps('timeStep/postProcessing/hearthFit/scratch0/log.run')
c.le('timeStep: the fit run\'s steps %d x 1.5 <= the finer run\'s %d'
     % (nFit, nFine), 1.5*nFit, nFine)
c.true('timeStep: check made, its shift finite', abs(check('timeStep')['shift_se']) >= 0,
       'shift %.3g se' % check('timeStep')['shift_se'])

# 5c. A failing meshCommand: a warning with its own message, the fit's
# results stand
log = open('meshFails/log.hearthFit').read()
work = 'meshFails/postProcessing/hearthFit'
c.true('meshFails: warning with refineMesh\'s message, log kept',
       'refinement check not made: meshCommand failed (exit status 1)' in log
       and 'Cannot open specified refinement dictionary' in log
       and os.path.exists(os.path.join(work, 'refinementCheck.failed.log')))
c.true('meshFails: no shift reported, the fit\'s results written',
       not os.path.exists(os.path.join(work, 'refinementCheck.csv'))
       and os.path.exists(os.path.join(work, 'parameters.csv')))

# 6. Bad input
bad = open('badInput.txt').read().splitlines()
c.true('bad input: 8 cases, each a FatalIOError before any run',
       len(bad) == 8 and all(': ok (' in b for b in bad),
       '%d of %d ok' % (sum(': ok (' in b for b in bad), len(bad)))

# 7. SIGINT during the check
status = int(open('interrupt/status').read())
log = open('interrupt/log.hearthFit').read()
work = 'interrupt/postProcessing/hearthFit'
c.true('interrupt: exit status 130 (128 + SIGINT)', status == 130,
       str(status))
c.true('interrupt: during the check, said so',
       'Refinement check interrupted (signal 2)' in log)
c.true('interrupt: the fit\'s results written, no refinementCheck.csv',
       os.path.exists(os.path.join(work, 'parameters.csv'))
       and not os.path.exists(os.path.join(work, 'refinementCheck.csv')))
c.true('interrupt: scratch copies removed, no solver left',
       not [d for d in os.listdir(work) if d.startswith('scratch')
            or d == 'refined']
       and not open('interrupt/solversLeft').read().strip())

c.done()
