#!/usr/bin/env python3
"""flatHearthFireRecord: summary of the run with heat loss (this case) and of
the same run with an insulated ground (insulatedGround/).

Writes sensors.csv (the thermocouples of this case), fireFace.csv (the fire
patch temperature at every step, C), alteration.csv (depths of the TMax
thresholds on the axis, under the edge and outside the fire, both cases) and
prints results.txt on stdout. Standard library only.
"""
import bisect
import csv
import glob
import os
import re
import shutil

C0 = 273.15
WEDGE_TO_FULL = None        # read from log.hearthAlteration


def read_sensors(case):
    path = os.path.join(case, 'postProcessing/thermocouples/0/sensors.csv')
    with open(path) as f:
        rows = list(csv.reader(f))
    names = rows[0][1:]
    data = [[float(x) for x in r] for r in rows[1:]]
    return path, names, data


def read_record(path, offset=240.0):
    """The logger record as fireTemperature reads it: (s since t = 0, C)."""
    times, temps = [], []
    with open(path) as f:
        for line in f:
            cols = line.strip().split(',')
            if line.startswith('#') or len(cols) < 2:
                continue
            try:
                times.append(60*float(cols[0]) - offset)
                temps.append(float(cols[1]))
            except ValueError:
                continue            # the header line
    return times, temps


def interpolate(times, values, t):
    if t <= times[0]:
        return values[0]
    if t >= times[-1]:
        return values[-1]
    i = bisect.bisect_right(times, t) - 1
    w = (t - times[i])/(times[i + 1] - times[i])
    return values[i] + w*(values[i + 1] - values[i])


def first_crossing(data, j, threshold):
    for r in data:
        if r[j] >= threshold:
            return r[0]/3600
    return None


def alteration(case):
    files = sorted(glob.glob(os.path.join(
        case, 'postProcessing/hearthAlteration/*/summary.csv')),
        key=lambda p: float(p.split('/')[-2]))
    with open(files[-1]) as f:
        rows = list(csv.DictReader(f))
    return rows


def energy_balance(case):
    with open(os.path.join(case, 'log.ahcFoam')) as f:
        log = f.read()
    block = log[log.rindex('Energy balance at t'):]
    block = block[:block.index('liquid water')]
    heat = dict(re.findall(r'heat in through (\w+) = (\S+)', block))
    stored = float(re.search(r'stored change += (\S+)', block).group(1))
    latent = float(re.search(r'latent (\S+),', block).group(1))
    relative = float(re.search(r'relative (\S+)\)', block).group(1))
    return {k: float(v) for k, v in heat.items()}, stored, latent, relative


def main():
    out = []
    # --- the fire patch against the record
    rec_t, rec_T = read_record('constant/fireRecord.csv')
    face = []
    with open('postProcessing/fireFace/0/surfaceFieldValue.dat') as f:
        for line in f:
            if line.startswith('#') or not line.strip():
                continue
            t, T = line.split()[:2]
            face.append((float(t), float(T) - C0))
    with open('fireFace.csv', 'w') as f:
        f.write('time_s,T_fire_patch_C\n')
        for t, T in face:
            f.write('%.10g,%.10g\n' % (t, T))
    err = max(abs(T - interpolate(rec_t, rec_T, t)) for t, T in face)
    out.append('Fire patch against the record (linear between its rows), '
               'every step: max |difference| = %.2e K' % err)

    # --- sensors, both cases
    path, names, data = read_sensors('.')
    shutil.copy(path, 'sensors.csv')
    _, _, data0 = read_sensors('insulatedGround')
    out.append('')
    out.append('Thermocouples (sensors.csv):      with heat loss          '
               '| insulated ground')
    out.append('%-18s %12s %8s %8s %8s | %12s' % (
        'sensor', 'peak [C]', 'at [h]', '100 C [h]', '290 C [h]', 'peak [C]'))
    for j, name in enumerate(names, start=1):
        peak = max(data, key=lambda r: r[j])
        peak0 = max(data0, key=lambda r: r[j])
        t100 = first_crossing(data, j, 100)
        t290 = first_crossing(data, j, 290)
        out.append('%-18s %12.1f %8.2f %8s %8s | %12.1f' % (
            name, peak[j], peak[0]/3600,
            '%.2f' % t100 if t100 is not None else '-',
            '%.2f' % t290 if t290 is not None else '-', peak0[j]))

    # --- TMax depths, both cases
    alt, alt0 = alteration('.'), alteration('insulatedGround')
    lines = [k[len('depth_'):-2] for k in alt[0] if k.startswith('depth_')]
    with open('alteration.csv', 'w') as f:
        f.write('threshold_C,' + ','.join(
            'depth_%s_cm,depth_%s_insulated_cm' % (l, l) for l in lines)
            + ',volume360_L,volume360_insulated_L\n')
        for a, a0 in zip(alt, alt0):
            f.write(a['threshold_C'] + ',' + ','.join(
                '%.4f,%.4f' % (100*float(a['depth_%s_m' % l]),
                               100*float(a0['depth_%s_m' % l]))
                for l in lines) + ',%.4f,%.4f\n' % (
                1000*float(a['volume360_m3']), 1000*float(a0['volume360_m3'])))
    out.append('')
    out.append('Depth reached by TMax at 12 h [cm] (alteration.csv): '
               'with heat loss / insulated ground')
    for a, a0 in zip(alt, alt0):
        out.append('  %4s C: ' % a['threshold_C'] + ', '.join(
            '%s %.2f / %.2f' % (l, 100*float(a['depth_%s_m' % l]),
                                100*float(a0['depth_%s_m' % l]))
            for l in lines) + '; volume %.2f / %.2f L' % (
            1000*float(a['volume360_m3']), 1000*float(a0['volume360_m3'])))

    # --- energy balance
    out.append('')
    for label, case in (('with heat loss', '.'),
                        ('insulated ground', 'insulatedGround')):
        heat, stored, latent, relative = energy_balance(case)
        out.append(
            'Energy balance at 12 h, %s (per 5-degree wedge): fire %.4g J, '
            'ground %.4g J (%.1f %% of the fire\'s), far boundaries %.2g J; '
            'stored %.4g J (latent %.4g J); relative imbalance %.1e'
            % (label, heat['fire'], heat['ground'],
               -100*heat['ground']/heat['fire'],
               heat['side'] + heat['bottom'], stored, latent, relative))
    print('\n'.join(out))


if __name__ == '__main__':
    main()
