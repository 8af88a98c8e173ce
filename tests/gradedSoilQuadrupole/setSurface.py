"""Set the surface condition of the finite-volume case CASE/0/T from the
histories of gradedSoil.py:

    python3 setSurface.py CASE temperature     uniformFixedValue (K)
    python3 setSurface.py CASE flux DZ         uniformFixedGradient

The flux q(t) [W/m2] into the soil is imposed as the gradient q/k_b: the
heat ahcFoam lets in through a boundary face is k_b x gradient x area, k_b
being the conductivity of the cell next to the face (porousMedium::
correctKappa), here kappaSolid at the centre of the first cell, at depth
DZ/2 (DZ: its thickness; the same polynomial soilProfile evaluates).
"""
import os
import re
import sys

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gradedSoil as gs  # noqa: E402

case, kind = sys.argv[1], sys.argv[2]
if kind == 'temperature':
    entry = ('        type            uniformFixedValue;\n'
             '        uniformValue    table %s;\n'
             % gs.history_text(gs.TEMPERATURE_HISTORY))
elif kind == 'flux':
    kb = gs.k(0.5*float(sys.argv[3]))
    rows = [(t, q/kb) for t, q in gs.FLUX_HISTORY]
    entry = ('        // flux %s W/m2 / k_b = %r W/(m K)\n'
             '        type            uniformFixedGradient;\n'
             '        uniformGradient table %s;\n'
             % (gs.history_text(gs.FLUX_HISTORY), kb, gs.history_text(rows)))
else:
    sys.exit('usage: setSurface.py CASE temperature | flux DZ')
entry += '        value           uniform %r;\n' % gs.T_INITIAL

path = os.path.join(case, '0', 'T')
with open(path) as f:
    text = f.read()
new, n = re.subn(r'(    surface\n    \{\n).*?(    \}\n)',
                 lambda m: m.group(1) + entry + m.group(2), text, flags=re.S)
if n != 1:
    sys.exit('setSurface.py: no surface entry in ' + path)
with open(path, 'w') as f:
    f.write(new)
