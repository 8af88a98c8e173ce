"""Resuming an interrupted run of a case written by bin/hearthCase
(`hearthCase -resume CASEDIR`, which runs `CASEDIR/Allrun -resume`).

    python3 hearthCaseRestart.py check CASE     the restart point, or why not
    python3 hearthCaseRestart.py prepare CASE   make CASE ready to resume
    python3 hearthCaseRestart.py merge CASE     one sensor history

The restart point is the latest time written whole: a time folder (in
every processor* folder when the case is decomposed) whose balance block
('Energy balance at t = ' of ahcFoam, 'Water balance at t = ' of
pendularFoam) is in the solver's log. The solvers print that block after
runTime.write() and after a global sum (gSum), so every rank had written
that time; a later folder may be cut short by the interrupt. The start of
the run the log belongs to (0, or the time an earlier resume restarted
from) counts as written whole too.

prepare: the folders after the restart point are removed (cut short), the
solver's log is kept as log.<solver>.<restart time> (the part of the
history up to that time: its balances there are the ones the summary adds
up; a log that wrote nothing since its own start is removed), and
system/controlDict gets `startFrom latestTime` (its line alone edited,
checked by foamDictionary). A solver that had ended (End in its log, the restart
point at endTime) is not run again: only the post-processing.

merge: a restarted run writes its thermocouples' rows into a new folder
postProcessing/thermocouples/<its start time>/ (the function object's
rule, as probes). The histories are merged into
postProcessing/thermocouples/0/sensors.csv (which every reader of the
case takes: plotSensors, hearthCaseSummary): each folder's rows up to
and including the next folder's start time, then the rows after it from
that folder (the rows the interrupted run wrote after the restart time are
dropped: the resumed run computed them again). The later folders are kept
as written (merging again gives the same file). A row cut short by the
interrupt (no end of line) is not a row. Refused: another header, or an
earlier folder without a row at the next one's start (a gap).
"""

import math
import os
import re
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import hearthTutorial as ht      # noqa: E402

HEADING = {'ahcFoam': 'Energy balance at t = ',
           'pendularFoam': 'Water balance at t = '}


class RestartError(Exception):
    pass


def same(a, b):
    """Two time values equal to the time names' round-off (timePrecision
    10 of the templates)"""
    return abs(a - b) <= 1e-9*max(abs(a), abs(b), 1.0)


def info(case):
    """system/hearthCaseInfo as a dict keyword -> value (text)"""
    d = {}
    with open(os.path.join(case, 'system', 'hearthCaseInfo')) as f:
        for line in f:
            if line.strip():
                k, v = (line.split(None, 1) + [''])[:2]
                d.setdefault(k, v.strip())
    return d


def isTime(name):
    return re.match(r'^[-+]?[0-9.]+([eE][-+]?[0-9]+)?$', name) is not None \
        and name not in ('.', '..')


def timeNames(path):
    """The time folders of path (names), sorted by value"""
    if not os.path.isdir(path):
        return []
    names = [n for n in os.listdir(path)
             if isTime(n) and os.path.isdir(os.path.join(path, n))]
    return sorted(names, key=float)


def timeRoots(case, ranks):
    """Where the solver writes its times: CASE, or processor0..N-1"""
    if ranks > 1:
        return [os.path.join(case, 'processor%d' % i) for i in range(ranks)]
    return [case]


def segmentLogs(case, solver):
    """The solver's logs of the run in order: [(path, up to time name)]
    for the interrupted parts (log.<solver>.<time>), then (log.<solver>,
    None), the last part (if present)"""
    base = 'log.' + solver
    parts = sorted((n[len(base) + 1:] for n in os.listdir(case)
                    if n.startswith(base + '.') and isTime(n[len(base) + 1:])),
                   key=float)
    out = [(os.path.join(case, base + '.' + t), t) for t in parts]
    if os.path.isfile(os.path.join(case, base)):
        out.append((os.path.join(case, base), None))
    return out


def balanceTimes(log, solver):
    """The times (values) whose balance block is in the log"""
    if not os.path.isfile(log):
        return []
    out = []
    with open(log, errors='replace') as f:
        for line in f:
            if line.startswith(HEADING[solver]):
                out.append(float(line[len(HEADING[solver]):].split()[0]))
    return out


def ended(log):
    if not os.path.isfile(log):
        return False
    with open(log, errors='replace') as f:
        return any(line.rstrip('\n') == 'End' for line in f)


def endTime(case):
    r = subprocess.run(['foamDictionary', '-entry', 'endTime', '-value',
                        os.path.join(case, 'system', 'controlDict')],
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                       universal_newlines=True)
    try:
        return float(r.stdout.split()[0])
    except (IndexError, ValueError):
        raise RestartError('system/controlDict: cannot read endTime: %s'
                           % r.stdout.strip()[:300])


def restartPoint(case):
    """(time name, whether the solver must run): the latest time written
    whole (module doc); RestartError if there is none after the start"""
    inf = info(case)
    solver, ranks = inf['solver'], int(inf['ranks'])
    log = os.path.join(case, 'log.' + solver)
    segs = segmentLogs(case, solver)
    # log.<solver> started where the latest kept part ends (or at 0)
    start = max([float(upto) for _, upto in segs if upto is not None] + [0])
    roots = timeRoots(case, ranks)
    written = [t for t in timeNames(roots[0])
               if all(os.path.isdir(os.path.join(r, t)) for r in roots[1:])]
    whole = balanceTimes(log, solver) + [start]
    ok = [t for t in written if any(same(float(t), w) for w in whole)]
    if not ok or float(ok[-1]) <= 0:
        where = 'processor*/' if ranks > 1 else ''
        raise RestartError(
            'nothing written yet: the solver wrote no time after 0 (%s<time>/ '
            'folders with their balance in log.%s), so there is nothing to '
            'resume from; start it from scratch' % (where, solver))
    t = ok[-1]
    run = not (ended(log) and float(t) >= endTime(case)*(1 - 1e-12))
    return t, run


def setStartFrom(case):
    """startFrom latestTime in system/controlDict: that entry's line
    alone is edited (foamDictionary -set rewrites the whole file, without
    its comments), then read back by foamDictionary"""
    path = os.path.join(case, 'system', 'controlDict')
    with open(path) as f:
        text = f.read()
    new, n = re.subn(r'(?m)^(\s*startFrom\s+)\w+(\s*;)', r'\g<1>latestTime\2',
                     text)
    if n != 1:
        raise RestartError('%s: %d lines "startFrom ...;" (one expected): set '
                           'startFrom latestTime yourself' % (path, n))
    if new != text:
        with open(path, 'w') as f:
            f.write(new)
    r = subprocess.run(['foamDictionary', '-entry', 'startFrom', '-value',
                        path], stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, universal_newlines=True)
    if r.stdout.strip() != 'latestTime':
        raise RestartError('%s: startFrom reads %r after the edit, not '
                           'latestTime' % (path, r.stdout.strip()[:200]))


def prepare(case):
    """Make CASE ready for its Allrun -resume (module doc); prints what it
    did, and 'runSolver yes|no' last"""
    inf = info(case)
    solver, ranks = inf['solver'], int(inf['ranks'])
    t, run = restartPoint(case)
    log = os.path.join(case, 'log.' + solver)
    if not run:
        print('the solver had ended at t = %s s: the post-processing only'
              % t)
        print('runSolver no')
        return
    for root in timeRoots(case, ranks) + ([case] if ranks > 1 else []):
        for name in timeNames(root):
            if float(name) > float(t) and not same(float(name), float(t)):
                shutil.rmtree(os.path.join(root, name))
                print('removed %s (written after t = %s s, cut short)'
                      % (os.path.relpath(os.path.join(root, name), case), t))
    if any(same(w, float(t)) for w in balanceTimes(log, solver)):
        os.rename(log, log + '.' + t)
        print('log.%s kept as log.%s.%s (the run up to t = %s s)'
              % (solver, solver, t, t))
    elif os.path.isfile(log):
        os.remove(log)
        print('log.%s removed (it wrote nothing after its start, %s s)'
              % (solver, t))
    setStartFrom(case)
    print('resuming %s from t = %s s (startFrom latestTime)' % (solver, t))
    print('runSolver yes')


# --------------------------------------------------------------------------
# The thermocouples' histories

def readRows(path):
    """(header line, [(time, line)]) of a sensors.csv; a last line
    without its end of line (cut short) is left out"""
    with open(path) as f:
        lines = f.read().split('\n')
    header, rows = lines[0], []
    n = header.count(',')
    for line in lines[1:-1]:            # the last: '' or cut short
        if not line.strip() or line.startswith('#'):
            continue
        if line.count(',') != n:
            raise RestartError('%s: a row of %d columns, the header has %d: '
                               '%s' % (path, line.count(',') + 1, n + 1,
                                       line[:80]))
        rows.append((float(line.split(',', 1)[0]), line))
    return header, rows


def mergeSensors(case, name='thermocouples'):
    """Merge the folders of postProcessing/NAME into its first folder's
    sensors.csv (module doc); returns the number of folders merged"""
    d = os.path.join(case, 'postProcessing', name)
    folders = timeNames(d)
    if len(folders) < 2:
        return len(folders)
    files = [os.path.join(d, f, 'sensors.csv') for f in folders]
    read = [readRows(p) for p in files]
    out = []
    for i, (header, rows) in enumerate(read):
        if header != read[0][0]:
            raise RestartError('%s: header %r, not that of %s (%r)'
                               % (files[i], header, files[0], read[0][0]))
        lo = float(folders[i])
        hi = float(folders[i + 1]) if i + 1 < len(folders) else math.inf
        if hi < math.inf and not any(same(t, hi) for t, _ in rows):
            raise RestartError(
                '%s ends at t = %s s, before the restart at %s s (%s): the '
                'history would have a gap' % (
                    files[i], rows[-1][0] if rows else 'its start',
                    folders[i + 1], files[i + 1]))
        out += [line for t, line in rows
                if (i == 0 or (t > lo and not same(t, lo)))
                and (t < hi or same(t, hi))]
    times = [float(line.split(',', 1)[0]) for line in out]
    for a, b in zip(times, times[1:]):
        if not b > a:
            raise RestartError('merged history of %s: time %s after %s'
                               % (d, b, a))
    tmp = files[0] + '.merging'
    with open(tmp, 'w') as f:
        f.write(read[0][0] + '\n' + ''.join(line + '\n' for line in out))
    os.replace(tmp, files[0])
    print('%s: the histories of %s merged (%d rows, %s to %s s)'
          % (os.path.relpath(files[0], case), ', '.join(folders), len(out),
             times[0], times[-1]))
    return len(folders)


# --------------------------------------------------------------------------
# The balances over the parts of a resumed run (hearthCaseSummary)

def runBalances(case, solver):
    """(first, parts): the balances of the whole run, as blocks of
    hearthTutorial's readers: the first block of the first log, and for
    each part its block at the time the next part started from (the last
    block of the last log). Their changes and flows add up."""
    segs = segmentLogs(case, solver)
    if not segs:
        raise RestartError('no log.%s in %s' % (solver, case))
    read = ht.energy_balances if solver == 'ahcFoam' else ht.pendular_balances
    parts, first = [], None
    for path, upto in segs:
        blocks = read(path)
        if first is None and blocks:
            first = blocks[0]
        if upto is None:
            if blocks:
                parts.append(blocks[-1])
            continue
        at = [b for b in blocks if same(b['time'], float(upto))]
        if not at:
            raise RestartError('%s: no balance at t = %s s' % (path, upto))
        parts.append(at[0])
    if not parts:
        raise RestartError('%s: no balance in its logs' % case)
    return first, parts


def main(argv):
    if len(argv) != 2 or argv[0] not in ('check', 'prepare', 'merge'):
        sys.stderr.write('Usage: hearthCaseRestart.py check|prepare|merge '
                         'CASE\n')
        return 1
    what, case = argv
    try:
        if what == 'check':
            t, run = restartPoint(case)
            print('restart from t = %s s%s' % (
                t, '' if run else ' (the solver had ended)'))
        elif what == 'prepare':
            prepare(case)
        else:
            mergeSensors(case)
    except RestartError as e:
        sys.stderr.write('%s: cannot %s: %s\n' % (case, {
            'check': 'resume', 'prepare': 'resume',
            'merge': 'merge the sensor histories'}[what], e))
        return 1
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
