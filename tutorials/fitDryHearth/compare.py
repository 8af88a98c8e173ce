"""fitDryHearth: the estimates of hearthFit against the truth of the
synthetic measurements (Allrun). Prints a table; writes figures.csv
(name,value,unit of the figures README.md states, checked by
tests/tutorialFitDryHearth). Standard library and
etc/python/hearthTutorial.py only."""
import csv
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                '..', '..', 'etc', 'python'))
import hearthTutorial as ht       # noqa: E402

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
aSensor = dict((n, float(x)) for n, x in re.findall(
    r'^\s+(TC\d+): depth \S+ m, diffusivity a = (\S+) m2/s', log, re.M))
aSensors = list(aSensor.values())
with open('postProcessing/hearthFit/report.txt') as f:
    report = f.read()
m = re.search(r'^status: (.*)$', report, re.M)
fig = ht.Figures()

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
    fig.add('truth_' + name, truth, unit)
    fig.add('estimate_' + name, v, unit)
    fig.add('stdError_' + name, se, unit)
    fig.add('z_' + name, z, '1')
    fig.add('error_' + name, v - truth, unit)
    fig.add('absError_' + name, abs(v - truth), unit)
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

aTrue, aFit = diffusivity(KS_TRUE), diffusivity(ks)
fig.add('aTrue', aTrue, 'm2/s')
fig.add('aFirst', aFirst, 'm2/s')
fig.add('aFirstError', 100*(aFirst/aTrue - 1), '%')
fig.add('aFirstLowPercent', 100*(1 - aFirst/aTrue), '%')
fig.add('ksErrorPercent', 100*(ks/KS_TRUE - 1), '%')
fig.add('ksMovesPercent', abs(100*(ks/KS_TRUE - 1)), '%')
fig.add('aFirstTC1OverMedian',
        aSensor['TC1']/aFirst if 'TC1' in aSensor else None, '1')
sens = ht.read_sensors('postProcessing/hearthFit/sensitivities.csv')
ks_cols = [c for c in sens if c.endswith('_ks')]
fig.add('sensitivityKsMax', max(max(abs(x) for x in sens[c])
                                for c in ks_cols), 'C')
fig.add('sensitivityKsTC1Max', max(abs(x) for x in sens['TC1_ks']), 'C')
fig.add('sensitivityKsTC1End', abs(sens['TC1_ks'][-1]), 'C')
fig.add('sensitivityDzTC1End', abs(sens['TC1_dz_TC1'][-1]), 'C')
fig.add('sensitivityDzTC1Max', max(abs(x) for x in sens['TC1_dz_TC1']), 'C')
fig.add('sensitivityDzTC9Max', max(abs(x) for x in sens['TC9_dz_TC9']), 'C')
for n in pos:
    fig.add('truthDr_' + n, float(pos[n]['dr_mm']), 'mm')
fig.add('aFirstSensorMin', min(aSensors) if aSensors else None, 'm2/s')
fig.add('aFirstSensorMax', max(aSensors) if aSensors else None, 'm2/s')
fig.add('aFirstTC1Ratio', aSensor['TC1']/aTrue if 'TC1' in aSensor else None,
        '1')
fig.add('aFit', aFit, 'm2/s')
fig.add('aFitError', 100*(aFit/aTrue - 1), '%')
fig.add('largestZ', worst, '1')
fig.add('largestDepthError', max(
    abs(1e3*float(est[n]['estimate']) - truth)
    for n, truth, f, unit in rows if n.startswith('dz_')), 'mm')
fig.add('outsideInterval', sum(
    not (f*float(est[n]['lower']) <= truth <= f*float(est[n]['upper']))
    for n, truth, f, unit in rows), '1')
m = re.search(r'^iterations (\d+).*forward runs (\d+)', report, re.M)
fig.add('iterations', int(m.group(1)), '1')
fig.add('forwardRuns', int(m.group(2)), '1')
fig.add('s2', float(re.search(r's\^2 (\S+)', report).group(1)), '1')
sv = sorted((float(x) for x in re.search(
    r'singular values of the scaled Jacobian J diag\(\|p\|\):(.*)',
    report).group(1).split()), reverse=True)
fig.add('singularValueLargest', sv[0], '1')
fig.add('singularValueSecondSmallest', sv[-2], '1')
fig.add('singularValueSmallest', sv[-1], '1')
rms = [float(x) for x in re.findall(r'^    TC\d+\s+(\S+)$', report, re.M)]
fig.add('rmsResidualMin', min(rms), 'C')
fig.add('rmsResidualMax', max(rms), 'C')
corr = report[report.index('correlation matrix'):
              report.index('singular values')].split('\n')[1:]
corr = [l.split() for l in corr if l.strip()]
names = [r[0] for r in corr]
C = [[float(x) for x in r[1:]] for r in corr]
ik = names.index('ks')
kd = [C[ik][j] for j in range(len(names)) if j != ik]
dd = [C[i][j] for i in range(len(names)) for j in range(len(names))
      if i != j and i != ik and j != ik]
fig.add('corrKsDepthMin', min(kd), '1')
fig.add('corrKsDepthMax', max(kd), '1')
fig.add('corrDepthsMin', min(dd), '1')
fig.add('corrDepthsMax', max(dd), '1')
fig.write('figures.csv')
