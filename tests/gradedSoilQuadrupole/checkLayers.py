"""(c) Krapez & Profice's claim (seed 002, §2.2 and fig. 1), with
quadrupoleTemperature alone.

What the paper compares: the SURFACE TEMPERATURE of the soil (water content
linear from 7 % at the surface to 38 % at 1 m, frozen in time; a uniform
semi-infinite soil below 1 m) under an IMPOSED SURFACE HEAT FLUX computed
from meteorological data (Alpilles-ReSeDA, 20 min samples), over 30 days;
the error is the RMS difference over the 30 days from a reference made of
50 uniform-gamma sublayers, as a function of the number of sublayers of the
top metre: uniform-gamma layers or classical layers (uniform effusivity and
diffusivity), of equal thickness or thinner near the surface (z^2). Its
statements: gamma layers are 5 to 7 times more accurate; about 0.1 K needs
2 gamma sublayers, or 15 classical ones of equal thickness, or 5 with z^2
spacing.

What is reproduced here (makeQuadrupoleDicts.py): the soil as
reconstructed in gradedSoil.py (the paper's k(theta) is not given), a
synthetic flux (diurnal half-sine of 150 W/m2 peak under a 7.3-day
weather cycle, -26 W/m2 loss: the paper's meteorological series is not
available; the RMS values scale with the forcing's amplitude), hourly rows
and outputs, 30 days; reference 200 uniform-gamma layers (quadratic
spacing), the paper's 50 regular ones being checked against it. Gamma
layers in three fits (gradedSoil.gamma_layers): 'faces' (k, c exact at the
faces, quadrupoleTemperature's conductivityBottom form), 'eq12' (the
paper's mean gamma), 'CR' (each layer's heat capacity and resistance
exact); classical layers with the layer's mean capacity and harmonic mean
conductivity ('mean'), or the mid-depth values ('mid').

Checks (orders of magnitude: the forcing is not the paper's):
  - the reference: 50 regular gamma layers within 0.01 K RMS of it;
  - the RMS error falls as layers are added, in every family;
  - 15 classical layers of equal thickness: RMS within a factor 3 of 0.1 K;
  - 5 classical layers with z^2 spacing: within a factor 3 of 0.1 K;
  - 2 gamma layers (the best of the fits and spacings): within a factor 3
    of 0.1 K;
  - gamma layers beat classical ones with the same number and spacing of
    layers by at least a factor 2.5, for every fit (paper: 5 to 7).
"""
import math
import os
import sys

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gradedSoil as gs  # noqa: E402
import makeQuadrupoleDicts as mq  # noqa: E402
import hearthcheck as hc  # noqa: E402

c = hc.Check('gradedSoilQuadrupole (c): layers needed for 0.1 K')


def surface(name):
    head, rows = gs.read_quadrupole_csv('quadrupole/postProcessing/%s.csv'
                                        % name)
    assert head[1] == 'T_surface'
    return [r[1] for r in rows]


ref = surface('cRef')
print('surface temperature over %d days: %.2f to %.2f K about the initial'
      ' temperature (%d hourly values)'
      % (mq.DAYS, min(ref), max(ref), len(ref)))


def rms(name):
    T = surface(name)
    assert len(T) == len(ref)
    return math.sqrt(sum((a - b)**2 for a, b in zip(T, ref))/len(ref))


c.le('paper-style reference (50 regular gamma layers) vs 200 quadratic,'
     ' RMS [K]', rms('cPaperRef'), 0.01)

families = [('gamma, faces', 'g_faces_%s_%d', mq.GAMMA_N),
            ('gamma, eq12', 'g_eq12_%s_%d', mq.GAMMA_N),
            ('gamma, CR', 'g_CR_%s_%d', mq.GAMMA_N),
            ('classical, mean', 'k_mean_%s_%d', mq.CLASSICAL_N)]
table = {}
print('\nRMS error of the surface temperature [K] against the reference')
print('%-16s %-10s %s' % ('layers', 'spacing',
                          ' '.join('%7d' % n for n in mq.CLASSICAL_N)))
for label, pattern, ns in families:
    for sp in ('regular', 'quadratic'):
        row = {}
        for n in ns:
            row[n] = rms(pattern % ('regular' if n == 1 else sp, n))
        table[(label, sp)] = row
        print('%-16s %-10s %s' % (label, sp, ' '.join(
            '%7.4f' % row[n] if n in row else '%7s' % '' for n in
            mq.CLASSICAL_N)))
        vals = [row[n] for n in ns]
        c.true('%s, %s: RMS falls as layers are added' % (label, sp),
               all(x > y for x, y in zip(vals, vals[1:])))
mid = {(sp, n): rms('k_mid_%s_%d' % (sp, n)) for sp, n in mq.MID}
print('classical, mid   ' + '  '.join('%s %d: %.4f' % (sp, n, v)
                                      for (sp, n), v in sorted(mid.items())))

print('\nGain (classical mean RMS / gamma RMS, same layers and spacing):')
for label in ('gamma, faces', 'gamma, eq12', 'gamma, CR'):
    gains = []
    for sp in ('regular', 'quadratic'):
        for n in mq.GAMMA_N:
            if n >= 2:
                gains.append(table[('classical, mean', sp)][n]
                             / table[(label, sp)][n])
    print('  %-14s %s' % (label, ' '.join('%.1f' % g for g in gains)))
    c.le('%s: smallest gain over classical layers >= 2.5 (1/gain)' % label,
         1.0/min(gains), 1/2.5)


def needed(row):
    """Fewest layers in the table with RMS <= 0.1 K (None: not reached)"""
    ok = [n for n in sorted(row) if row[n] <= 0.1]
    return ok[0] if ok else None


print('\nFewest layers (of those computed) for RMS <= 0.1 K:')
for key in sorted(table):
    print('  %-16s %-10s %s' % (key[0], key[1], needed(table[key])))

factor3 = lambda x: max(x/0.1, 0.1/x)
k15 = table[('classical, mean', 'regular')][15]
k5q = table[('classical, mean', 'quadratic')][5]
g2 = min(table[(f, sp)][2] for f in ('gamma, faces', 'gamma, eq12',
                                      'gamma, CR')
         for sp in ('regular', 'quadratic'))
c.le('15 classical layers, equal thickness: RMS %.4f K, factor from 0.1 K'
     % k15, factor3(k15), 3)
c.le('5 classical layers, z^2 spacing: RMS %.4f K, factor from 0.1 K'
     % k5q, factor3(k5q), 3)
c.le('2 gamma layers (best fit/spacing): RMS %.4f K, factor from 0.1 K'
     % g2, factor3(g2), 3)
c.done()
