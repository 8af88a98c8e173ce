"""hearthFit through a launcher template on a one-node Slurm cluster (see
run). Checks:
- the three fits converged;
- srun: the forward runs went through Slurm (slurmctld logged one
  allocation per forward run of the two srun fits, plus run's own srun
  check) and the estimates, standard errors and
  cost equal the local fit's: the same serial solver on the same inputs
  gives the same residuals bit for bit, so the same path; tolerance
  1e-12 relative (the report's 10 significant digits);
- hung run: exactly one run timed out (report: 'timed out 1'; the log
  names the time limit), counted as failed; no 'sleep 3599.25' process
  and no job left; the fit converges to the local estimates within
  0.01 standard error: the failed Jacobian column is taken on the other
  side, so the path differs, and two paths stop at different points of
  the stopping tolerance (tolStep 1e-6 relative to max(|p|, typical) is
  a bound on the last step, not on the distance to the minimum, which
  the 0.99 correlation of the offsets stretches: measured 7e-7 to 1e-5
  of the parameters' scales, 8e-4 to 1e-3 standard errors, over runs on
  a loaded machine); 0.01 standard error is 10 times below the 0.1 of
  tests/hearthFitBroyden's "same estimates";
- bad launcher / timeLimit: a clear error naming the keyword before any
  run."""
import csv
import re
import hearthcheck as hc

c = hc.Check('hearthFitSlurm')
scale = {'ks': 0.45, 'dz_TC2': 1e-3, 'dz_TC3': 1e-3}


def params(case):
    with open(case + '/postProcessing/hearthFit/parameters.csv') as f:
        return {r['name']: {k: float(v) for k, v in r.items() if k != 'name'}
                for r in csv.DictReader(f)}


def report(case):
    with open(case + '/postProcessing/hearthFit/report.txt') as f:
        return f.read()


def cost(case):
    return float(re.search(r'cost \(weighted residual sum of squares\) '
                           r'(\S+),', report(case)).group(1))


def runs(case):
    return int(re.search(r'forward runs (\d+) ', report(case)).group(1))


for case in ('local', 'srun', 'hang'):
    c.true('%s: converged' % case, '(converged)' in report(case))

pl, ps, ph = params('local'), params('srun'), params('hang')
with open('slurm/log/slurmctld.log') as f:
    allocations = len(re.findall(r'_slurm_rpc_allocate_resources', f.read()))
nSrun, nHang = runs('srun'), runs('hang')
# allocations: the srun check of run, the srun fit's runs and the hung
# fit's runs
c.true('srun + hang: %d Slurm allocations = 1 + %d + %d forward runs'
       % (allocations, nSrun, nHang), allocations == 1 + nSrun + nHang)
for k in scale:
    c.le('srun %s: |srun - local|/|local| (%.12g, %.12g)'
         % (k, ps[k]['estimate'], pl[k]['estimate']),
         abs(ps[k]['estimate'] - pl[k]['estimate'])/abs(pl[k]['estimate']),
         1e-12)
    c.le('srun %s: std error |srun - local|/local' % k,
         abs(ps[k]['std_error'] - pl[k]['std_error'])/pl[k]['std_error'],
         1e-12)
c.le('srun: cost |srun - local|/local', abs(cost('srun') - cost('local'))
     / cost('local'), 1e-12)
c.true('srun: as many runs as local (%d, %d)' % (nSrun, runs('local')),
       nSrun == runs('local'))

rep = report('hang')
c.true('hang: report says "timed out 1"', re.search(r'timed out 1\b', rep)
       is not None)
c.true('hang: report counts 1 failed run',
       re.search(r'\(1 failed\)', rep) is not None)
with open('hang/log.hearthFit') as f:
    log = f.read()
c.true('hang: log names the time limit', 'time limit (keyword timeLimit)'
       ' exceeded' in log)
c.true('hang: no sleep process left', open('hang/sleepLeft').read() == '')
c.true('hang: no Slurm job left', open('hang/squeueAfter').read() == '')
for k in scale:
    d = abs(ph[k]['estimate'] - pl[k]['estimate'])
    c.le('hang %s: |hang - local|/std error (%.12g, %.12g)'
         % (k, ph[k]['estimate'], pl[k]['estimate']),
         d/pl[k]['std_error'], 1e-2)

for name, msg in (
        ('noCase', r"Keyword 'launcher' = .*: no \{case\}"),
        ('unknownPlaceholder', r"unknown placeholder \{ranks\} \(valid: "
                               r"\{solver\}, \{nProcs\}, \{case\}, \{log\}\)"),
        ('noParallel', r"nProcs 2 > 1 but no -parallel"),
        ('missingExe', r"needs 'srunx', not found on the PATH"),
        ('negativeTimeLimit', r"Keyword 'timeLimit' = -1 is outside its "
                              r"valid range \[0, inf\)")):
    with open('bad/log.' + name) as f:
        txt = f.read()
    c.true('bad input %s: error "%s" with the file named' % (name, msg),
           re.search(msg, txt) is not None and 'hearthFitDict' in txt
           and 'accepted' not in txt)
c.true('bad input: no forward run', not __import__('os').path.exists(
    'bad/runMade'))
c.done()
