"""Where pendularFoam's Newton iterations go, from verbose logs ('Newton k:'
lines of pendularNewton): per log, the sub-steps, Newton iterations per
sub-step, a histogram of the iterations of the sub-steps, the iterations
whose step chopped or projected cells (or solved them locally), and, for
every iteration that did not end the sub-step, the criterion that kept it
going: 'residual' (a scaled residual at or above its tolerance), 'modified'
(residuals below, but cells chopped, projected or solved locally), or
'update' (residuals below, the last update of T, p or W above its
tolerance). A chord step (pendularNewton: the last Jacobian's linear solve
ending a sub-step whose residuals are below their tolerances) is counted
apart: it assembles no Jacobian."""
import collections
import re
import sys

pat = re.compile(r'Newton (\d+): residual/tol \(water (\S+), gas (\S+), energy (\S+)\), '
                 r'update/tol \(T (\S+), p (\S+), W (\S+)\), chopped (\d+), projected (\d+)')
for path in sys.argv[1:]:
    steps, cur = [], []
    chord = 0
    for line in open(path):
        chord += 'chord step' in line
        m = pat.search(line)
        if m:
            if int(m.group(1)) == 0 and cur:
                steps.append(cur)
                cur = []
            cur.append([float(v) for v in m.groups()])
    if cur:
        steps.append(cur)
    hist = collections.Counter(len(s) - 1 for s in steps)
    why = collections.Counter()
    modified = 0
    for s in steps:
        for it in s[1:]:
            modified += it[7] + it[8] > 0
        # every iterate but the last (converged, or the sub-step ended)
        for it in s[1:-1]:
            if max(it[1:4]) >= 1:
                why['residual'] += 1
            elif it[7] + it[8] > 0:
                why['modified'] += 1
            else:
                why['update ' + ''.join(n for n, u in zip('TpW', it[4:7]) if u >= 1)] += 1
    n = sum(len(s) - 1 for s in steps)
    print('%s: %d sub-steps, %d Newton iterations (%.2f a sub-step), %d with cells chopped/projected,'
          ' %d chord steps' % (path, len(steps), n, n/max(len(steps), 1), modified, chord))
    print('  iterations of a sub-step: count  ' + ', '.join('%d: %d' % kv for kv in sorted(hist.items())))
    print('  kept going by: ' + ', '.join('%s %d' % kv for kv in why.most_common()))
