"""fitDryHearth: the estimates of hearthFit against the truth of the
synthetic measurements (Allrun). Prints a table."""
import csv
import re

KS_TRUE = 0.45
RHOC_E = 0.6*2540*700 + 0.4*1.2*1005      # (rho C)_e [J/(m3 K)]


def diffusivity(ks):
    """a = k_e/(rho C)_e, arithmetic law k_e = 0.6 k_s + 0.4 k_air."""
    return (0.6*ks + 0.4*0.026)/RHOC_E


with open('postProcessing/hearthFit/parameters.csv') as f:
    est = {r['name']: r for r in csv.DictReader(f)}
with open('synthetic/truePositions.csv') as f:
    pos = {r['name']: r for r in csv.DictReader(f)}
with open('log.hearthFit') as f:
    log = f.read()
m = re.search(r'first estimate: diffusivity a = (\S+) m2/s', log)
aFirst = float(m.group(1)) if m else float('nan')
m = re.search(r'^status: (.*)$', open('postProcessing/hearthFit/report.txt')
              .read(), re.M)

print('fitDryHearth: estimates against the truth (%s)'
      % (m.group(1) if m else '?'))
print()
print('%-9s %12s %12s %12s %9s  %s' % ('parameter', 'truth', 'estimate',
                                       'std error', '(e-t)/se',
                                       'truth in 95 % interval'))
rows = [('ks', KS_TRUE, 1.0, 'W/(m K)')]
rows += [('dz_' + n, float(pos[n]['dz_mm']), 1e3, 'mm') for n in pos]
worst = 0.0
for name, truth, f, unit in rows:
    e = est[name]
    v, se = f*float(e['estimate']), f*float(e['std_error'])
    lo, hi = f*float(e['lower']), f*float(e['upper'])
    z = (v - truth)/se
    worst = max(worst, abs(z))
    print('%-9s %12.5f %12.5f %12.5f %9.2f  %s'
          % (name, truth, v, se, z, 'yes' if lo <= truth <= hi else 'NO'))
print('(offsets in mm: the true depth errors; the true radial errors, not '
      'fitted, are')
print(' ' + ', '.join('%s %+.2f' % (n, float(pos[n]['dr_mm'])) for n in pos)
      + ' mm)')
print()
ks = float(est['ks']['estimate'])
print('diffusivity a = k_e/(rho C)_e [m2/s]: truth %.4e, Laloy-Massard first '
      'estimate %.4e (%+.1f %%), fit %.4e (%+.2f %%)'
      % (diffusivity(KS_TRUE), aFirst,
         100*(aFirst/diffusivity(KS_TRUE) - 1), diffusivity(ks),
         100*(diffusivity(ks)/diffusivity(KS_TRUE) - 1)))
print('largest |estimate - truth|/std error: %.1f' % worst)
