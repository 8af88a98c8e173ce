#!/usr/bin/env python3
"""Capillary-gravity equilibrium start of the -liquidFlow column.

    equilibrium.py CASE ALPHAL0 [TOP]

Writes CASE/0/alphaL, p, pl, gasPresent, Xair: the column at rest (the
uniform T of 0/T, the gas at the pressure p0 of 0/p's patch TOP, the
open top: `plate` unless given; tutorials/wetHearthCoupled's is `fire`)
with the same liquid as the uniform start alpha_l0 (sum of phi alpha_l dz
over the cells), the liquid hydrostatic about a water table at y_wt:

    p_l(y) = p0 - rho_l |g| (y - y_wt),

above it (y_c > y_wt) two-phase cells at the van Genuchten saturation of
p_c = p0 - p_l (p_c(1) = 0),

    Se = [1 + (a p_c)^n]^(-m),  m = 1 - 1/n   (van Genuchten 1980, eq. 3)
    S  = Swr + (1 - Swr - Sgr) Se            (the model's effectiveSaturation)

below it liquid-only cells (saturatedZone: gasPresent 0, p = p_l) at
p_l > p0, holding the air of water in Henry's equilibrium with the air of
the gas at the top, X = M_a H^cp(T) (min(p0, p_l) - p_wsat(T))/rho_l
(p_l < p0 in a liquid-only cell above the water table: its bubble point,
the solver's bound; Henry's law as
saturatedZone's `henry`, p_wsat of Wagner & Pruss 1993 as the
`wagnerPruss` law). A two-phase cell whose gas fraction 1 - S would be
below the Newton engine's gasSeed (system/fvSolution nonlinear, default
1e-4: the least gas the engine gives a cell where gas appears) is made
liquid-only at its p_l (the solver's own state for so little gas); the
script prints how many. Two-point finite volumes are exact for
hydrostatics: the discrete state at the cell centres is at rest
(tests/pendularWaterTable). y_wt is found by bisection so that the liquid
volume equals alpha_l0 phi H (the stored water of a liquid-only cell
differs by phi rho_l c_s (p_l - p0) dz, at most 1.4e-6 of its water here,
and the vapour of the two-phase cells by their phi (1 - alpha_l) rho_v:
both below 1e-5 of the column's water; the script prints the liquid
volumes; with Sgr > 0 the saturation jumps by Sgr at the water table and
the volume matches within Sgr dz/H, printed).

Read from the case: constant/soilProperties (porosity, liquid rho,
pendular Ma and saturationPressureLaw, liquidFlow's
capillaryPressureModel, which must be vanGenuchten (another law has
p_c(1) != 0: p = p_l in the liquid-only cells would be wrong), its alpha,
n, Swr, Sgr, pcLinearBelowSe (the start must not hold a cell below it:
refused) and saturatedZone's henry), constant/g, 0/T (uniform), 0/p (its
TOP patch value), system/fvSolution (gasSeed), the cells from
constant/polyMesh/points (a 1-D column along y, one cell across: cell j
between the j-th and (j+1)-th distinct y). The patches must be this
tutorial's (TOP: the open top, bottom, sides: empty; read from
constant/polyMesh/boundary and checked): the boundary conditions written
are its. Each error exits non-zero naming the file, the keyword and its
valid range.
"""
import math
import os
import re
import sys

# Wagner & Pruss (1993), eq. 2.5 of Wagner & Pruss (2002): the
# coefficients of src/pendular/saturationPressure/wagnerPruss
WP_TC, WP_PC = 647.096, 22.064e6
WP_A = (-7.85951783, 1.84408259, -11.7866497, 22.6807411, -15.9618719,
        1.80122502)
PATCHES = {'bottom': 'patch', 'sides': 'empty'}   # and TOP: 'patch'


def fail(path, msg):
    sys.exit('equilibrium.py: %s: %s' % (path, msg))


def strip_comments(text):
    text = re.sub(r'/\*.*?\*/', ' ', text, flags=re.S)
    return re.sub(r'//[^\n]*', ' ', text)


def top_level(text):
    """The text of a dictionary body with its sub-dictionaries blanked
    out: its own entries only"""
    out, depth = [], 0
    for c in text:
        if c == '{':
            depth += 1
        if depth == 0:
            out.append(c)
        if c == '}':
            depth -= 1
    return ''.join(out)


def subdict(text, name, path):
    """The body of the top-level sub-dictionary NAME of text (None if
    absent)"""
    for m in re.finditer(r'(?<![\w.])%s\s*\{' % re.escape(name), text):
        if text[:m.start()].count('{') != text[:m.start()].count('}'):
            continue                    # not at the top level of text
        d, j = 1, m.end()
        while d and j < len(text):
            d += {'{': 1, '}': -1}.get(text[j], 0)
            j += 1
        if d:
            fail(path, 'unbalanced braces after %s' % name)
        return text[m.end():j - 1]
    return None


def entry(text, key, path, where, default=None, valid=None, word=False):
    """The top-level entry KEY of a dictionary body: a number in the range
    valid = (lo, hi, description), or a word"""
    m = re.search(r'(?:^|[;{}\s])%s\s+([^;\s]+)\s*;' % re.escape(key),
                  top_level(text))
    if not m:
        if default is not None:
            return default
        fail(path, 'keyword %s%s not found' % (where, key))
    v = m.group(1)
    if word:
        return v
    try:
        x = float(v)
    except ValueError:
        fail(path, '%s%s = %s is not a number' % (where, key, v))
    if valid and not valid[0](x):
        fail(path, '%s%s = %s out of its valid range %s'
             % (where, key, v, valid[1]))
    return x


POSITIVE = (lambda x: x > 0, '(0, inf)')
FRACTION = (lambda x: 0 <= x < 1, '[0, 1)')


def read(case, rel):
    path = os.path.join(case, rel)
    try:
        with open(path) as f:
            return path, strip_comments(f.read())
    except OSError as e:
        sys.exit('equilibrium.py: cannot read %s: %s' % (path, e.strerror))


def uniform_internal(case, rel):
    path, text = read(case, rel)
    m = re.search(r'internalField\s+uniform\s+(\S+);', text)
    if not m:
        fail(path, 'internalField must be uniform (the column at rest)')
    return float(m.group(1))


def wagner_pruss(T):
    """p_wsat(T) [Pa], Wagner & Pruss (1993)"""
    tau = 1 - T/WP_TC
    a1, a2, a3, a4, a5, a6 = WP_A
    f = (a1*tau + a2*tau**1.5 + a3*tau**3 + a4*tau**3.5 + a5*tau**4
         + a6*tau**7.5)
    return WP_PC*math.exp(WP_TC/T*f)


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


def need(body, name, path, where):
    d = subdict(body, name, path)
    if d is None:
        fail(path, 'sub-dictionary %s%s not found' % (where, name))
    return d


def check_patches(case, top):
    """The patches of constant/polyMesh/boundary must be this tutorial's
    (PATCHES and the open top): the boundary conditions written are its"""
    path, text = read(case, 'constant/polyMesh/boundary')
    found = dict((n, t) for n, t in re.findall(
        r'(\w+)\s*\{[^}]*?\btype\s+(\w+)\s*;', text))
    if found.get(top) != 'patch':
        fail(path, 'TOP = %s (the third argument, default plate): no patch '
             'of type patch of that name; patches %s' % (top, found))
    expected = dict(PATCHES, **{top: 'patch'})
    if found != expected:
        fail(path, 'patches %s: this script writes the boundary conditions '
             'of %s (name: type)' % (found, expected))


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    case = sys.argv[1]
    top = sys.argv[3] if len(sys.argv) == 4 else 'plate'
    try:
        alpha0 = float(sys.argv[2])
    except ValueError:
        alpha0 = float('nan')
    if not 0 < alpha0 < 1:
        sys.exit('equilibrium.py: ALPHAL0 = %s (%s/0/alphaL internalField) '
                 'out of its valid range (0, 1)' % (sys.argv[2], case))
    check_patches(case, top)
    path, soil = read(case, 'constant/soilProperties')
    pend = need(soil, 'pendular', path, '')
    lf = need(pend, 'liquidFlow', path, 'pendular/')
    w = 'pendular/liquidFlow/'
    model = entry(lf, 'capillaryPressureModel', path, w, word=True)
    if model != 'vanGenuchten':
        fail(path, '%scapillaryPressureModel %s: only vanGenuchten (p_c(1) '
             '= 0: p = p_l in the liquid-only cells) is valid here'
             % (w, model))
    vg = need(lf, 'vanGenuchtenCoeffs', path, w)
    a = entry(vg, 'alpha', path, w + 'vanGenuchtenCoeffs/', valid=POSITIVE)
    n = entry(vg, 'n', path, w + 'vanGenuchtenCoeffs/',
              valid=(lambda x: x > 1, '(1, inf)'))
    swr = entry(lf, 'Swr', path, w, default=0.0, valid=FRACTION)
    sgr = entry(lf, 'Sgr', path, w, default=0.0, valid=FRACTION)
    if swr + sgr >= 1:
        fail(path, '%sSwr + Sgr = %g must be in [0, 1)' % (w, swr + sgr))
    seLin = entry(lf, 'pcLinearBelowSe', path, w, default=0.0,
                  valid=(lambda x: 0 <= x < 1, '(0, 1)'))
    sz = need(lf, 'saturatedZone', path, w)
    w2 = w + 'saturatedZone/henry/'
    he = need(sz, 'henry', path, w + 'saturatedZone/')
    hcp = entry(he, 'Hcp', path, w2, valid=POSITIVE)
    vh = entry(he, 'vantHoff', path, w2,
               valid=(lambda x: True, '(-inf, inf)'))
    th = entry(he, 'T0', path, w2, valid=POSITIVE)
    ma = entry(pend, 'Ma', path, 'pendular/', valid=POSITIVE)
    law = entry(pend, 'saturationPressureLaw', path, 'pendular/', word=True)
    if law != 'wagnerPruss':
        fail(path, 'pendular/saturationPressureLaw %s: this script has '
             'wagnerPruss only' % law)
    rho = entry(need(soil, 'liquid', path, ''), 'rho', path, 'liquid/',
                valid=POSITIVE)
    # porosity cancels (the liquid per pore volume); checked all the same
    entry(soil, 'porosity', path, '', valid=(lambda x: 0 < x < 1, '(0, 1)'))
    gpath, gtext = read(case, 'constant/g')
    gm = re.search(r'value\s*\(\s*(\S+)\s+(\S+)\s+(\S+)\s*\)', gtext)
    if not gm or float(gm.group(1)) != 0 or float(gm.group(3)) != 0 \
            or float(gm.group(2)) >= 0:
        fail(gpath, 'value must be (0 -g 0), g > 0 (the column along y)')
    g = -float(gm.group(2))
    T = uniform_internal(case, '0/T')
    if not 273.16 <= T < WP_TC:
        fail(os.path.join(case, '0/T'), 'internalField %g out of the '
             'valid range [273.16, %g) K of wagnerPruss' % (T, WP_TC))
    ppath, ptext = read(case, '0/p')
    pm = re.search(r'\b%s\s*\{[^}]*\bvalue\s+uniform\s+(\S+)\s*;'
                   % re.escape(top), ptext)
    if not pm or not float(pm.group(1)) > 0:
        fail(ppath, 'boundaryField/%s value must be uniform, > 0 '
             '(the gas pressure at the open top)' % top)
    p0 = float(pm.group(1))
    spath, fvs = read(case, 'system/fvSolution')
    nl = subdict(fvs, 'nonlinear', spath) or ''
    gasSeed = entry(nl, 'gasSeed', spath, 'nonlinear/', default=1e-4,
                    valid=(lambda x: 0 < x < 1, '(0, 1)'))
    m = 1 - 1/n

    faces = distinct_y(case)
    yc = [(faces[j] + faces[j + 1])/2 for j in range(len(faces) - 1)]
    dz = [faces[j + 1] - faces[j] for j in range(len(faces) - 1)]
    H = faces[-1] - faces[0]

    def state(ywt):
        """(S, p_l, gas present, Se) of each cell"""
        out = []
        for y in yc:
            pl = p0 - rho*g*(y - ywt)
            if y > ywt:
                Se = (1 + (a*(p0 - pl))**n)**(-m)
                S = swr + (1 - swr - sgr)*Se
                if 1 - S >= gasSeed:
                    out.append((S, pl, 1, Se))
                    continue
            out.append((1.0, pl, 0, 1.0))
        return out

    def liquid(ywt):
        return sum(s[0]*d for s, d in zip(state(ywt), dz))

    target = alpha0*H
    lo, hi = faces[0] - 10*H, faces[-1]
    if liquid(lo) > target:
        sys.exit('equilibrium.py: ALPHAL0 = %g below the column drained '
                 'to its residual profile (%g)' % (alpha0, liquid(lo)/H))
    if liquid(hi) < target:
        sys.exit('equilibrium.py: ALPHAL0 = %g above what the column holds '
                 'at rest with its water table at the top (%g)'
                 % (alpha0, liquid(hi)/H))
    for _ in range(200):
        mid = (lo + hi)/2
        if liquid(mid) < target:
            lo = mid
        else:
            hi = mid
    # the upper end: liquid(hi) >= target (liquid() jumps by Sgr dz, or by
    # the gasSeed fringe, when the water table crosses a cell centre: the
    # volume is then that of alpha_l0 within that jump, printed)
    ywt = hi
    st = state(ywt)
    seMin = min(s[3] for s in st)
    if seMin < seLin:
        fail(path, 'the equilibrium start has a cell at Se = %g, below '
             '%spcLinearBelowSe = %g (p_c linearised there, not van '
             'Genuchten\'s): ALPHAL0 = %g too low for this column'
             % (seMin, w, seLin, alpha0))
    fringe = sum(1 for y, s in zip(yc, st) if y > ywt and not s[2])
    # the dissolved air: Henry's at the air of the top, p0 - p_wsat; in a
    # liquid-only cell above the water table (p_l < p0) at most its bubble
    # point, at the air pressure p_l - p_wsat (the solver's bound; 1e-9
    # below it, not to cross it by the rounding of the file)
    kH = ma*hcp*math.exp(vh*(1/T - 1/th))/rho
    pw = wagner_pruss(T)
    X = [kH*(p0 - pw) if s[2] or s[1] >= p0
         else kH*(s[1] - pw)*(1 - 1e-9) for s in st]

    patches = [(top, 'type zeroGradient;'),
               ('bottom', 'type zeroGradient;'), ('sides', 'type empty;')]
    pPatches = [(top, 'type fixedValue; value uniform %.10g;' % p0),
                ('bottom', 'type zeroGradient;'), ('sides', 'type empty;')]
    write_field(case, 'alphaL', '[0 0 0 0 0 0 0]', [s[0] for s in st],
                'capillary-gravity equilibrium, water table at y = %.6g m'
                % ywt, patches)
    write_field(case, 'pl', '[1 -1 -2 0 0 0 0]', [s[1] for s in st],
                'liquid pressure, hydrostatic about the water table',
                patches)
    write_field(case, 'p', '[1 -1 -2 0 0 0 0]',
                [p0 if s[2] else s[1] for s in st],
                'gas at p0; p_l + p_c(1) = p_l in liquid-only cells',
                pPatches)
    write_field(case, 'gasPresent', '[0 0 0 0 0 0 0]',
                [s[2] for s in st], '0: liquid-only below the water table '
                'and where 1 - S would be below gasSeed', patches)
    write_field(case, 'Xair', '[0 0 0 0 0 0 0]', X,
                "Henry's at the air of min(p0, p_l) - p_wsat(T), T = %g K"
                % T, patches)
    print('water table y_wt = %.6f m (%.2f cm above the bottom), '
          '%d liquid-only cells (%d above the water table, 1 - S < gasSeed '
          '%g); least 1 - S of a two-phase cell %.3g; liquid volume %.12g, '
          'target %.12g m3/m2 of pores (relative difference %.2g); '
          'X = %.6g'
          % (ywt, 100*(ywt - faces[0]), sum(1 - s[2] for s in st), fringe,
             gasSeed, min([1 - s[0] for s in st if s[2]] or [float('nan')]),
             liquid(ywt), target, liquid(ywt)/target - 1, X[0]))


if __name__ == '__main__':
    main()
