#!/usr/bin/env python3
"""Capillary-gravity equilibrium start of the -liquidFlow column.

    equilibrium.py CASE ALPHAL0

Writes CASE/0/alphaL, p, pl, gasPresent, Xair: the column at rest (20 C,
the gas at p0 = 1 atm) with the same liquid as the uniform start
alpha_l0 (sum of phi alpha_l dz over the cells), the liquid hydrostatic
about a water table at y_wt:

    p_l(y) = p0 - rho_l |g| (y - y_wt),

above it (y_c > y_wt) two-phase cells at the van Genuchten saturation of
p_c = p0 - p_l (p_c(1) = 0), S = Swr + (1 - Swr) [1 + (a p_c)^n]^(-m),
m = 1 - 1/n (van Genuchten 1980, eq. 3, with the residual saturation of
the model's effectiveSaturation); below it liquid-only cells
(saturatedZone: gasPresent 0) at p_l > p0, holding the air of water in
Henry's equilibrium with the air of the atmosphere at 20 C, X = M_a
H^cp(T) (p0 - p_w(T))/rho_l (Henry's law as saturatedZone's `henry`).
Two-point finite volumes are exact for hydrostatics: the discrete state
at the cell centres is at rest (tests/pendularWaterTable). y_wt is found
by bisection so that the liquid volume equals alpha_l0 phi H (the stored
water of a liquid-only cell differs by phi rho_l c_s (p_l - p0) dz, at
most 1.4e-6 of its water here, and the vapour of the two-phase cells by
their phi (1 - alpha_l) rho_v: both below 1e-5 of the column's water;
the script prints the liquid volumes). Parameters read from the case's
constant/soilProperties (liquidFlow's van Genuchten alpha, n, Swr, the
liquid's rho, porosity, henry) and constant/g; cells from
constant/polyMesh/points (a 1-D column along y, one cell across: cell j
between the j-th and (j+1)-th distinct y).
"""
import math
import os
import re
import sys

P0 = 101325.0
T0 = 293.15
PSAT = 2338.294        # Pa: Wagner & Pruss at 20 C (column/0/pw)
MA = 0.029             # kg/mol (soilProperties' Ma)


def number(text, pattern, what):
    m = re.search(pattern, text, re.S)
    if not m:
        sys.exit('equilibrium.py: no %s in constant/soilProperties' % what)
    return float(m.group(1))


def points(case):
    """The mesh points (ascii constant/polyMesh/points) -> [(x, y, z)]"""
    text = open(os.path.join(case, 'constant/polyMesh/points')).read()
    m = re.search(r'\n(\d+)\s*\(\s*\n(.*?)\n\)', text, re.S)
    pts = [tuple(float(v) for v in line.strip()[1:-1].split())
           for line in m.group(2).split('\n') if line.strip()]
    if len(pts) != int(m.group(1)):
        sys.exit('equilibrium.py: cannot read %s/constant/polyMesh/points'
                 % case)
    return pts


def distinct_y(case):
    """The distinct y of the points, increasing: the faces of the 1-D
    column"""
    ys = sorted(p[1] for p in points(case))
    faces = []
    for y in ys:
        if not faces or y - faces[-1] > 1e-12:
            faces.append(y)
    return faces


def extent(case):
    """The column's width in x and z [m] (its cross-section, from the
    points)."""
    pts = points(case)
    return (max(p[0] for p in pts) - min(p[0] for p in pts),
            max(p[2] for p in pts) - min(p[2] for p in pts))


def write_field(case, name, dims, values, comment, patchTypes):
    body = '\n'.join('%.10g' % v for v in values)
    bf = '\n'.join('    %-7s { %s }' % (p, t) for p, t in patchTypes)
    with open(os.path.join(case, '0', name), 'w') as f:
        f.write('''/*--------------------------------*- C++ -*----------------------------------*\\
  hearthFoam: tutorials/mansourPlate (equilibrium.py)
\\*---------------------------------------------------------------------------*/
FoamFile
{
    version     2.0;
    format      ascii;
    class       volScalarField;
    location    "0";
    object      %s;
}

// %s
dimensions      %s;
internalField   nonuniform List<scalar> %d
(
%s
);
boundaryField
{
%s
}
''' % (name, comment, dims, len(values), body, bf))


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    case, alpha0 = sys.argv[1], float(sys.argv[2])
    soil = open(os.path.join(case, 'constant/soilProperties')).read()
    lf = soil[soil.index('liquidFlow'):]
    a = number(lf, r'vanGenuchtenCoeffs\s*\{\s*alpha\s+([0-9.eE+-]+);',
               'liquidFlow vanGenuchtenCoeffs alpha')
    n = number(lf, r'vanGenuchtenCoeffs\s*\{[^}]*\bn\s+([0-9.eE+-]+);',
               'liquidFlow vanGenuchtenCoeffs n')
    swr = number(lf, r'\bSwr\s+([0-9.eE+-]+);', 'liquidFlow Swr')
    hcp = number(lf, r'henry\s*\{\s*Hcp\s+([0-9.eE+-]+);', 'henry Hcp')
    vh = number(lf, r'vantHoff\s+([0-9.eE+-]+);', 'henry vantHoff')
    th = number(lf, r'henry\s*\{[^}]*\bT0\s+([0-9.eE+-]+);', 'henry T0')
    rho = number(soil, r'\nliquid\s*\{\s*rho\s+([0-9.eE+-]+);', 'liquid rho')
    phi = number(soil, r'\nporosity\s+([0-9.eE+-]+);', 'porosity')
    gtext = open(os.path.join(case, 'constant/g')).read()
    g = abs(float(re.search(r'value\s*\(\s*\S+\s+(\S+)\s+\S+\s*\)',
                            gtext).group(1)))
    m = 1 - 1/n

    faces = distinct_y(case)
    yc = [(faces[j] + faces[j + 1])/2 for j in range(len(faces) - 1)]
    dz = [faces[j + 1] - faces[j] for j in range(len(faces) - 1)]
    H = faces[-1] - faces[0]

    def state(ywt):
        out = []
        for y in yc:
            pl = P0 - rho*g*(y - ywt)
            if y > ywt:
                pc = P0 - pl
                S = swr + (1 - swr)*(1 + (a*pc)**n)**(-m)
                out.append((S, pl, 1))
            else:
                out.append((1.0, pl, 0))
        return out

    def liquid(ywt):
        return sum(s[0]*d for s, d in zip(state(ywt), dz))

    target = alpha0*H
    lo, hi = faces[0] - 10*H, faces[-1]
    if liquid(lo) > target:
        sys.exit('equilibrium.py: alpha_l0 = %g below the column drained '
                 'to its residual profile' % alpha0)
    for _ in range(200):
        mid = (lo + hi)/2
        if liquid(mid) < target:
            lo = mid
        else:
            hi = mid
    ywt = (lo + hi)/2
    st = state(ywt)
    X = MA*hcp*math.exp(vh*(1/T0 - 1/th))*(P0 - PSAT)/rho

    patches = [('plate', 'type zeroGradient;'),
               ('bottom', 'type zeroGradient;'), ('sides', 'type empty;')]
    pPatches = [('plate', 'type fixedValue; value uniform 101325;'),
                ('bottom', 'type zeroGradient;'), ('sides', 'type empty;')]
    write_field(case, 'alphaL', '[0 0 0 0 0 0 0]', [s[0] for s in st],
                'capillary-gravity equilibrium, water table at y = %.6g m'
                % ywt, patches)
    write_field(case, 'pl', '[1 -1 -2 0 0 0 0]', [s[1] for s in st],
                'liquid pressure, hydrostatic about the water table',
                patches)
    write_field(case, 'p', '[1 -1 -2 0 0 0 0]',
                [P0 if s[2] else s[1] for s in st],
                'gas at 1 atm; p_l + p_c(1) = p_l in liquid-only cells',
                pPatches)
    write_field(case, 'gasPresent', '[0 0 0 0 0 0 0]',
                [s[2] for s in st], '0: liquid-only below the water table',
                patches)
    write_field(case, 'Xair', '[0 0 0 0 0 0 0]', [X]*len(st),
                "Henry's at the air of 1 atm at 20 C", patches)
    print('water table y_wt = %.6f m (%.2f cm above the bottom), '
          '%d liquid-only cells; liquid volume %.12g, target %.12g m3/m2 '
          'of pores; X = %.6g' % (ywt, 100*(ywt - faces[0]),
                                  sum(1 - s[2] for s in st),
                                  liquid(ywt), target, X))


if __name__ == '__main__':
    main()
