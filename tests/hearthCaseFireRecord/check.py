"""tests/hearthCaseFireRecord (see run): the case of bin/hearthCase against
the hand-written tutorial case, entry by entry, then result by result."""
import os
import subprocess
import sys

import hearthcheck as hc

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                '..', '..', 'etc', 'python'))
import hearthTutorial as ht  # noqa: E402

gen, hand = sys.argv[1], sys.argv[2]
c = hc.Check('hearthCaseFireRecord')


def value(case, f, entry):
    r = subprocess.run(['foamDictionary', os.path.join(case, f), '-entry',
                        entry, '-value'], stdout=subprocess.PIPE,
                       stderr=subprocess.DEVNULL, universal_newlines=True)
    return r.stdout.strip() if r.returncode == 0 else None


def same(a, b):
    try:
        return abs(float(a) - float(b)) <= 1e-12*abs(float(b))
    except (TypeError, ValueError):
        return a == b


# 0/T, every entry of every patch of the hand case (but 'file': the
# same record under another name) and the internal field
pairs = [('0/T', 'internalField', '0/T', 'internalField')]
for patch in ('fire', 'ground', 'side', 'bottom', 'front', 'back', 'axis'):
    keys = subprocess.run(['foamDictionary', os.path.join(hand, '0/T'),
                           '-entry', 'boundaryField.' + patch, '-keywords'],
                          stdout=subprocess.PIPE, universal_newlines=True
                          ).stdout.split()
    for k in keys:
        if k != 'file':
            e = 'boundaryField.%s.%s' % (patch, k)
            pairs.append(('0/T', e, '0/T', e))
soil = [('porosity', 'porosity'), ('waterContent', 'waterContent'),
        ('conductivityModel', 'conductivityModel')]
for ph, alias in (('solid', 'solid'), ('liquid', 'liquid'), ('gas', 'vapour')):
    for k in ('rho', 'Cp', 'kappa'):
        soil.append(('%s.%s' % (ph, k), '%s.%s' % (alias, k)))
for k in ('type', 'Tv', 'dT', 'latentHeat'):
    soil.append(('phaseChange.' + k, 'phaseChange.' + k))
pairs += [('constant/soilProperties', a, 'constant/porousProperties', b)
          for a, b in soil]
pairs += [('system/controlDict', k, 'system/controlDict', k)
          for k in ('endTime', 'deltaT', 'adjustTimeStep', 'maxDeltaT',
                    'maxDeltaTemperature', 'application')]
for k in ('solvers.T.solver', 'solvers.T.tolerance', 'nonlinear.maxIter',
          'nonlinear.residualTol', 'nonlinear.TTol'):
    pairs.append(('system/fvSolution', k, 'system/fvSolution', k))
for fg, eg, fh, eh in pairs:
    a, b = value(gen, fg, eg), value(hand, fh, eh)
    c.true('%s %s: %s = %s' % (fg, eg, a, b), a is not None and same(a, b))

# results
for t in ('3600', '7200'):
    for f in ('T', 'TMax'):
        a = hc.read_internal_field(os.path.join(gen, t, f))
        b = hc.read_internal_field(os.path.join(hand, t, f))
        c.true('%s/%s: %d cells' % (t, f, len(a)), len(a) == len(b) > 1000)
        c.le('%s/%s max |difference| [K]' % (t, f),
             max(abs(x - y) for x, y in zip(a, b)), 1e-9)
sa, sb = ht.sensors_of(gen), ht.sensors_of(hand)
c.true('the same sensors', list(sa) == list(sb))
for k in sb:
    if k != 'time_s':
        c.le('sensor %s max |difference| [K]' % k,
             max(abs(x - y) for x, y in zip(sa[k], sb[k])), 1e-9)
c.true('the same steps: %d' % len(sb['time_s']),
       sa['time_s'] == sb['time_s'])
ea = ht.energy_balance(os.path.join(gen, 'log.ahcFoam'))
eb = ht.energy_balance(os.path.join(hand, 'log.ahcFoam'))
for k in ('stored', 'in'):
    c.le('energy balance %s: %.10g J, relative difference' % (k, eb[k]),
         abs(ea[k] - eb[k])/abs(eb[k]), 1e-9)
c.done()
