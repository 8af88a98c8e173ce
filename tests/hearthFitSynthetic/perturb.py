"""Multiply one parameter of a case copy's constant/porousProperties:
    python3 perturb.py CASE rhoCs|ks|phi FACTOR
rhoCs is written as solid/Cp (rhoCs/1500: scaling Cp scales rhoCs), ks as
solid/kappa, phi as porosity (the format written by hearthFit -writeCase
or the test case)."""
import re
import sys

case, name, factor = sys.argv[1], sys.argv[2], float(sys.argv[3])
path = case + '/constant/porousProperties'
with open(path) as f:
    txt = f.read()
m = re.search(r'solid\s*\{([^}]*)\}', txt)
solid = m.group(1)


def scale(text, key):
    return re.sub(r'(\b%s\s+)([^;]+);' % key,
                  lambda g: '%s%.17g;' % (g.group(1), float(g.group(2))*factor),
                  text, count=1)


if name in ('rhoCs', 'ks'):
    new = scale(solid, 'Cp' if name == 'rhoCs' else 'kappa')
    txt = txt[:m.start(1)] + new + txt[m.end(1):]
else:
    txt = re.sub(r'^(porosity\s+)([^;]+);',
                 lambda g: '%s%.17g;' % (g.group(1), float(g.group(2))*factor),
                 txt, count=1, flags=re.M)
with open(path, 'w') as f:
    f.write(txt)
