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
    figures.csv     name,value,unit of every result figure README.md states
                    (checked by tests/tutorialFlatHearthAxi)

Standard library and etc/python/hearthTutorial.py only.
"""

import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                '..', '..', 'etc', 'python'))
import hearthTutorial as ht       # noqa: E402  (etc/python/hearthTutorial.py)

T0 = ht.T0
FIRE_END = 21600.0      # s, end of the 700 C fire (0/T)
PLATEAU_BAND = 5.0      # K: the "100 C plateau" is 100 +- 5 C
ALTERATION = (100.0, 290.0)     # C: drying; reddening (Muhieddine 2009 §5.4)


def read_profile(timeDir):
    """Cell-centre depths [cm] and a dict field -> values [K] of the axis
    profile at one write time"""
    return ht.read_axis_set(timeDir)


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


def hours(t):
    return '%.2f h' % (t/3600.0)


def main():
    out = []
    say = out.append
    fig = ht.Figures()

    # ---- sensors ----------------------------------------------------------
    locations, times, cols = ht.read_probes('postProcessing/probes/0/T')
    depths = [-100*p[2] for p in locations]
    colsC = [[x - T0 for x in c] for c in cols]
    names = ['T_%gcm_C' % round(d, 3) for d in depths]
    with open('sensors.csv', 'w') as f:
        f.write(','.join(['time_s'] + names) + '\n')
        for i, t in enumerate(times):
            f.write('%.6g,' % t
                    + ','.join('%.4f' % c[i] for c in colsC) + '\n')

    say('Sensors on the axis (sensors.csv, sensors.png):')
    for d, c in zip(depths, colsC):
        Tpeak, tPeak = ht.peak(times, c)
        t100 = ht.crossing(times, c, 100.0)
        t290 = ht.crossing(times, c, 290.0)
        tIn, tOut, inside = plateau(times, c)
        line = '  %4.1f cm: peak %6.1f C at %s' % (d, Tpeak, hours(tPeak))
        if inside is not None:
            line += ('; 100 C at %s, 100 +- %g C from %s to %s (%.0f min)'
                     % (hours(t100), PLATEAU_BAND, hours(tIn), hours(tOut),
                        inside/60))
        else:
            line += '; does not pass 100 +- %g C' % PLATEAU_BAND
        line += '; 290 C at %s' % (hours(t290) if t290 else 'never')
        say(line)
        s = '%gcm' % round(d, 3)
        fig.add('peak_%s' % s, Tpeak, 'C')
        fig.add('peakTime_%s' % s, tPeak/3600, 'h')
        fig.add('t100_%s' % s, t100 and t100/3600, 'h')
        fig.add('plateauIn_%s' % s, tIn and tIn/3600, 'h')
        fig.add('plateauOut_%s' % s, tOut and tOut/3600, 'h')
        fig.add('plateauMinutes_%s' % s, inside and inside/60, 'min')
        fig.add('t290_%s' % s, t290 and t290/3600, 'h')

    # ---- TMax down the axis -----------------------------------------------
    tDirs = ht.time_dirs('postProcessing/axisProfile')
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
        dF = ht.depth_reached(depth, TMaxFC, level)
        dE = ht.depth_reached(depth, TMaxC, level)
        fmt = lambda d: ('%.2f cm' % d) if d is not None else 'not reached'
        say('  TMax = %3.0f C at depth %s at the end of the fire (%s),'
            ' %s at the end of the run (%s)'
            % (level, fmt(dF), hours(float(os.path.basename(tFire))),
               fmt(dE), hours(tEnd)))
        fig.add('depth%g_fireEnd' % level, dF, 'cm')
        fig.add('depth%g_runEnd' % level, dE, 'cm')
        if level == 100.0 and dF is not None and dE is not None:
            fig.add('dryingAfterFire', dE - dF, 'cm')

    # ---- energy balance ---------------------------------------------------
    eb = ht.energy_balance('log.ahcFoam')
    if eb:
        sector = ht.wedge_to_full()     # the balance is per wedge sector
        water = sector*eb['evaporated']     # the log's: initial - now
        say('Energy balance at t = %s (log.ahcFoam; whole hearth = %.2f'
            ' x the wedge):' % (hours(eb['time']), sector))
        say('  heat in through the fire %.4g MJ, stored %.4g MJ'
            ' (latent %.4g MJ = %.3g kg of water evaporated)'
            % (sector*eb.get('in_fire', 0)/1e6, sector*eb['stored']/1e6,
               sector*eb['latent']/1e6, water))
        far = sum(v for k, v in eb.items()
                  if k in ('in_side', 'in_bottom', 'in_ground'))
        farFraction = -far/max(abs(eb.get('in_fire', 0)), 1e-300)
        say('  through side, bottom, ground: %.3g J (%.2g of the fire\'s);'
            ' relative imbalance %.3g'
            % (far*sector, -farFraction, eb['relative']))
        if abs(eb['relative']) > 1e-6:
            say('  WARNING: relative energy imbalance above 1e-6')
        fig.add('heatInFire', sector*eb.get('in_fire', 0)/1e6, 'MJ')
        fig.add('waterEvaporated', water, 'kg')
        fig.add('latentHeat', sector*eb['latent']/1e6, 'MJ')
        fig.add('heatLeavingFar', 100*farFraction, '%')
        fig.add('relativeImbalance', eb['relative'], '1')

    steps, rejected, _, _ = ht.log_stats('log.ahcFoam')
    fig.add('steps', steps, '1')
    fig.add('rejected', rejected, '1')

    fig.write('figures.csv')
    text = '\n'.join(out) + '\n'
    with open('results.txt', 'w') as f:
        f.write(text)
    sys.stdout.write(text)


if __name__ == '__main__':
    main()
