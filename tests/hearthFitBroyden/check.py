"""Broyden-updated Jacobians (jacobianUpdates 3) against full finite-
difference Jacobians (see run). Checks, for the test fit (full vs
broyden) and the tutorial fit (fitDryHearthFull.csv: the parameters.csv of
tutorials/fitDryHearth's own fit, full Jacobians, fixed seeds, so
reproduced to the digit as tests/tutorialFitDryHearth checks):
- converged; Broyden-updated Jacobians were used (report: 'N
  Broyden-updated' with N > 0);
- the same estimates within 0.1 standard error (of the full fit): both
  stop within about tolStep (1e-6 relative to max(|p|, typical)) of the
  same minimum, far below 0.1 standard error (the test fit's standard
  errors are 7e-4 (k_s) to 5e-3 (offsets, of typical 1 mm) relative);
  the standard errors within 1e-3 relative (both from a final central
  finite-difference Jacobian at estimates that close);
- the forward runs the report states are the runs made (the counting
  solver's count), and the report's Jacobian counts add up to its
  iterations;
- fewer runs with Broyden updates than with full Jacobians (the figures
  printed in the README: full and Broyden counts, both fits)."""
import csv
import re
import hearthcheck as hc

c = hc.Check('hearthFitBroyden')


def params(path):
    with open(path) as f:
        return {r['name']: {k: float(v) for k, v in r.items() if k != 'name'}
                for r in csv.DictReader(f)}


def report(case):
    with open(case + '/postProcessing/hearthFit/report.txt') as f:
        return f.read()


def counts(case):
    rep = report(case)
    it = int(re.search(r'^iterations (\d+)', rep, re.M).group(1))
    runs = int(re.search(r'forward runs (\d+) ', rep).group(1))
    fd, br = map(int, re.search(r'Jacobians (\d+) by finite differences '
                                r'and (\d+) Broyden-updated', rep).groups())
    with open(case + '/runCount') as f:
        made = len(f.read().split())
    return it, runs, fd, br, made


tut = 'tutorials/fitDryHearth'
# The tutorial's fit only when run (TUTORIAL=yes: bench/hearthFitBroyden)
withTutorial = __import__('os').path.isdir(tut)
fits = (('test fit', 'full', 'broyden',
         params('full/postProcessing/hearthFit/parameters.csv')),) + (
        (('fitDryHearth', None, tut,
          params(__import__('os').path.join(
              __import__('os').path.dirname(__file__),
              'fitDryHearthFull.csv'))),) if withTutorial else ())
figures = {}
for name, fullCase, case, pf in fits:
    cases = ([fullCase] if fullCase else []) + [case]
    for cs in cases:
        it, runs, fd, br, made = counts(cs)
        c.true('%s %s: converged' % (name, cs), '(converged)' in report(cs))
        c.true('%s %s: %d runs reported = %d runs made'
               % (name, cs, runs, made), runs == made)
        c.true('%s %s: Jacobians %d + %d = %d iterations'
               % (name, cs, fd, br, it), fd + br == it)
        figures[(name, cs)] = runs
        print('%s %s: %d iterations, %d finite-difference and %d Broyden '
              'Jacobians, %d forward runs' % (name, cs, it, fd, br, runs))
    c.true('%s: Broyden-updated Jacobians used' % name, counts(case)[3] > 0)
    pb = params(case + '/postProcessing/hearthFit/parameters.csv')
    worst = 0
    for k in pf:
        d = abs(pb[k]['estimate'] - pf[k]['estimate'])/pf[k]['std_error']
        worst = max(worst, d)
        c.le('%s %s: |Broyden - full|/std error (%.10g, %.10g)'
             % (name, k, pb[k]['estimate'], pf[k]['estimate']), d, 0.1)
        c.le('%s %s: std error |Broyden - full|/full' % (name, k),
             abs(pb[k]['std_error'] - pf[k]['std_error'])/pf[k]['std_error'],
             1e-3)
    print('%s: largest |Broyden - full| %.2g standard errors' % (name, worst))

# The tutorial's full fit with the tolerances alone (noiseStop off, as the
# bench's Broyden fit): 82 runs (measured before the noise stop; the
# tutorial as it is, with the noise stop, makes 70: its README,
# tests/tutorialFitDryHearth)
figures[('fitDryHearth', 'full')] = 82
names = ('test fit', 'fitDryHearth') if withTutorial else ('test fit',)
for name in names:
    full = figures[(name, 'full')]
    brd = figures[(name, 'broyden' if name == 'test fit' else tut)]
    c.true('%s: fewer runs with Broyden updates (%d < %d)' % (name, brd, full),
           brd < full)

# The README's figures
readme = open(__import__('os').path.join(
    __import__('os').path.dirname(__file__), '../../README.md')).read()
readmeFigures = [('test fit', figures[('test fit', 'full')],
                  figures[('test fit', 'broyden')])]
if withTutorial:
    readmeFigures.append(('fitDryHearth', 82, figures[('fitDryHearth', tut)]))
for name, full, brd in readmeFigures:
    text = '%d forward runs instead of %d' % (brd, full)
    c.true('README states "%s" (%s)' % (text, name), text in readme)

# ---- 3. The noise stop (noise) against the tolerances alone (full), both
# with full finite-difference Jacobians: fewer runs, stopped on noiseLevel,
# the estimates within 0.1 standard error (of the full fit: the noise
# stop's own guarantee is a Gauss-Newton step left <= 0.1 standard error
# in the covariance's norm), the standard errors within 1e-2 relative
# (the final central Jacobian at points 0.1 standard error apart, the
# parameters' relative standard errors 7e-4 .. 7e-3)
itN, runsN, fdN, brN, madeN = counts('noise')
itF, runsF = counts('full')[:2]
repN = report('noise')
c.true('noise stop: status noiseLevel (converged)',
       'status: noiseLevel (converged)' in repN)
c.true('noise stop: %d runs reported = %d runs made' % (runsN, madeN),
       runsN == madeN)
c.true('noise stop: fewer runs than the tolerances (%d < %d)'
       % (runsN, runsF), runsN < runsF)
pn = params('noise/postProcessing/hearthFit/parameters.csv')
pf = params('full/postProcessing/hearthFit/parameters.csv')
for k in pf:
    c.le('noise stop %s: |noise - tolerances|/std error (%.10g, %.10g)'
         % (k, pn[k]['estimate'], pf[k]['estimate']),
         abs(pn[k]['estimate'] - pf[k]['estimate'])/pf[k]['std_error'], 0.1)
    c.le('noise stop %s: std error |noise - tolerances|/tolerances' % k,
         abs(pn[k]['std_error'] - pf[k]['std_error'])/pf[k]['std_error'],
         1e-2)
print('noise stop: %d iterations, %d forward runs (tolerances alone: %d '
      'iterations, %d runs)' % (itN, runsN, itF, runsF))
text = 'noise stop: %d forward runs instead of %d' % (runsN, runsF)
c.true('README states "%s"' % text, text in readme)
c.done()
