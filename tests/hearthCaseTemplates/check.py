"""Checks of one case of tests/hearthCaseTemplates (see run): patches of
the mesh = patches of each field; energy balance closed; sensors warmed."""
import os
import re
import sys

import hearthcheck  # noqa: F401 (PYTHONPATH: tests/lib)

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                '..', '..', 'etc', 'python'))
import hearthTutorial as ht  # noqa: E402

case = sys.argv[1]
ok = True


def check(cond, what):
    global ok
    print(('ok   ' if cond else 'FAIL ') + what)
    ok = ok and cond


with open(os.path.join(case, 'constant', 'polyMesh', 'boundary')) as f:
    text = f.read()
mesh = set(re.findall(r'^\s{4}(\w+)\s*\n\s{4}\{', text, re.M))
# snappyHexMesh's layer diagnostics (scannedPit's Allmesh) are not fields
# of the solver
LAYER_FIELDS = ('nSurfaceLayers', 'thickness', 'thicknessFraction')
for field in sorted(set(os.listdir(os.path.join(case, '0')))
                    - set(LAYER_FIELDS)):
    with open(os.path.join(case, '0', field)) as f:
        bf = f.read().split('boundaryField', 1)[1]
    names = set(re.findall(r'^\s{4}(\w+)\s*\n\s{4}\{', bf, re.M))
    check(names == mesh, '0/%s patches %s = mesh %s'
          % (field, sorted(names), sorted(mesh)))
solver = open(os.path.join(case, 'system', 'hearthCaseInfo')).read() \
    .split()[1]
log = os.path.join(case, 'log.' + solver)
if solver == 'ahcFoam':
    b = ht.energy_balance(log)
    rel = b['relative']
else:
    rel = abs(ht.pendular_balances(log)[-1]['energy']['relative'])
check(abs(rel) < 1e-6, 'energy balance relative imbalance %.2g < 1e-6' % rel)
s = ht.sensors_of(case)
peak = max(s['centre'])
check(peak > 16.0, 'sensor under the centre peaks at %.2f C > 16 C' % peak)
print('%s: %d patches, imbalance %.1g, centre peak %.1f C'
      % (solver, len(mesh), rel, peak))
sys.exit(0 if ok else 1)
