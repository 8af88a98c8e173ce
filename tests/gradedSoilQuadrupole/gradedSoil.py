"""The graded soil of Krapez & Profice (§2.2; see doc/references.md), as
reconstructed for the tests, and its
approximations by layers for quadrupoleTemperature (standard library only).

What the paper gives (and nothing more): the volumetric water content
rises linearly from theta = 7 % at the surface to 38 % at 1 m and is 38 %
below; the capacity (DeVries) goes from 1.3 to 2.6 MJ/(m3 K), the
effusivity b = sqrt(k c) (Johansen modified by Lu & Horton) from 879 to
2008 J/(m2 K s^0.5), and the gradient factor gamma = (1/(2c)) db/dz falls
from 1.1e-3 to 7.0e-5 s^-0.5 between the surface and 1 m; below 1 m a
uniform semi-infinite soil. The soil's composition (4 % organic matter,
11 % clay, 89 % quartz) is given, its porosity and the parameters of the
conductivity model are not, so k(theta) cannot be rebuilt. Reconstruction:

    theta(z) = 0.07 + 0.31 z                        (0 <= z <= 1 m)
    c(z)     = 1.3e6 (1 + z)  J/(m3 K)              (DeVries: linear in
               theta, slope 1.3e6/0.31 = 4.19e6 = rho_w C_w: consistent)
    k(z)     = the cubic in z with k(0) = 879^2/1.3e6, k(1) = 2008^2/2.6e6
               and the slopes that give gamma(0) = 1.1e-3, gamma(1) = 7.0e-5
               (dk/dz = (4 b c gamma - k dc/dz)/c)
    z > 1 m:  c = 2.6e6, k = 1.5508 (b 2008, a 5.965e-7 m2/s)

so that the four figures of the paper (b and gamma at both ends) and the
two capacities are exact. Note: gamma(1 m) = 7.0e-5 is below
b (dc/dz)/(4 c^2) = 9.65e-5, the value with dk/dz = 0: the paper's gamma
needs k to fall slightly near 1 m. The cubic does: k = 0.594 at the
surface, 1.585 at 0.78 m (its maximum), 1.551 at 1 m (a Johansen-type
k(theta) would rise monotonically; the paper's figures are rounded to
two digits).
"""
import math

C0, C1 = 1.3e6, 2.6e6          # capacity at 0 and 1 m [J/(m3 K)]
B0, B1 = 879.0, 2008.0         # effusivity at 0 and 1 m
G0, G1 = 1.1e-3, 7.0e-5        # gamma at 0 and 1 m [s^-0.5]
H = 1.0                        # depth of the graded layer [m]
DC = (C1 - C0)/H               # dc/dz

K0 = B0*B0/C0
K1 = B1*B1/C1
_M0 = (4.0*B0*C0*G0 - K0*DC)/C0     # dk/dz at 0
_M1 = (4.0*B1*C1*G1 - K1*DC)/C1     # dk/dz at 1 m
# k(z) = K_COEFFS[0] + K_COEFFS[1] z + K_COEFFS[2] z^2 + K_COEFFS[3] z^3
K_COEFFS = (K0, _M0, 3.0*(K1 - K0) - 2.0*_M0 - _M1,
            2.0*(K0 - K1) + _M0 + _M1)
C_COEFFS = (C0, DC)


def theta(z):
    return 0.07 + 0.31*min(z, H)


def c(z):
    """Volumetric heat capacity [J/(m3 K)] at depth z [m]."""
    return C0 + DC*min(z, H)


def k(z):
    """Conductivity [W/(m K)] at depth z [m]."""
    z = min(z, H)
    return sum(a*z**i for i, a in enumerate(K_COEFFS))


def dk(z):
    if z > H:
        return 0.0
    return sum(i*a*z**(i - 1) for i, a in enumerate(K_COEFFS) if i)


def b(z):
    return math.sqrt(k(z)*c(z))


def a(z):
    return k(z)/c(z)


def gamma(z):
    """(1/(2c)) db/dz [s^-0.5]."""
    if z > H:
        return 0.0
    db = (dk(z)*c(z) + k(z)*DC)/(2.0*b(z))
    return db/(2.0*c(z))


# ---------------------------------------------------------------------------
# Surface histories of the finite-volume comparison (piecewise linear)

T_INITIAL = 293.15          # K
# A fire of about 4 h and its cooling: surface temperature (s, K)
TEMPERATURE_HISTORY = [(0, 293.15), (1800, 873.15), (14400, 923.15),
                       (18000, 573.15), (28800, 393.15), (86400, 313.15)]
# A fire as an imposed heat flux into the soil (s, W/m2): 4 kW/m2 for 4 h
FLUX_HISTORY = [(0, 0.0), (600, 4000.0), (14400, 4000.0), (15000, 0.0),
                (86400, 0.0)]


# ---------------------------------------------------------------------------
# Layers for quadrupoleTemperature. A layer is a dict: thickness [m], k, c at
# its top, and either kBottom, cBottom (the exact properties at the bottom
# face: quadrupoleTemperature computes gamma = ln(b_bot/b_top)/(2 xi_L) with
# a linear in z) or gamma [s^-0.5] and aBottom [m2/s] (which sets xi_L =
# 2 L/(sqrt(a_top) + sqrt(a_bottom))); gamma = 0 and aBottom = a_top is a
# classical uniform layer.

def faces(n, spacing='regular'):
    """Interfaces 0 = z_0 < ... < z_n = H: regular, or 'quadratic' (thinner
    near the surface, z_i = H (i/n)^2, the paper's z^2 spacing)."""
    if spacing == 'regular':
        return [H*i/n for i in range(n + 1)]
    return [H*(i/n)**2 for i in range(n + 1)]


def integral(f, z0, z1, n=200):
    """Simpson's rule (n even)."""
    h = (z1 - z0)/n
    return h/3.0*(f(z0) + f(z1) + sum((4 if i % 2 else 2)*f(z0 + i*h)
                                      for i in range(1, n)))


def gamma_layers(zf, fit='faces'):
    """Uniform-gamma layers between the interfaces zf. Each has the exact
    effusivity b_E at its top; what else it reproduces depends on fit:
      'faces': k and c at both faces (so b at both faces; xi_L from a
               linear in z): quadrupoleTemperature's conductivityBottom form;
      'eq12':  xi_L = int dz/sqrt(a) exact and gamma = (b_S - b_E)/
               (2 int c dz), the paper's eq. 12 (its 'mean gamma');
      'CR':    the layer's heat capacity int c dz and thermal resistance
               int dz/k exact (a uniform-gamma layer of top effusivity b_E,
               gamma, xi_L has C = b_E (e^(2u) - 1)/(2 gamma) and
               R = (1 - e^(-2u))/(2 gamma b_E), u = gamma xi_L: hence
               e^(2u) = C/(R b_E^2), gamma = sinh(u)/sqrt(C R))."""
    out = []
    for i in range(len(zf) - 1):
        z0, z1 = zf[i], zf[i + 1]
        L = z1 - z0
        if fit == 'faces':
            out.append(dict(thickness=L, k=k(z0), c=c(z0),
                            kBottom=k(z1), cBottom=c(z1)))
            continue
        bE, aT = b(z0), a(z0)
        if fit == 'eq12':
            xi = integral(lambda z: 1.0/math.sqrt(a(z)), z0, z1)
            g = (b(z1) - bE)/(2.0*integral(c, z0, z1))
        elif fit == 'CR':
            C = integral(c, z0, z1)
            R = integral(lambda z: 1.0/k(z), z0, z1)
            u = 0.5*math.log(C/(R*bE*bE))
            g = math.sinh(u)/math.sqrt(C*R)
            xi = u/g if u != 0 else math.sqrt(C*R)
        else:
            raise ValueError(fit)
        sqaB = 2.0*L/xi - math.sqrt(aT)
        assert sqaB > 0, 'cannot set xi_L with a linear diffusivity'
        out.append(dict(thickness=L, k=bE*math.sqrt(aT), c=bE/math.sqrt(aT),
                        gamma=g, aBottom=sqaB*sqaB))
    return out


def classical_layers(zf, rule='mean'):
    """Uniform layers (gamma = 0, uniform b and a). rule 'mean': the mean
    capacity and the harmonic mean conductivity of the layer (its heat
    capacity and its steady resistance exact); 'mid': the values at
    mid-depth."""
    out = []
    for i in range(len(zf) - 1):
        z0, z1 = zf[i], zf[i + 1]
        if rule == 'mid':
            kk, cc = k(0.5*(z0 + z1)), c(0.5*(z0 + z1))
        else:
            cc = integral(c, z0, z1)/(z1 - z0)
            kk = (z1 - z0)/integral(lambda z: 1.0/k(z), z0, z1)
        out.append(dict(thickness=z1 - z0, k=kk, c=cc, gamma=0.0,
                        aBottom=kk/cc))
    return out


def layer_profile(layer, zl):
    """(k, c) of a quadrupoleTemperature layer at zl from its top (its own
    model: a linear in z, b = b_top exp(2 gamma xi))."""
    L = layer['thickness']
    aT = layer['k']/layer['c']
    bT = math.sqrt(layer['k']*layer['c'])
    if 'gamma' in layer:
        aB, g = layer['aBottom'], layer['gamma']
    else:
        aB = layer['kBottom']/layer['cBottom']
    xi = lambda z: 2.0*z/(math.sqrt(aT) + math.sqrt(aT + (aB - aT)*z/L))
    if 'gamma' not in layer:
        bB = math.sqrt(layer['kBottom']*layer['cBottom'])
        g = math.log(bB/bT)/(2.0*xi(L))
    az = aT + (aB - aT)*zl/L
    bz = bT*math.exp(2.0*g*xi(zl))
    return bz*math.sqrt(az), bz/math.sqrt(az)


def profile_deviation(layers, n=200):
    """Largest relative deviation of k and of c of the layers from the
    soil's k(z), c(z)."""
    dk_, dc_ = 0.0, 0.0
    top = 0.0
    for L in layers:
        for j in range(n + 1):
            zl = L['thickness']*j/n
            kk, cc = layer_profile(L, zl)
            dk_ = max(dk_, abs(kk/k(top + zl) - 1.0))
            dc_ = max(dc_, abs(cc/c(top + zl) - 1.0))
        top += L['thickness']
    return dk_, dc_


def num(x):
    """A float as the shortest text that reads back exactly."""
    return repr(float(x))


def history_text(rows):
    return '(%s)' % ' '.join('(%s %s)' % (num(t), num(v)) for t, v in rows)


def quadrupole_dict(layers, surface, depths, output, outfile,
                    initial=0.0):
    """Text of a quadrupoleDict. surface: the body of the surface
    sub-dictionary; output: 'endTime ...; writeInterval ...;' or
    'times (...);'."""
    s = ['FoamFile { version 2.0; format ascii; class dictionary;'
         ' object quadrupoleDict; }',
         'initialTemperature %s;' % num(initial), 'layers', '{']
    for i, L in enumerate(layers):
        s.append('    l%d' % i)
        s.append('    {')
        s.append('        thickness %s;' % num(L['thickness']))
        s.append('        conductivity %s;' % num(L['k']))
        s.append('        volumetricHeatCapacity %s;' % num(L['c']))
        if 'gamma' in L:
            s.append('        gamma %s;' % num(L['gamma']))
            s.append('        diffusivityBottom %s;' % num(L['aBottom']))
        else:
            s.append('        conductivityBottom %s;' % num(L['kBottom']))
            s.append('        volumetricHeatCapacityBottom %s;'
                     % num(L['cBottom']))
        s.append('    }')
    s += ['}',
          'substrate { conductivity %s; volumetricHeatCapacity %s; }'
          % (num(k(H)), num(c(H))),
          'surface', '{', surface, '}',
          'depths (%s);' % ' '.join(num(d) for d in depths),
          output,
          'outputFile "%s";' % outfile,
          '']
    return '\n'.join(s)


def read_quadrupole_csv(path):
    """-> (column names, rows of floats)"""
    with open(path) as f:
        lines = [l.strip() for l in f if l.strip()]
    head = lines[0].split(',')
    return head, [[float(v) for v in l.split(',')] for l in lines[1:]]
