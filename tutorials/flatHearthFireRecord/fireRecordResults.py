#!/usr/bin/env python3
"""flatHearthFireRecord: summary of the run with heat loss (this case) and of
the same run with an insulated ground (insulatedGround/).

Writes sensors.csv (the thermocouples of this case), fireFace.csv (the fire
patch temperature at every step, C), alteration.csv (depths of the TMax
thresholds on the axis, under the edge and outside the fire, both cases) and
prints results.txt on stdout; writes figures.csv (name,value,unit of every
result figure README.md states, checked by tests/tutorialFlatHearthFireRecord).
Standard library and etc/python/hearthTutorial.py only.
"""
import os
import shutil
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                '..', '..', 'etc', 'python'))
import hearthTutorial as ht       # noqa: E402

C0 = ht.T0


def read_sensors(case):
    path = os.path.join(case, 'postProcessing/thermocouples/0/sensors.csv')
    header, data = ht.read_csv(path)
    return path, header[1:], data


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


def first_crossing(data, j, threshold):
    """First sample at or above threshold [h] (no interpolation)"""
    t = ht.first_sample([r[0] for r in data], [r[j] for r in data], threshold)
    return None if t is None else t/3600


def alteration(case):
    return ht.alteration_summary(case)


def energy_balance(case):
    eb = ht.energy_balance(os.path.join(case, 'log.ahcFoam'))
    heat = dict((k[3:], v) for k, v in eb.items() if k.startswith('in_'))
    return heat, eb['stored'], eb['latent'], eb['relative']


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
    err = max(abs(T - ht.interpolate(rec_t, rec_T, t)) for t, T in face)
    fig = ht.Figures()
    fig.add('fireRecordError', err, 'K')
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
        fig.add('peak_' + name, peak[j], 'C')
        fig.add('peakTime_' + name, peak[0]/3600, 'h')
        fig.add('t100_' + name, t100, 'h')
        fig.add('t290_' + name, t290, 'h')
        fig.add('peakInsulated_' + name, peak0[j], 'C')

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
        for l in lines:
            fig.add('depth%s_%s' % (a['threshold_C'], l),
                    100*float(a['depth_%s_m' % l]), 'cm')
            fig.add('depth%s_%s_insulated' % (a['threshold_C'], l),
                    100*float(a0['depth_%s_m' % l]), 'cm')
        fig.add('volume%s' % a['threshold_C'],
                1000*float(a['volume360_m3']), 'L')
        fig.add('volume%s_insulated' % a['threshold_C'],
                1000*float(a0['volume360_m3']), 'L')
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
        sfx = '' if case == '.' else '_insulated'
        fig.add('heatFire' + sfx, heat['fire']/1e3, 'kJ')
        fig.add('heatGround' + sfx, -heat['ground']/1e3, 'kJ')
        fig.add('groundFraction' + sfx, -100*heat['ground']/heat['fire'], '%')
        fig.add('heatFar' + sfx, heat['side'] + heat['bottom'], 'J')
        fig.add('stored' + sfx, stored/1e3, 'kJ')
        fig.add('latent' + sfx, latent/1e3, 'kJ')
        fig.add('relativeImbalance' + sfx, relative, '1')
        out.append(
            'Energy balance at 12 h, %s (per 5-degree wedge): fire %.4g J, '
            'ground %.4g J (%.1f %% of the fire\'s), far boundaries %.2g J; '
            'stored %.4g J (latent %.4g J); relative imbalance %.1e'
            % (label, heat['fire'], heat['ground'],
               -100*heat['ground']/heat['fire'],
               heat['side'] + heat['bottom'], stored, latent, relative))
    # what the losses change under the centre of the fire
    f = dict((n, v) for n, v, u in fig.rows)
    fig.add('lossEffectPeak_TC_axis_3.5cm', f['peakInsulated_TC_axis_3.5cm']
            - f['peak_TC_axis_3.5cm'], 'K')
    fig.add('lossEffectDepth100_axis', f['depth100_axis_insulated']
            - f['depth100_axis'], 'cm')
    steps, rejected, _, _ = ht.log_stats('log.ahcFoam')
    fig.add('steps', steps, '1')
    fig.add('rejected', rejected, '1')
    fig.write('figures.csv')
    print('\n'.join(out))


if __name__ == '__main__':
    main()
