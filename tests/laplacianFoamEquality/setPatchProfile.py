"""setPatchProfile.py CASE FIELD PATCH PLACEHOLDER A B COMPONENT:
replace PLACEHOLDER in CASE/0/FIELD with the face values A + B*c of PATCH,
c the COMPONENT (x, y or z) of its face centres, read from CASE/0/C<x|y|z>
as written by 'postProcess -func writeCellCentres -time 0'."""
import re
import sys

case, field, patch, placeholder, a, b, comp = sys.argv[1:8]
a, b = float(a), float(b)

with open('%s/0/C%s' % (case, comp)) as f:
    txt = f.read()
m = re.search(r'\n\s*%s\s*\{[^}]*?value\s+nonuniform\s+List<scalar>\s*(\d+)\s*\(([^)]*)\)'
              % re.escape(patch), txt)
n = int(m.group(1))
c = [float(v) for v in m.group(2).split()]
assert len(c) == n and n > 0, 'patch %s: %d face centres' % (patch, len(c))

values = 'nonuniform List<scalar> %d (%s)' % (
    n, ' '.join('%.17g' % (a + b*ci) for ci in c))
path = '%s/0/%s' % (case, field)
with open(path) as f:
    txt = f.read()
assert placeholder in txt, '%s not in %s' % (placeholder, path)
with open(path, 'w') as f:
    f.write(txt.replace(placeholder, values))
