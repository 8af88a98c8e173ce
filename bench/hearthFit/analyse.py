"""Figures of bench/hearthFit/run for one column: python3 analyse.py DIR
(DIR/<forward|central>_<1|2>/ holding a finished hearthFit)."""
import re
import sys

d = sys.argv[1]
truth = {'rhoCs': 1.95e6, 'ks': 0.756, 'phi': 0.20}
res = {}
for diff in ('forward', 'central'):
    for conc in (1, 2):
        case = '%s/%s_%d' % (d, diff, conc)
        rep = open(case + '/postProcessing/hearthFit/report.txt').read()
        m = re.search(r'iterations (\d+), forward runs (\d+) \((\d+) failed\), '
                      r'elapsed (\S+) s', rep)
        b = re.search(r'wall time in forward runs: (\S+) s for (\d+) runs in '
                      r'batches .*, (\S+) s for (\d+) single runs', rep)
        est = {}
        for line in rep.splitlines():
            f = line.split()
            if f and f[0] in truth and f[0] not in est and len(f) >= 2:
                try:
                    est[f[0]] = float(f[1])
                except ValueError:
                    pass
        res[diff, conc] = dict(
            it=int(m.group(1)), runs=int(m.group(2)), failed=int(m.group(3)),
            wall=float(m.group(4)), bw=float(b.group(1)), bn=int(b.group(2)),
            sw=float(b.group(3)), sn=int(b.group(4)),
            conv='(converged)' in rep,
            err=max(abs(est[k] - v)/v for k, v in truth.items()))
print('%-8s %4s %5s %5s %9s %10s %12s %12s %10s'
      % ('diff', 'runs', 'iter', 'at', 'wall [s]', 'max err', 'batch s/run',
         'single s/run', 'converged'))
for (diff, conc), r in sorted(res.items()):
    print('%-8s %4d %5d %5s %9.1f %10.2e %12.3f %12.3f %10s'
          % (diff, r['runs'], r['it'], '%d' % conc, r['wall'], r['err'],
             r['bw']/max(r['bn'], 1), r['sw']/max(r['sn'], 1),
             'yes' if r['conv'] else 'NO'))
for diff, ideal in (('forward', '1.5x for 3 columns'),
                    ('central', '2x for 6 columns')):
    a, b = res[diff, 1], res[diff, 2]
    print('%s differences: finite-difference batches %.2fx faster on 2 '
          'cores (%.3f -> %.3f s a run; ideal %s, goal 1.7x); whole fit '
          '%.2fx (%.1f -> %.1f s)'
          % (diff, (a['bw']/a['bn'])/(b['bw']/b['bn']), a['bw']/a['bn'],
             b['bw']/b['bn'], ideal, a['wall']/b['wall'], a['wall'],
             b['wall']))
