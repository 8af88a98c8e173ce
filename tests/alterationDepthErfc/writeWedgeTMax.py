"""Write 0/TMax of the wedge case: 500 K in the cells whose centre is
within 0.2 m of the axis and 0.1 m of the surface, 300 K elsewhere (cell
centres from 'postProcess -func writeCellCentres': 0/Cx, 0/Cz)."""
import hearthcheck as hc

cx = hc.read_internal_field('0/Cx')
cz = hc.read_internal_field('0/Cz')
values = [500.0 if x < 0.2 and z > -0.1 else 300.0 for x, z in zip(cx, cz)]

with open('0/TMax', 'w') as f:
    f.write('''FoamFile
{
    version     2.0;
    format      ascii;
    class       volScalarField;
    object      TMax;
}
dimensions      [0 0 0 1 0 0 0];
internalField   nonuniform List<scalar> %d
(
%s
);
boundaryField
{
    surface { type calculated; value uniform 0; }
    bottom  { type calculated; value uniform 0; }
    outer   { type calculated; value uniform 0; }
    front   { type wedge; }
    back    { type wedge; }
    axis    { type empty; }
}
''' % (len(values), '\n'.join('%g' % v for v in values)))
print('0/TMax: %d cells, %d at 500 K' % (len(values), values.count(500.0)))
