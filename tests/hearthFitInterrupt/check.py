"""hearthFit stopped by SIGINT (tests/hearthFitInterrupt/run):
- the interrupted fit exits with 130 (128 + SIGINT), not 0 (it used to
  count the killed runs as failed and go on to a report, or ignore SIGINT);
- forward runs were running when the signal came (solvers.before not empty:
  the test did interrupt a batch), and none is left 1 s after hearthFit
  exited (solvers.after empty: their process groups were killed);
- its log says it was interrupted and where -resume continues; state.dict
  is there;
- the resumed fit converges to the uninterrupted fit's estimates within
  1e-6 relative: both stop at the minimum of the same noise-free problem
  (tolStep 1e-6 relative step; hearthFitSynthetic measures 6e-9 between a
  resumed and an uninterrupted fit)."""
import os
import sys
import hearthcheck as hc

scratch = sys.argv[1]
c = hc.Check('hearthFitInterrupt')
d = os.path.join(scratch, 'interrupted')


def params(case):
    import csv
    with open(os.path.join(case, 'postProcessing/hearthFit/parameters.csv')) as f:
        return {r['name']: float(r['estimate']) for r in csv.DictReader(f)}


with open(os.path.join(d, 'interrupted.status')) as f:
    st = int(f.read())
c.true('interrupted: exit status 130 (%d)' % st, st == 130)
before = open(os.path.join(d, 'solvers.before')).read().split()
after = open(os.path.join(d, 'solvers.after')).read().split()
c.true('interrupted: forward runs were running at the signal (%d processes)'
       % len(before), len(before) > 0)
c.true('interrupted: no solver process left (%d)' % len(after),
       len(after) == 0)
log = open(os.path.join(d, 'log.hearthFit.interrupted')).read()
c.true('interrupted: the log says so and where -resume continues',
       'hearthFit interrupted by signal 2 (SIGINT)' in log
       and 'hearthFit -resume continues' in log)
c.true('interrupted: no report written by the interrupted fit',
       'hearthFit report' not in log)
c.true('interrupted: state.dict saved',
       os.path.isfile(os.path.join(d, 'state.interrupted')))
rlog = open(os.path.join(d, 'log.hearthFit')).read()
c.true('resumed: converged', '(converged)' in rlog)
whole = params(os.path.join(scratch, 'whole'))
resumed = params(d)
for k in ('rhoCs', 'ks', 'phi'):
    c.le('resumed: |%s - uninterrupted|/uninterrupted (%.12g, %.12g)'
         % (k, resumed[k], whole[k]),
         abs(resumed[k] - whole[k])/abs(whole[k]), 1e-6)
c.done()
