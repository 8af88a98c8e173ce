#!/usr/bin/env python3
"""pendular3DHour benchmark: accuracy and CPU time per simulated hour of the
runs of one mesh against a reference run, and issue 13's ratio.

    analyse.py RUNDIR REF END SEGRUN [NEWRUN]

RUNDIR holds one case per run (log.pendularFoam, log.time, the probes'
postProcessing/temperatures/0/T and postProcessing/dryingColumn/0/alphaL).
For each run:
  * accuracy: the largest |T - T_ref| over the run's own step times and
    the probes of ../system/probesDict (T_ref linearly interpolated in time
    between the reference run's steps), and the dried depth at END under
    the fire (alpha_l crossing 0.005, half the initial 0.01, linearly
    between the probes) against the reference's; 'after 60 s': the
    largest |T - T_ref| once the fire's ramp is over;
  * cost: the master's CPU time of the whole run (ExecutionTime, setup
    included) and per simulated hour (x 3600/END), the wall time
    (ClockTime), the steps, sub-steps, rejected sub-steps, the nonlinear
    (Newton or segregated) iterations in all and per accepted sub-step
    (rejected sub-steps' iterations included);
  * where they go: the same per phase of the window (the ramp to 60 s,
    then to 600 s, 1800 s and END) with the CPU spent in it and the
    sizes of its steps (min, median, max).
The ratio is CPU(SEGRUN)/CPU(NEWRUN) per simulated hour; without NEWRUN,
NEWRUN is the cheapest run on SEGRUN's ranks other than SEGRUN and REF
whose T error is at most SEGRUN's (+ E_SAME). With REF = SEGRUN (no
reference run on a mesh) NEWRUN must be given and the two are compared
with each other only.
"""
import bisect
import os
import re
import sys


# Two runs within E_SAME of each other are equally accurate: 10 TTol, the
# case's nonlinear tolerance (the two engines on the same steps agree
# within it)
E_SAME = 1e-3
ALPHA_DRY = 0.005           # half the initial alpha_l = 0.01
DZ = 0.2/60                 # the column probes' spacing (N = 30's cells)


def probes(path):
    """The rows (time, value at each probe) of a probes file."""
    return [list(map(float, l.split())) for l in open(path)
            if l.strip() and not l.startswith('#')]


def interp(t, ts, vs):
    """vs(t), linear between the sorted times ts (ends held)."""
    i = bisect.bisect_left(ts, t)
    if i == 0:
        return vs[0]
    if i == len(ts):
        return vs[-1]
    w = (t - ts[i-1])/(ts[i] - ts[i-1])
    return (1 - w)*vs[i-1] + w*vs[i]


def run_figures(case, end, unfinished=False):
    """The figures of a run; None if it did not end, unless unfinished
    (then those of its steps so far)."""
    log = open(os.path.join(case, 'log.pendularFoam')).read()
    finished = re.search(r'^End\s*$', log, re.M) is not None
    if not finished and not unfinished:
        return None
    steps = re.findall(r'pendularFoam: deltaT = \S+, iterations = (\d+), '
                       r'sub-steps = (\d+), rejected = (\d+)', log)
    # each step: (its end time, deltaT, iterations, sub-steps, rejected,
    # the CPU time at its end)
    trace = []
    for m in re.finditer(r'^Time = (\S+)$|^pendularFoam: deltaT = (\S+), '
                         r'iterations = (\d+), sub-steps = (\d+), '
                         r'rejected = (\d+)|^ExecutionTime = (\S+) s',
                         log, re.M):
        if m.group(1):
            t = float(m.group(1))
        elif m.group(2):
            trace.append([t, float(m.group(2)), int(m.group(3)),
                          int(m.group(4)), int(m.group(5)), None])
        elif trace and trace[-1][5] is None:
            trace[-1][5] = float(m.group(6))
    cpu = [float(x) for x in re.findall(r'ExecutionTime = (\S+) s', log)]
    clock = [float(x) for x in re.findall(r'ClockTime = (\S+) s', log)]
    ranks = 2 if re.search(r'^nProcs\s*:\s*2', log, re.M) else 1
    T = probes(os.path.join(case, 'postProcessing/temperatures/0/T'))
    a = probes(os.path.join(case, 'postProcessing/dryingColumn/0/alphaL'))
    if finished and abs(T[-1][0] - end) > 1e-6*end:
        sys.exit('pendular3DHour: %s ends at %g s, not %g' % (case, T[-1][0], end))
    col = a[-1][1:] if finished else []
    wet = [i for i, x in enumerate(col) if x >= ALPHA_DRY]
    if not wet:
        depth = float('nan')
    elif wet[0] == 0:
        depth = 0.0
    else:
        i = wet[0]
        depth = DZ*(i - 0.5 + (ALPHA_DRY - col[i-1])/(col[i] - col[i-1]))
    iters = sum(int(s[0]) for s in steps)
    subs = sum(int(s[1]) for s in steps)
    return dict(ranks=ranks, steps=len(steps), subs=subs,
                rejected=sum(int(s[2]) for s in steps), iters=iters,
                itersPerSub=iters/max(subs, 1), cpu=cpu[-1], wall=clock[-1],
                T=T, depth=depth, trace=trace, finished=finished)


def phases(run, end):
    """Where the steps, iterations and CPU go: per phase of the window
    (the ramp to 60 s, then to 600, 1800 s and END), the steps, rejected
    sub-steps, iterations, CPU and the steps' sizes."""
    bounds = [0] + [b for b in (60, 600, 1800) if b < end] + [end]
    rows = []
    cpu0 = 0.0
    for a, b in zip(bounds[:-1], bounds[1:]):
        st = [s for s in run['trace'] if a < s[0] <= b*(1 + 1e-9)]
        if not st:
            continue
        cpu1 = st[-1][5] if st[-1][5] is not None else cpu0
        dts = sorted(s[1] for s in st)
        rows.append((a, b, len(st), sum(s[4] for s in st),
                     sum(s[2] for s in st), cpu1 - cpu0, dts[0],
                     dts[len(dts)//2], dts[-1]))
        cpu0 = cpu1
    return rows


def t_error(run, ref, t0=0):
    """Largest |T - T_ref| over the run's step times from t0 on (to the
    reference's last time) and the probes, and where (probe index,
    time)."""
    T, Tr = run['T'], ref['T']
    tr = [row[0] for row in Tr]
    worst = (0.0, -1, 0.0)
    for row in (r for r in T if t0 <= r[0] <= tr[-1]):
        for j in range(1, len(row)):
            e = abs(row[j] - interp(row[0], tr, [r[j] for r in Tr]))
            if e > worst[0]:
                worst = (e, j - 1, row[0])
    return worst


def main():
    rundir, refname, end, segname = sys.argv[1:5]
    end = float(end)
    newname = sys.argv[5] if len(sys.argv) > 5 else None
    runs = {}
    for name in sorted(os.listdir(rundir)):
        case = os.path.join(rundir, name)
        if os.path.isfile(os.path.join(case, 'log.pendularFoam')):
            r = run_figures(case, end)
            if r is None:
                print('  %s: no End in its log (not finished or failed)' % name)
            else:
                runs[name] = r
    if refname not in runs:
        # an unfinished reference: the errors over the part it ran
        case = os.path.join(rundir, refname)
        if not os.path.isfile(os.path.join(case, 'log.pendularFoam')):
            sys.exit('pendular3DHour: no reference run %s in %s'
                     % (refname, rundir))
        runs[refname] = run_figures(case, end, unfinished=True)
        print('  the reference %s is unfinished: the errors below are over'
              ' 0-%g s only (no dried depth)' % (refname, runs[refname]['T'][-1][0]))
    ref = runs[refname]
    hour = 3600/end
    print('pendular3DHour: %s, window 0-%g s, reference %s (dried depth %.2f mm)'
          % (rundir, end, refname, 1e3*ref['depth']))
    print('  %-16s %5s %6s %6s %6s %7s %7s %9s %11s %8s %11s %14s %9s %9s' % (
        'run', 'ranks', 'steps', 'subs', 'rej', 'iters', 'it/sub',
        'CPU [s]', 'CPU/h [s]', 'wall [s]', 'max|dT| [K]', '(probe, t [s])',
        'ddepth', 'after 60 s'))
    for name, r in runs.items():
        e, j, t = t_error(r, ref) if r is not ref else (0.0, -1, 0.0)
        e60 = t_error(r, ref, 60)[0] if r is not ref else 0.0
        r['error'] = e
        print('  %-16s %5d %6d %6d %6d %7d %7.2f %9.1f %11.1f %8.0f %11.4f %14s %6.2f mm %9.4f'
              % (name, r['ranks'], r['steps'], r['subs'], r['rejected'],
                 r['iters'], r['itersPerSub'], r['cpu'], r['cpu']*hour,
                 r['wall'], e, '(%d, %.1f)' % (j, t) if j >= 0 else '',
                 1e3*abs(r['depth'] - ref['depth']), e60))
    print('  where the steps go: phase [s], steps, rejected sub-steps,'
          ' iterations (a step), CPU [s], the steps min/median/max [s]')
    for name, r in runs.items():
        for a, b, n, rej, it, cpu, d0, dm, d1 in phases(r, end):
            print('  %-16s %5g-%-5g %5d %4d %6d (%5.2f) %8.1f   %7.3g %7.3g %7.3g'
                  % (name, a, b, n, rej, it, it/n, cpu, d0, dm, d1))
    if segname not in runs:
        print('  no finished run %s: no ratio' % segname)
        return
    seg = runs[segname]
    if newname is None:
        if segname == refname:
            sys.exit('pendular3DHour: REF is SEGRUN: give NEWRUN')
        fits = [n for n, r in runs.items()
                if n not in (segname, refname) and r['ranks'] == seg['ranks']
                and r['error'] <= seg['error'] + E_SAME]
        if not fits:
            print('  no run other than %s and %s within E_seg = %.4f K: no ratio'
                  % (segname, refname, seg['error']))
            return
        newname = min(fits, key=lambda n: runs[n]['cpu'])
    new = runs[newname]
    if segname == refname:
        print('  no reference run at this mesh: %s against %s' % (newname, segname))
    else:
        print('  E_seg = %.4f K (%s), E_newton = %.4f K (%s)%s'
              % (seg['error'], segname, new['error'], newname,
                 '' if new['error'] <= seg['error'] + E_SAME
                 else ': NOT within E_seg'))
    e, j, t = t_error(new, seg)
    print('  the two against each other: max abs(T_%s - T_%s) = %.2e K'
          ' (probe %d, %.1f s), dried depth %.2f and %.2f mm'
          % (newname, segname, e, j, t, 1e3*new['depth'], 1e3*seg['depth']))
    print('  ratio CPU(%s)/CPU(%s) per simulated hour: %.2f (%.0f s/h against'
          ' %.0f s/h; %.2f iterations a sub-step)'
          % (segname, newname, seg['cpu']/new['cpu'], seg['cpu']*hour,
             new['cpu']*hour, new['itersPerSub']))


if __name__ == '__main__':
    main()
