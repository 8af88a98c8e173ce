"""Readers shared by the tutorials' results scripts (standard library only).

A tutorial script imports it with

    import os, sys
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                    '..', '..', 'etc', 'python'))
    import hearthTutorial as ht

It reads what hearthFoam writes (thermocouple CSV files, probes, axis
profiles, the balance blocks of ahcFoam and pendularFoam logs,
hearthAlteration's summary; its balance readers are the project's only
ones: tests/lib/hearthcheck.py uses them too) and writes `figures.csv`:
one row name,value,unit per result figure a tutorial's README states,
which the test of the tutorial (tests/tutorial<Name>/) compares with the
README.
"""

import csv
import glob
import math
import os
import re

T0 = 273.15     # K at 0 C


# --------------------------------------------------------------------------
# Sensor histories

def read_csv(path):
    """A CSV file with a header line ('#' lines and blank lines skipped)
    -> (header, rows of floats)."""
    with open(path) as f:
        lines = [r for r in csv.reader(f) if r and not r[0].startswith('#')]
    return lines[0], [[float(x) for x in r] for r in lines[1:]]


def read_sensors(path):
    """The CSV of the thermocouples function object (time_s, then one
    column per sensor, in C) -> dict header -> list of values (in file
    order, 'time_s' included)."""
    header, rows = read_csv(path)
    return dict((h, [r[i] for r in rows]) for i, h in enumerate(header))


def sensors_of(case='.', name='thermocouples'):
    """read_sensors of CASE/postProcessing/NAME/0/sensors.csv"""
    return read_sensors(os.path.join(case, 'postProcessing', name, '0',
                                     'sensors.csv'))


def read_probes(path):
    """An OpenFOAM probes file -> (locations [(x, y, z)], times [s],
    columns[probe][time])."""
    locations, times, cols = [], [], None
    with open(path) as f:
        for line in f:
            if line.startswith('#'):
                m = re.match(r'#\s*Probe\s+\d+\s+\(([^)]*)\)', line)
                if m:
                    locations.append(tuple(float(v) for v in m.group(1).split()))
                continue
            v = line.split()
            if not v:
                continue
            times.append(float(v[0]))
            if cols is None:
                cols = [[] for _ in v[1:]]
            for c, x in zip(cols, v[1:]):
                c.append(float(x))
    if cols is None or len(cols) != len(locations):
        raise ValueError('no probe data in %s' % path)
    return locations, times, cols


def crossing(t, T, level):
    """First time at which T reaches level, linear between the samples;
    None if never."""
    if T and T[0] >= level:
        return t[0]
    for i in range(1, len(t)):
        if T[i] >= level > T[i - 1]:
            return t[i - 1] + (level - T[i - 1])*(t[i] - t[i - 1]) \
                / (T[i] - T[i - 1])
    return None


def first_sample(t, T, level):
    """Time of the first sample at or above level (no interpolation);
    None if never."""
    for ti, x in zip(t, T):
        if x >= level:
            return ti
    return None


def peak(t, T):
    """(largest value, time of its first occurrence)"""
    i = max(range(len(T)), key=lambda k: T[k])
    return T[i], t[i]


def interpolate(times, values, t):
    """values linear in times at t (held constant outside)"""
    if t <= times[0]:
        return values[0]
    if t >= times[-1]:
        return values[-1]
    lo, hi = 0, len(times) - 1
    while hi - lo > 1:
        mid = (lo + hi)//2
        if times[mid] <= t:
            lo = mid
        else:
            hi = mid
    w = (t - times[lo])/(times[hi] - times[lo])
    return values[lo] + w*(values[hi] - values[lo])


# --------------------------------------------------------------------------
# Profiles

def depth_reached(depth, TMax, level):
    """Deepest depth at which TMax (decreasing with depth) = level, linear
    between the points; None if the first point is below level."""
    if TMax[0] < level:
        return None
    for i in range(1, len(depth)):
        if TMax[i] < level:
            a, b = TMax[i - 1], TMax[i]
            return depth[i - 1] + (level - a)/(b - a)*(depth[i] - depth[i - 1])
    return depth[-1]


def read_internal_field(path):
    """Values of an ascii volScalarField's internalField (uniform: one
    value; nonuniform List<scalar>: the list). One reader for the tests
    (tests/lib/hearthcheck.py) and the tutorials."""
    with open(path) as f:
        txt = f.read()
    m = re.search(r'internalField\s+uniform\s+(\S+);', txt)
    if m:
        return [float(m.group(1))]
    m = re.search(r'internalField\s+nonuniform\s+List<scalar>\s*(\d+)\s*\(',
                  txt)
    if not m:
        raise SystemExit('%s: no ascii scalar internalField' % path)
    n = int(m.group(1))
    body = txt[m.end():]
    return [float(v) for v in body.split(')')[0].split()[:n]]


def time_dirs(path):
    """The numeric subfolders of path, sorted by time"""
    return sorted((d for d in glob.glob(os.path.join(path, '*'))
                   if re.match(r'^[-+.\deE]+$', os.path.basename(d))),
                  key=lambda d: float(os.path.basename(d)))


def read_axis_set(timeDir, name='axis'):
    """A raw 'sets' file <timeDir>/<name>_<field1>_<field2>....xy of a line
    down z (columns z, then one per field) -> (depths [cm, positive down,
    increasing], dict field -> values in the same order)."""
    files = glob.glob(os.path.join(timeDir, name + '_*.xy'))
    if len(files) != 1:
        raise ValueError('expected one %s_*.xy in %s' % (name, timeDir))
    fields = os.path.basename(files[0])[len(name) + 1:-len('.xy')].split('_')
    rows = []
    with open(files[0]) as f:
        for line in f:
            if line.startswith('#') or not line.strip():
                continue
            rows.append([float(x) for x in line.split()])
    rows.sort(key=lambda r: -r[0])
    return ([-100*r[0] for r in rows],
            dict((fld, [r[i + 1] for r in rows])
                 for i, fld in enumerate(fields)))


# --------------------------------------------------------------------------
# Energy balance of an ahcFoam log

def energy_balance_blocks(log):
    """Every 'Energy balance at t = ...' block of an ahcFoam log, as lists
    of lines (the heading first, up to the first blank line)."""
    with open(log, errors='replace') as f:   # a log: never a traceback
        lines = f.read().splitlines()
    blocks = []
    for i, l in enumerate(lines):
        if l.startswith('Energy balance at t ='):
            block = [l]
            for m in lines[i + 1:]:
                if not m.strip():
                    break
                block.append(m.strip())
            blocks.append(block)
    return blocks


def parse_energy_balance(block):
    """One block of energy_balance_blocks -> dict: time, in_<patch> [J],
    in, stored, latent, sensible, imbalance, relative, liquidWater (now),
    initialLiquidWater (at the start of the run, or of this part of a
    resumed run, at time waterStart [s]), evaporated (initial - now) [kg]
    (the entries present: ahcFoam before 2026-12-05 printed the liquid
    water now only)."""
    text = '\n'.join(block)
    res = {'time': float(re.search(r'at t = (\S+)', text).group(1))}
    for m in re.finditer(r'heat in through (\S+) = (\S+)', text):
        res['in_' + m.group(1)] = float(m.group(2))
    patterns = (('in', r'heat in \(all patches\) = (\S+)'),
                ('stored', r'stored change\s+= (\S+)'),
                ('latent', r'\(latent (\S+?),'),
                ('sensible', r'sensible (\S+?)\)'),
                ('imbalance', r'imbalance\s+= (\S+)'),
                ('relative', r'\(relative (\S+?)\)'),
                ('liquidWater', r'liquid water\s+= (\S+)'),
                ('initialLiquidWater', r'liquid water\s+= .*?\(initial (\S+)'),
                ('waterStart', r'liquid water\s+= .*? kg at t = (\S+) s'),
                ('evaporated', r'liquid water\s+= .*?, evaporated (\S+) kg'))
    for key, p in patterns:
        m = re.search(p, text)
        if m:
            res[key] = float(m.group(1))
    return res


def energy_balances(log):
    """Every energy balance block of an ahcFoam log, parsed
    (parse_energy_balance), in order."""
    return [parse_energy_balance(b) for b in energy_balance_blocks(log)]


def energy_balance(log, block=-1):
    """One energy balance block of an ahcFoam log (default: the last),
    parsed (parse_energy_balance); None if the log has none."""
    blocks = energy_balance_blocks(log)
    if not blocks:
        return None
    return parse_energy_balance(blocks[block])


def latent_heat(path=None):
    """latentHeat [J/kg] of ahcFoam's phaseChange in a soil dictionary
    (default: constant/soilProperties, else its deprecated alias
    constant/porousProperties; nan if absent)"""
    if path is None:
        path = 'constant/soilProperties'
        if not os.path.exists(path):
            path = 'constant/porousProperties'
    with open(path) as f:
        text = f.read()
    m = re.search(r'phaseChange\s*\{[^}]*?latentHeat\s+([^;\s]+)\s*;', text) \
        or re.search(r'latentHeat\s+([^;\s]+)\s*;', text)
    return float(m.group(1)) if m else float('nan')


def wedge_to_full(blockMeshDict='system/blockMeshDict'):
    """Factor from one wedge sector to the whole disc, from the
    'tan(degToRad(ANGLE))' of a wedge blockMeshDict (1 if none)."""
    with open(blockMeshDict) as f:
        m = re.search(r'tan\(degToRad\((\S+?)\)\)', f.read())
    return math.pi/math.tan(math.radians(float(m.group(1)))) if m else 1.0


# --------------------------------------------------------------------------
# Balances of a pendularFoam log

def pendular_balances(log):
    """Every write's balances of a pendularFoam log -> list of dicts:
    time, and for each of 'water' [kg], 'air' [kg], 'energy' [J] a dict
    out_<patch>, inDomain, stored, bdf2 (the BDF2 term C^N of the stored
    change, with timeScheme BDF2 only), out, imbalance, relative; nOutside (cells
    above the pendular range), alphaLMin, alphaLMax."""
    with open(log, errors='replace') as f:   # a log: never a traceback
        text = f.read()
    out = []
    blocks = re.split(r'\n(?=Water balance at t = )', text)[1:]
    for i, block in enumerate(blocks):
        block = block.split('\n\n')[0]
        res = {'time': float(re.match(r'Water balance at t = (\S+)',
                                      block).group(1))}
        sections = [re.search(what + r' balance at t = .*?\n((?:    .*\n?)*)',
                              block) for what in ('Water', 'Air', 'Energy')]
        if not all(m and re.search(r'imbalance', m.group(1))
                   for m in sections):
            if i == len(blocks) - 1:
                break       # the log ends within its last write's balances
            raise SystemExit('%s: the balances at t = %g are incomplete'
                             % (log, res['time']))
        for what, m in zip(('Water', 'Air', 'Energy'), sections):
            d = {}
            for k, v in re.findall(r'out through (\S+) = (\S+)', m.group(1)):
                d['out_' + k] = float(v)
            for key, pat in (('inDomain', r'in the domain\s+= (\S+)'),
                             ('stored', r'stored change\s+= (\S+)'),
                             ('bdf2', r'of which BDF2 term\s+= (\S+)'),
                             ('out', r'out \(all patches\)\s+= (\S+)'),
                             ('imbalance', r'imbalance\s+= (\S+)'),
                             ('relative', r'\(relative (\S+?)\)')):
                mm = re.search(pat, m.group(1))
                if mm:
                    d[key] = float(mm.group(1))
            res[what.lower()] = d
        m = re.search(r'Pendular range: (\d+) cells', block)
        if m:
            res['nOutside'] = int(m.group(1))
        m = re.search(r'alpha_l (\S+) to (\S+), T', block)
        if m:
            res['alphaLMin'], res['alphaLMax'] = float(m.group(1)), \
                float(m.group(2))
        out.append(res)
    return out


def worst_pendular_imbalances(log, airHeld=False):
    """Largest |relative imbalance| of the water, air and energy balances
    over every block of a pendularFoam log -> dict 'water', 'air',
    'energy' (0 without blocks); with airHeld, also 'air_held': the
    largest |air imbalance| relative to the air in the domain (the air's
    flows are ~0: its own relative figure is no measure)."""
    worst = dict.fromkeys(('water', 'air', 'energy'), 0.0)
    if airHeld:
        worst['air_held'] = 0.0
    for b in pendular_balances(log):
        for kind in ('water', 'air', 'energy'):
            worst[kind] = max(worst[kind], abs(b[kind]['relative']))
        if airHeld:
            worst['air_held'] = max(worst['air_held'],
                                    abs(b['air']['imbalance']
                                        / b['air']['inDomain']))
    return worst


# --------------------------------------------------------------------------
# hearthAlteration

def alteration_summary(case='.', time=None):
    """The rows of hearthAlteration's summary.csv (dicts of strings) at
    the given time folder name, default the latest."""
    if time is None:
        path = time_dirs(os.path.join(case, 'postProcessing',
                                      'hearthAlteration'))[-1]
    else:
        path = os.path.join(case, 'postProcessing', 'hearthAlteration', time)
    with open(os.path.join(path, 'summary.csv')) as f:
        return list(csv.DictReader(f))


def alteration_depth(rows, line, threshold):
    """Depth [m] of TMax >= threshold along a line of alteration_summary"""
    for r in rows:
        if float(r['threshold_C']) == float(threshold):
            return float(r['depth_%s_m' % line])
    raise KeyError('no threshold %g in the alteration summary' % threshold)


# --------------------------------------------------------------------------
# Solver logs

def log_stats(log):
    """Steps, rejected sub-steps, last ExecutionTime and ClockTime [s] of
    an ahcFoam or pendularFoam log."""
    steps, rejected, exe, clock = 0, 0, None, None
    with open(log, errors='replace') as f:   # a log: never a traceback
        for line in f:
            m = re.match(r'^(ahcFoam|pendularFoam): deltaT = .*rejected = '
                         r'(\d+)', line)
            if m:
                steps += 1
                rejected += int(m.group(2))
            m = re.match(r'ExecutionTime = ([\d.eE+-]+) s\s+ClockTime = '
                         r'([\d.eE+-]+) s', line)
            if m:
                exe, clock = float(m.group(1)), float(m.group(2))
    return steps, rejected, exe, clock


# --------------------------------------------------------------------------
# Markdown tables of results

def fmt(v, spec):
    """v formatted by spec, or '-' when it is None or NaN."""
    return '-' if v is None or (isinstance(v, float) and math.isnan(v)) \
        else spec % v


def table(say, title, runs, rows):
    """A markdown table of runs, one line per run, passed line by line to
    say (a function of one string): runs a list of (label, results dict),
    rows the columns (label, key, scale, format); a missing value '-'."""
    say(title)
    say('| run | ' + ' | '.join(r[0] for r in rows) + ' |')
    say('|---|' + '---|'*len(rows))
    for label, r in runs:
        say('| %s | ' % label + ' | '.join(
            fmt(None if r.get(k) is None else r[k]*sc, f)
            for _, k, sc, f in rows) + ' |')
    say()


# --------------------------------------------------------------------------
# figures.csv

class Figures:
    """The result figures a tutorial's README states, collected by its
    results script and written as figures.csv (name,value,unit), full
    precision: the README rounds them, the test compares."""

    def __init__(self):
        self.rows = []

    def add(self, name, value, unit):
        if value is None:
            value = float('nan')        # 'not reached'
        self.rows.append((name, float(value), unit))

    def write(self, path='figures.csv'):
        with open(path, 'w') as f:
            f.write('name,value,unit\n')
            for name, value, unit in self.rows:
                f.write('%s,%.10g,%s\n' % (name, value, unit))
