"""Resuming an interrupted run of a case written by bin/hearthCase
(`hearthCase -resume CASEDIR`, which runs `CASEDIR/Allrun -resume`).

    python3 hearthCaseRestart.py check CASE     the restart point, or why not
    python3 hearthCaseRestart.py prepare CASE   make CASE ready to resume
    python3 hearthCaseRestart.py merge CASE     one sensor history

The restart point is the latest time written whole: a time folder (in
every processor* folder when the case is decomposed) whose balance block
('Energy balance at t = ' of ahcFoam, 'Water balance at t = ' and the
air and energy balances after it of pendularFoam) is whole in one of the
solver's logs (log.<solver>, and the log.<solver>.<time> of earlier
parts; a block cut short by the interrupt does not count, and its folder
is taken as cut short), and which is whole on disk too
(uniform/time and each field of that folder written to its end, the
footer line). The solvers print that block after runTime.write() and after
a global sum (gSum), so every rank had written that time; a later folder
may be cut short by the interrupt. The start of each part of the run (0,
or the time an earlier resume restarted from) counts as written whole too.
Refused: a later folder that looks whole on disk but is in no log (a log
renamed or cut short: resuming before it would discard it), a run still
holding Allrun.lock (its process alive; a stale lock is said and
ignored), and a solver that printed End but exited non-zero
(log.<solver>.status, kept by Allrun: a failed check at its end).

prepare: the folders after the restart point (cut short) are renamed
<time>.cutShort (nothing is deleted; the solver reads no such name), the
solver's log is kept as log.<solver>.<restart time> (the part of the
history up to that time: its balances there are the ones the summary adds
up; a log that wrote nothing since its own start is removed), and
system/controlDict gets `startFrom latestTime` (its line alone edited,
written to a temporary file renamed over it, checked by foamDictionary).
A solver that had ended (End in its log, the restart point at endTime) is
not run again: only the post-processing.

merge: a restarted run writes its thermocouples' rows into a new folder
postProcessing/thermocouples/<its start time>/ (the function object's
rule, as probes). The histories are merged into
postProcessing/thermocouples/0/sensors.csv (which every reader of the
case takes: plotSensors, hearthCaseSummary): each folder's rows up to
and including the next folder's start time, then the rows after it from
that folder (the rows the interrupted run wrote after the restart time are
dropped from the merged file, the resumed run computed them again; the
interrupted run's file is kept as sensors.csv.<restart time>). A row at
the restart time missing from the earlier folder (the interrupt between
the balance print and the row's write) is taken from the next folder,
which writes it at its start. The later folders are kept
as written (merging again gives the same file). A row cut short by the
interrupt (no end of line) is not a row. Refused: another header, or an
earlier folder without a row at the next one's start in either folder (a
gap).
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
    """system/hearthCaseInfo as a dict keyword -> value (text); its
    solver and ranks checked (RestartError naming the file)"""
    path = os.path.join(case, 'system', 'hearthCaseInfo')
    d = {}
    try:
        with open(path) as f:
            for line in f:
                if line.strip():
                    k, v = (line.split(None, 1) + [''])[:2]
                    d.setdefault(k, v.strip())
    except OSError as e:
        raise RestartError('%s: cannot read it: %s' % (path, e))
    if d.get('solver') not in HEADING:
        raise RestartError('%s: keyword solver: %r, not one of %s' % (
            path, d.get('solver'), ', '.join(sorted(HEADING))))
    try:
        if int(d.get('ranks', '')) < 1:
            raise ValueError
    except ValueError:
        raise RestartError('%s: keyword ranks: %r, not a whole number >= 1'
                           % (path, d.get('ranks')))
    return d


def isTime(name):
    """A time folder's name: a number (not '2026.12.05', '.', '..')"""
    try:
        float(name)
    except ValueError:
        return False
    return re.match(r'^[-+]?[0-9.]+([eE][-+]?[0-9]+)?$', name) is not None


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


def headingTimes(log, solver):
    """The times (values) whose balance heading is in the log"""
    if not os.path.isfile(log):
        return []
    out = []
    with open(log, errors='replace') as f:
        for line in f:
            if line.startswith(HEADING[solver]):
                out.append(float(line[len(HEADING[solver]):].split()[0]))
    return out


def balanceTimes(log, solver):
    """The times (values) whose balance block is whole in the log, read
    by hearthTutorial's readers, the summary's (runBalances): a block the
    interrupt cut short is not one (pendularFoam prints its water, air and
    energy balances one after the other, each flushed: an interrupt
    between them left a time the summary of the resumed run could not
    add up, 'no balance at t = '; ahcFoam's block ends with its liquid
    water)"""
    if not os.path.isfile(log):
        return []
    if solver == 'ahcFoam':
        return [b['time'] for b in ht.energy_balances(log)
                if 'liquidWater' in b]
    return [b['time'] for b in ht.pendular_balances(log)]


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


FOOTER = '// ****'


def fileWhole(path):
    """An ASCII OpenFOAM file written to its end: its last line is the
    footer '// ****...' (the templates write ascii, controlDict)"""
    try:
        with open(path, 'rb') as f:
            f.seek(0, os.SEEK_END)
            f.seek(max(0, f.tell() - 200))
            tail = f.read().decode('ascii', 'replace').rstrip().split('\n')
    except OSError:
        return False
    return tail[-1].startswith(FOOTER)


def fields(folder):
    """The files of a time folder (its fields), names"""
    return sorted(n for n in os.listdir(folder)
                  if os.path.isfile(os.path.join(folder, n)))


def diskWhole(roots, t, names):
    """Time t written whole on disk: in every root, uniform/time and each
    field of names there and written to its end"""
    return all(fileWhole(os.path.join(r, t, n))
               for r in roots for n in ['uniform/time'] + names)


def solverStatus(case, solver):
    """The solver's exit status Allrun kept in log.<solver>.status (None:
    not kept, e.g. it was interrupted)"""
    path = os.path.join(case, 'log.%s.status' % solver)
    try:
        with open(path) as f:
            return int(f.read().split()[0])
    except (OSError, IndexError, ValueError):
        return None


def lockHolder(case):
    """The pid of a run still going in CASE (Allrun.lock, written by Allrun
    while it runs), or None; a stale lock (its process gone) is said so"""
    path = os.path.join(case, 'Allrun.lock')
    try:
        with open(path) as f:
            pid = int(f.read().split()[0])
    except (OSError, IndexError, ValueError):
        return None
    if pid == os.getppid():
        return None                 # prepare, run by that Allrun itself
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        sys.stderr.write('%s: stale lock (process %d is gone): going on\n'
                         % (path, pid))
        return None
    except PermissionError:
        pass
    return pid


def restartPoint(case):
    """(time name, whether the solver must run): the latest time written
    whole (module doc); RestartError if there is none after the start, or
    if a later folder looks whole on disk but no log confirms it, or if a
    run still holds the case's lock, or if the solver ended failing"""
    inf = info(case)
    solver, ranks = inf['solver'], int(inf['ranks'])
    pid = lockHolder(case)
    if pid is not None:
        raise RestartError('a run is still going in it (process %d, %s): '
                           'stop it first (kill %d) or let it end'
                           % (pid, os.path.join(case, 'Allrun.lock'), pid))
    log = os.path.join(case, 'log.' + solver)
    segs = segmentLogs(case, solver)
    starts = [float(upto) for _, upto in segs if upto is not None] + [0]
    # whole by the logs: a balance in any part, or a part's start
    confirmed = starts + [w for p, _ in segs for w in balanceTimes(p, solver)]
    roots = timeRoots(case, ranks)
    names = sorted(set(n for r in roots for n in timeNames(r)), key=float)
    byLog = [t for t in names if any(same(float(t), w) for w in confirmed)
             and all(os.path.isdir(os.path.join(r, t)) for r in roots)]
    where = 'processor*/' if ranks > 1 else ''
    if not byLog:
        raise RestartError('%s: no time folder (not even 0) in %s' % (
            case, where or 'the case'))
    t = byLog[-1]
    ref = fields(os.path.join(roots[0], t))
    later = [n for n in names if float(n) > float(t) and not same(float(n),
                                                                  float(t))]
    # a later folder whose balance the interrupt cut short in the last log
    # (its heading printed, not the whole block) is cut short, whole on
    # disk or not: the resumed run writes it again
    whole = balanceTimes(log, solver)      # the log parsed once
    cut = [w for w in headingTimes(log, solver)
           if not any(same(w, b) for b in whole)]
    looks = [n for n in later if diskWhole(roots, n, ref)
             and not any(same(float(n), w) for w in cut)]
    if looks:
        raise RestartError(
            '%s%s looks written whole (uniform/time and the fields of %s, on '
            'every rank) but no log.%s* has its balance (a log renamed, '
            'removed or cut short?); resuming from %s s would discard it. '
            'Restore the log that has it, or move %s aside yourself to '
            'resume from %s s' % (where, looks[-1], t, solver, t,
                                  ', '.join(where + n for n in looks), t))
    if float(t) <= 0:
        if later:
            raise RestartError(
                'nothing written whole after 0: the time folder(s) %s were '
                'cut short (a field or uniform/time missing or not written '
                'to its end), so there is nothing to resume from; start it '
                'from scratch' % ', '.join(where + n for n in later))
        raise RestartError(
            'nothing written yet: the solver wrote no time after 0 (%s<time>/ '
            'folders), so there is nothing to resume from; start it '
            'from scratch' % where)
    if not diskWhole(roots, t, ref):
        raise RestartError('%s%s: its balance is in log.%s* but a file of it '
                           'is not written to its end' % (where, t, solver))
    status = solverStatus(case, solver)
    if ended(log) and status:
        raise RestartError(
            '%s ended (End in log.%s) with exit status %d (log.%s.status): '
            'it failed a check at its end (see the end of log.%s); running '
            'it again would not change that' % (solver, solver, status,
                                                 solver, solver))
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
        tmp = path + '.resuming'
        with open(tmp, 'w') as f:
            f.write(new)
        os.replace(tmp, path)       # a Ctrl-C leaves the old or the new
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
                old = os.path.join(root, name)
                new = old + '.cutShort'
                i = 1
                while os.path.exists(new):
                    new, i = '%s.cutShort%d' % (old, i), i + 1
                os.rename(old, new)
                print('%s renamed %s (written after t = %s s, cut short; '
                      'the solver does not read it)'
                      % (os.path.relpath(old, case),
                         os.path.basename(new), t))
    if os.path.isfile(log + '.status'):
        os.remove(log + '.status')  # the resumed run writes its own
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
    fromNext = False        # folder i's row at its start taken from it
    for i, (header, rows) in enumerate(read):
        if header != read[0][0]:
            raise RestartError('%s: header %r, not that of %s (%r)'
                               % (files[i], header, files[0], read[0][0]))
        lo = float(folders[i])
        hi = float(folders[i + 1]) if i + 1 < len(folders) else math.inf
        atStart = i == 0 or fromNext
        fromNext = False
        if hi < math.inf and not any(same(t, hi) for t, _ in rows):
            # the interrupt between the balance print and the row's write:
            # the resumed run wrote that row again at its start
            if not any(same(t, hi) for t, _ in read[i + 1][1]):
                raise RestartError(
                    '%s ends at t = %s s, before the restart at %s s (%s): '
                    'the history would have a gap' % (
                        files[i], rows[-1][0] if rows else 'its start',
                        folders[i + 1], files[i + 1]))
            fromNext = True
        out += [line for t, line in rows
                if (atStart or (t > lo and not same(t, lo)))
                and (t < hi or same(t, hi) and not fromNext)]
    times = [float(line.split(',', 1)[0]) for line in out]
    for a, b in zip(times, times[1:]):
        if not b > a:
            raise RestartError('merged history of %s: time %s after %s'
                               % (d, b, a))
    tmp = files[0] + '.merging'
    with open(tmp, 'w') as f:
        f.write(read[0][0] + '\n' + ''.join(line + '\n' for line in out))
    # the interrupted run's own history kept (first merge only: later the
    # file holds merged rows)
    keep = '%s.%s' % (files[0], folders[1])
    if not os.path.exists(keep):
        os.link(files[0], keep)
    os.replace(tmp, files[0])
    print('%s: the histories of %s merged (%d rows, %s to %s s)'
          % (os.path.relpath(files[0], case), ', '.join(folders), len(out),
             times[0], times[-1]))
    return len(folders)


# --------------------------------------------------------------------------
# The balances over the parts of a resumed run (hearthCaseSummary)

def runBalances(case, solver):
    """The balances of the whole run, as blocks of hearthTutorial's
    readers: for each part its block at the time the next part started from
    (the last block of the last log), with 'log' its log's path. Each part's
    flows, stored change and (ahcFoam) water evaporated count from its own
    start: they add up."""
    segs = segmentLogs(case, solver)
    if not segs:
        raise RestartError('no log.%s in %s' % (solver, case))
    read = ht.energy_balances if solver == 'ahcFoam' else ht.pendular_balances
    parts = []
    for path, upto in segs:
        blocks = read(path)
        if upto is None:
            if blocks:
                parts.append(dict(blocks[-1], log=path))
            continue
        at = [b for b in blocks if same(b['time'], float(upto))]
        if not at:
            raise RestartError('%s: no balance at t = %s s' % (path, upto))
        parts.append(dict(at[0], log=path))
    if not parts:
        raise RestartError('%s: no balance in its logs' % case)
    return parts


def runTotals(case, solver):
    """The balances of the whole run added up over its parts (runBalances),
    for the mesh (per wedge sector): time (the last), heatIn, stored,
    imbalance [J] and water [kg], the water evaporated (ahcFoam: each
    part's liquid water at its start minus at its end) or that left through
    the patches (pendularFoam)"""
    parts = runBalances(case, solver)
    if solver == 'ahcFoam':
        for b in parts:
            if 'evaporated' not in b:
                raise RestartError(
                    '%s: its balance at t = %g s gives no initial liquid'
                    ' water (ahcFoam older than 2026-12-05): the water'
                    ' evaporated since the start cannot be counted; run the'
                    ' case again' % (b['log'], b['time']))
        return dict(time=parts[-1]['time'],
                    heatIn=sum(b['in'] for b in parts),
                    stored=sum(b['stored'] for b in parts),
                    imbalance=sum(b['imbalance'] for b in parts),
                    water=sum(b['evaporated'] for b in parts),
                    parts=parts)
    return dict(time=parts[-1]['time'],
                heatIn=-sum(b['energy']['out'] for b in parts),
                stored=sum(b['energy']['stored'] for b in parts),
                imbalance=sum(b['energy']['imbalance'] for b in parts),
                water=sum(b['water']['out'] for b in parts),
                parts=parts)


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
