#!/usr/bin/env python3
"""flatHearthAxi: CSV files and a summary from a finished (reconstructed) run.

Run in the case directory after ahcFoam (called by ./Allrun). Reads

    postProcessing/probes/0/T                    sensor histories [K]
    postProcessing/axisProfile/<t>/axis_*.xy     TMax and T down the axis [K]
    log.ahcFoam                                  energy balance

and writes

    sensors.csv     time_s, then one column T_<depth>cm_C per sensor
    TMax_axis.csv   depth_cm, TMax at the end of the fire and at the end of
                    the run [C], one row per cell of the axis column
    results.txt     the summary printed at the end

Only the Python standard library is used.
"""

import glob
import math
import os
import re
import sys

T0 = 273.15             # K
FIRE_END = 21600.0      # s, end of the 700 C fire (0/T)
PLATEAU_BAND = 5.0      # K: the "100 C plateau" is 100 +- 5 C
ALTERATION = (100.0, 290.0)     # C: drying; reddening (Muhieddine 2009 §5.4)


def read_probes(path):
    """Probe depths [cm, positive down], times [s], columns of T [K]"""
    depths, times, cols = [], [], None
    with open(path) as f:
        for line in f:
            m = re.match(r'#\s*Probe\s+\d+\s+\(\s*(\S+)\s+(\S+)\s+(\S+)\s*\)',
                         line)
            if m:
                depths.append(-100*float(m.group(3)))
                continue
            if line.startswith('#') or not line.strip():
                continue
            v = [float(x) for x in line.split()]
            if cols is None:
                cols = [[] for _ in v[1:]]
            times.append(v[0])
            for c, x in zip(cols, v[1:]):
                c.append(x)
    if cols is None or len(cols) != len(depths):
        sys.exit('hearthResults: no probe data in %s' % path)
    return depths, times, cols


def read_profile(timeDir):
    """Cell-centre depths [cm] and a dict field -> values [K] of the axis
    profile at one write time (raw set file: z and one column per field, in
    the order of the file name axis_<field1>_<field2>.xy)"""
    files = glob.glob(os.path.join(timeDir, 'axis_*.xy'))
    if len(files) != 1:
        sys.exit('hearthResults: expected one axis_*.xy in %s' % timeDir)
    names = os.path.basename(files[0])[len('axis_'):-len('.xy')].split('_')
    depth, vals = [], [[] for _ in names]
    with open(files[0]) as f:
        for line in f:
            if line.startswith('#') or not line.strip():
                continue
            v = [float(x) for x in line.split()]
            depth.append(-100*v[0])
            for c, x in zip(vals, v[1:]):
                c.append(x)
    order = sorted(range(len(depth)), key=lambda i: depth[i])
    return ([depth[i] for i in order],
            dict((n, [c[i] for i in order]) for n, c in zip(names, vals)))


def depth_reached(depth, TMaxC, level):
    """Deepest depth [cm] at which TMax = level [C], linear between cell
    centres (TMax decreases downward); None if the top cell is below it"""
    if TMaxC[0] < level:
        return None
    for i in range(1, len(depth)):
        if TMaxC[i] < level:
            a, b = TMaxC[i - 1], TMaxC[i]
            return depth[i - 1] + (level - a)/(b - a)*(depth[i] - depth[i - 1])
    return depth[-1]


def plateau(times, TC, level=100.0, band=PLATEAU_BAND):
    """First entry into and exit from [level - band, level + band] while
    heating, and the time spent inside [s]"""
    tIn = tOut = None
    for t, x in zip(times, TC):
        if tIn is None and x >= level - band:
            tIn = t
        if tIn is not None and x > level + band:
            tOut = t
            break
    if tIn is None or tOut is None:
        return tIn, tOut, None
    inside = 0.0
    for i in range(1, len(times)):
        if times[i] > tOut:
            break
        if abs(TC[i] - level) <= band and times[i - 1] >= tIn:
            inside += times[i] - times[i - 1]
    return tIn, tOut, inside


def energy_balance(log):
    """The last energy balance block of the log: dict name -> value"""
    blocks = open(log).read().split('Energy balance at t = ')
    if len(blocks) < 2:
        return None
    b = blocks[-1]
    res = {'time': float(b.split()[0])}
    for m in re.finditer(r'heat in through (\S+) = (\S+)', b):
        res['in_' + m.group(1)] = float(m.group(2))
    m = re.search(r'heat in \(all patches\) = (\S+)', b)
    res['in'] = float(m.group(1))
    m = re.search(r'stored change\s+= (\S+) \(latent (\S+),', b)
    res['stored'], res['latent'] = float(m.group(1)), float(m.group(2))
    m = re.search(r'relative (\S+)\)', b)
    res['relative'] = float(m.group(1))
    return res


def latentHeat():
    """L [J/kg] of constant/porousProperties (energyConsistent: the latent
    enthalpy is L x the mass of water evaporated)"""
    m = re.search(r'latentHeat\s+([^;\s]+)\s*;',
                  open('constant/porousProperties').read())
    return float(m.group(1)) if m else float('nan')


def hours(t):
    return '%.2f h' % (t/3600.0)


def main():
    out = []
    say = out.append

    # ---- sensors ----------------------------------------------------------
    depths, times, cols = read_probes('postProcessing/probes/0/T')
    colsC = [[x - T0 for x in c] for c in cols]
    names = ['T_%gcm_C' % round(d, 3) for d in depths]
    with open('sensors.csv', 'w') as f:
        f.write(','.join(['time_s'] + names) + '\n')
        for i, t in enumerate(times):
            f.write('%.6g,' % t
                    + ','.join('%.4f' % c[i] for c in colsC) + '\n')

    say('Sensors on the axis (sensors.csv, sensors.png):')
    for d, c in zip(depths, colsC):
        iMax = max(range(len(c)), key=lambda i: c[i])
        tIn, tOut, inside = plateau(times, c)
        line = '  %4.1f cm: peak %6.1f C at %s' % (d, c[iMax], hours(times[iMax]))
        if inside is not None:
            line += ('; 100 +- %g C from %s to %s (%.0f min)'
                     % (PLATEAU_BAND, hours(tIn), hours(tOut), inside/60))
        else:
            line += '; does not pass 100 +- %g C' % PLATEAU_BAND
        say(line)

    # ---- TMax down the axis -----------------------------------------------
    tDirs = sorted(glob.glob('postProcessing/axisProfile/*'),
                   key=lambda p: float(os.path.basename(p)))
    if not tDirs:
        sys.exit('hearthResults: no postProcessing/axisProfile output')
    tEnd = float(os.path.basename(tDirs[-1]))
    tFire = min(tDirs, key=lambda p: abs(float(os.path.basename(p)) - FIRE_END))
    depth, prof = read_profile(tDirs[-1])
    depthF, profF = read_profile(tFire)
    if depthF != depth:
        sys.exit('hearthResults: axis profiles on different points')
    TMaxC = [x - T0 for x in prof['TMax']]
    TMaxFC = [x - T0 for x in profF['TMax']]
    labelF = 'TMax_%gh_C' % (float(os.path.basename(tFire))/3600)
    with open('TMax_axis.csv', 'w') as f:
        f.write('depth_cm,%s,TMax_C\n' % labelF)
        for z, a, b in zip(depth, TMaxFC, TMaxC):
            f.write('%.4f,%.4f,%.4f\n' % (z, a, b))

    say('Maximum temperature on the axis (TMax_axis.csv, TMax_axis.png):')
    for level in ALTERATION:
        dF = depth_reached(depth, TMaxFC, level)
        dE = depth_reached(depth, TMaxC, level)
        fmt = lambda d: ('%.2f cm' % d) if d is not None else 'not reached'
        say('  TMax = %3.0f C at depth %s at the end of the fire (%s),'
            ' %s at the end of the run (%s)'
            % (level, fmt(dF), hours(float(os.path.basename(tFire))),
               fmt(dE), hours(tEnd)))

    # ---- energy balance ---------------------------------------------------
    eb = energy_balance('log.ahcFoam')
    if eb:
        sector = 1.0    # the balance is per wedge sector: x 2 pi/angle
        m = re.search(r'tan\(degToRad\((\S+?)\)\)', open('system/blockMeshDict').read())
        if m:
            sector = math.pi/math.tan(math.radians(float(m.group(1))))
        say('Energy balance at t = %s (log.ahcFoam; whole hearth = %.2f'
            ' x the wedge):' % (hours(eb['time']), sector))
        say('  heat in through the fire %.4g MJ, stored %.4g MJ'
            ' (latent %.4g MJ = %.3g kg of water evaporated)'
            % (sector*eb.get('in_fire', 0)/1e6, sector*eb['stored']/1e6,
               sector*eb['latent']/1e6, sector*eb['latent']/latentHeat()))
        far = sum(v for k, v in eb.items()
                  if k in ('in_side', 'in_bottom', 'in_ground'))
        say('  through side, bottom, ground: %.3g J (%.2g of the fire\'s);'
            ' relative imbalance %.3g'
            % (far*sector, far/max(abs(eb.get('in_fire', 0)), 1e-300),
               eb['relative']))
        if abs(eb['relative']) > 1e-6:
            say('  WARNING: relative energy imbalance above 1e-6')

    text = '\n'.join(out) + '\n'
    with open('results.txt', 'w') as f:
        f.write(text)
    sys.stdout.write(text)


if __name__ == '__main__':
    main()
