"""Geometric invariants of the mesh templates of etc/meshes (tests/hearthMeshes/run
builds them). For each mesh: checkMesh passed (Allmesh stops otherwise; its
'Mesh OK' is checked again here), the patches are the documented ones, the
volume printed by checkMesh equals the volume enclosed by the boundary
(recomputed here from constant/polyMesh, as a check of the reader), and the
volume and the patch areas equal the exact values of the geometry:

flat-faced meshes (flatDiscWedge, rectangularPit): to 1e-11 relative (round-
  off; measured ~1e-15). The wedge of angle 2 a with the points of radius r
  at (r, -+r tan a, z) holds tan(a)/pi of the body of revolution, and its
  faces r = const, z = const are tan(a)/pi of the full circles' areas.
flatDisc3D: the arcs are block edges, so the fire is the regular polygon of
  N = 8 nCore sides inscribed in r = rFire, the domain an N-gon prism: the
  mesh values equal the polygon's exactly (1e-11); the faceting error
  against the circle, sin(2 pi/N)/(2 pi/N) - 1 ~ -(2 pi/N)^2/6, is reported,
  must be below that bound and fall with refinement as 1/N^2.
circularBasin (curved): the basin's points must lie on the sphere (on the
  wedge: on the circle of the (r, z) plane) to 1e-12 rho, the flat patches
  (ground, side, bottom) are exact (1e-11). The basin surface is the
  surface of revolution of chords of the circle: a chord of angle d has
  cos(d/2) times the area of its spherical zone, so the fire area is short
  by between 0 and dMax^2/8 (dMax: the largest chord angle, measured on the
  mesh); the soil gains the circular segments between chords and arc,
  rho^2 (d - sin d)/2 ~ rho^2 d^3/12 each, so the volume is larger by
  between 0 and dMax^2 rho A/(12 V) relative (A: basin area, V: volume). Both errors must fall by
  at least 3 per doubling of the cells (second order: 4).
circularBasin3D: the same on the 3-D O-grid, whose circles are N-gons
  (N = 8 nCore): the basin's points on the sphere (1e-12 rho); ground, side,
  bottom exact N-gon shapes (1e-11); the volume against the N-gon body
  (N/(2 pi)) sin(2 pi/N) times the exact one, off by the faceting of the
  meridians, between 0 and dMax^2 rho A/(12 V) (dMax: the largest angle an
  edge of the basin's faces subtends at the centre); the basin area against
  the exact sphere cap, short by up to dMax^2/4 (planar quadrilaterals
  inscribed in the sphere, both directions faceted); both errors must fall
  as 1/N^2 (at least 0.9 (N2/N1)^2 from N1 to N2).
"""
import math
import os
import re

from hearthcheck import Check
from polyMeshGeometry import PolyMesh

chk = Check('hearthMeshes')
TOL_FLAT = 1e-11


def entries(path):
    """'key value;' entries of a dictionary file (scalars and words)."""
    out = {}
    with open(path) as f:
        for line in f:
            m = re.match(r'^(\w+)\s+([^;\s(]+)\s*;', line)
            if m:
                v = m.group(2)
                try:
                    v = float(v)
                except ValueError:
                    pass
                out[m.group(1)] = v
    return out


class Case:
    def __init__(self, name):
        self.name = name
        self.g = entries(os.path.join(name, 'system', 'hearthGeometry'))
        self.d = entries(os.path.join(name, 'system', 'blockMeshDict.expanded'))
        self.mesh = PolyMesh(name)
        with open(os.path.join(name, 'log.checkMesh')) as f:
            log = f.read()
        self.meshOK = re.search(r'^Mesh OK\.', log, re.M) is not None
        self.checkMeshVolume = float(
            re.search(r'Total volume = (\S+?)\.?\s', log).group(1))
        print('%s: %d cells' % (name, self.mesh.nCells))

    def common(self, patches):
        chk.true('%s: checkMesh: Mesh OK' % self.name, self.meshOK)
        chk.true('%s: patches %s' % (self.name, ' '.join(patches)),
                 list(self.mesh.patches) == patches,
                 ' '.join(self.mesh.patches))
        v = self.mesh.volume()
        chk.le('%s: |volume (boundary) / checkMesh - 1|' % self.name,
               abs(v/self.checkMeshVolume - 1), 1e-12)

    def rel(self, what, value, exact, tol):
        e = value/exact - 1 if exact else value
        chk.le('%s: %-10s %.12g vs %.12g, rel. error' % (self.name, what, value, exact),
               abs(e), tol)
        return e


def flatDiscWedge(name):
    c = Case(name)
    g = c.g
    c.common(['fire', 'ground', 'side', 'bottom', 'front', 'back', 'axis'])
    t = math.tan(math.radians(0.5*g['wedgeAngle']))
    R, D, rF = g['rDomain'], g['depth'], g['rFire']
    m = c.mesh
    c.rel('volume', m.volume(), t*R*R*D, TOL_FLAT)
    c.rel('fire', m.area('fire'), t*rF*rF, TOL_FLAT)
    c.rel('ground', m.area('ground'), t*(R*R - rF*rF), TOL_FLAT)
    c.rel('side', m.area('side'), 2*t*R*D, TOL_FLAT)
    c.rel('bottom', m.area('bottom'), t*R*R, TOL_FLAT)
    for w in ('front', 'back'):
        c.rel(w, m.area(w), R*D/math.cos(math.atan(t)), TOL_FLAT)
    chk.true('%s: axis has no faces' % name, m.patches['axis'][2] == 0)
    return c


def flatDisc3D(name):
    c = Case(name)
    g = c.g
    c.common(['fire', 'ground', 'side', 'bottom'])
    R, D, rF = g['rDomain'], g['depth'], g['rFire']
    N = 8*int(c.d['nCore'])
    p = 0.5*N*math.sin(2*math.pi/N)         # N-gon area / r^2
    m = c.mesh
    c.rel('volume', m.volume(), p*R*R*D, TOL_FLAT)
    c.rel('fire', m.area('fire'), p*rF*rF, TOL_FLAT)
    c.rel('ground', m.area('ground'), p*(R*R - rF*rF), TOL_FLAT)
    c.rel('side', m.area('side'), 2*N*R*math.sin(math.pi/N)*D, TOL_FLAT)
    c.rel('bottom', m.area('bottom'), p*R*R, TOL_FLAT)
    bound = (2*math.pi/N)**2/6
    c.eV = c.rel('volume vs cylinder (N = %d)' % N, m.volume(), math.pi*R*R*D, bound)
    c.eA = c.rel('fire vs disc', m.area('fire'), math.pi*rF*rF, bound)
    c.N = N
    return c


def circularBasin(name):
    c = Case(name)
    g = c.g
    c.common(['fire', 'ground', 'side', 'bottom', 'front', 'back', 'axis'])
    t = math.tan(math.radians(0.5*g['wedgeAngle']))
    R, D, rB, dB = g['rDomain'], g['depth'], g['rBasin'], g['dBasin']
    rho = (rB*rB + dB*dB)/(2*dB)
    zc = rho - dB
    m = c.mesh
    pts = [m.points[i] for i in m.patch_points('fire')]
    dev = max(abs(math.hypot(x, z - zc) - rho) for x, y, z in pts)
    chk.le('%s: basin points: max |dist to centre - rho|/rho' % name, dev/rho, 1e-12)
    devy = max(abs(abs(y) - x*t) for x, y, z in pts)
    chk.le('%s: basin points: max |y| - r tan(a), /rho' % name, devy/rho, 1e-12)
    back = sorted(math.atan2(z - zc, x) for x, y, z in pts if y < 0 or x == 0)
    dMax = max(b - a for a, b in zip(back, back[1:]))
    Vx = t*(R*R*D - dB*(3*rB*rB + dB*dB)/6)
    Ax = t*(rB*rB + dB*dB)
    c.rel('ground', m.area('ground'), t*(R*R - rB*rB), TOL_FLAT)
    c.rel('side', m.area('side'), 2*t*R*D, TOL_FLAT)
    c.rel('bottom', m.area('bottom'), t*R*R, TOL_FLAT)
    c.eA = c.rel('fire', m.area('fire'), Ax, dMax**2/8)
    c.eV = c.rel('volume', m.volume(), Vx, dMax**2*rho*Ax/(12*Vx))
    chk.true('%s: fire area below the exact (chords)' % name, c.eA < 0, '%.3g' % c.eA)
    chk.true('%s: volume above the exact (chords)' % name, c.eV > 0, '%.3g' % c.eV)
    print('    largest chord angle %.4g rad: bounds %.3g (area), %.3g (volume)'
          % (dMax, dMax**2/8, dMax**2*rho*Ax/(12*Vx)))
    return c


def circularBasin3D(name):
    c = Case(name)
    g = c.g
    c.common(['fire', 'ground', 'side', 'bottom'])
    R, D, rB, dB = g['rDomain'], g['depth'], g['rBasin'], g['dBasin']
    rho = (rB*rB + dB*dB)/(2*dB)
    zc = rho - dB
    N = 8*int(c.d['nCore'])
    p = 0.5*N*math.sin(2*math.pi/N)         # N-gon area / r^2
    m = c.mesh
    pts = [m.points[i] for i in m.patch_points('fire')]
    dev = max(abs(math.sqrt(x*x + y*y + (z - zc)**2) - rho) for x, y, z in pts)
    chk.le('%s: basin points: max |dist to centre - rho|/rho' % name, dev/rho, 1e-12)
    dMax = 0.0
    for f in m.patch_faces('fire'):
        for a, b in zip(f, f[1:] + f[:1]):
            chord = math.sqrt(sum((a[i] - b[i])**2 for i in range(3)))
            dMax = max(dMax, 2*math.asin(min(1.0, 0.5*chord/rho)))
    Vx = math.pi*(R*R*D - dB*(3*rB*rB + dB*dB)/6)
    Ax = math.pi*(rB*rB + dB*dB)
    c.rel('ground', m.area('ground'), p*(R*R - rB*rB), TOL_FLAT)
    c.rel('side', m.area('side'), 2*N*R*math.sin(math.pi/N)*D, TOL_FLAT)
    c.rel('bottom', m.area('bottom'), p*R*R, TOL_FLAT)
    c.eA = c.rel('fire vs cap (N = %d)' % N, m.area('fire'), Ax, dMax**2/4)
    c.eVN = c.rel('volume vs N-gon body', m.volume(), p/math.pi*Vx,
                  dMax**2*rho*Ax/(12*Vx))
    chk.true('%s: volume above the N-gon body (chords)' % name, c.eVN > 0,
             '%.3g' % c.eVN)
    c.eV = m.volume()/Vx - 1
    print('    volume vs exact %.4g (N-gon: %.4g); largest edge angle %.4g rad'
          % (c.eV, p/math.pi - 1, dMax))
    c.N = N
    return c


def rectangularPit(name):
    c = Case(name)
    g = c.g
    split = str(g['splitWalls']).lower() in ('yes', 'on', 'true', '1', 'y', '1.0')
    quarter = g['symmetry'] == 'quarter'
    walls = ['wallsLower', 'wallsUpper'] if split else ['walls']
    c.common(['floor'] + walls + ['ground', 'far']
             + (['symmetryX', 'symmetryY'] if quarter else []))
    Bx, By, Bz = g['blockLength'], g['blockWidth'], g['blockDepth']
    Lx, Ly, Hp, hH = g['pitLength'], g['pitWidth'], g['pitDepth'], g['hotHeight']
    q = 0.25 if quarter else 1.0
    m = c.mesh
    c.rel('volume', m.volume(), q*(Bx*By*Bz - Lx*Ly*Hp), TOL_FLAT)
    c.rel('floor', m.area('floor'), q*Lx*Ly, TOL_FLAT)
    if split:
        c.rel('wallsLower', m.area('wallsLower'), q*2*(Lx + Ly)*hH, TOL_FLAT)
        c.rel('wallsUpper', m.area('wallsUpper'), q*2*(Lx + Ly)*(Hp - hH), TOL_FLAT)
    else:
        c.rel('walls', m.area('walls'), q*2*(Lx + Ly)*Hp, TOL_FLAT)
    c.rel('ground', m.area('ground'), q*(Bx*By - Lx*Ly), TOL_FLAT)
    c.rel('far', m.area('far'), q*(2*(Bx + By)*Bz + Bx*By), TOL_FLAT)
    if quarter:
        c.rel('symmetryX', m.area('symmetryX'), 0.5*By*Bz - 0.5*Ly*Hp, TOL_FLAT)
        c.rel('symmetryY', m.area('symmetryY'), 0.5*Bx*Bz - 0.5*Lx*Hp, TOL_FLAT)
    return c


def falls(what, coarse, fine, factor):
    chk.le('%s: error ratio fine/coarse (%.3g/%.3g)' % (what, fine, coarse),
           abs(fine/coarse), 1.0/factor)


# -----------------------------------------------------------------------------
flatDiscWedge('wedge-r1')
flatDiscWedge('wedge-r0.5')
flatDiscWedge('wedge-other')

d1, d2 = flatDisc3D('disc3D-r0.25'), flatDisc3D('disc3D-r0.5')
# 1 - sin(x)/x falls as 1/N^2 (to 1 % at these N)
f = 0.99*(d2.N/d1.N)**2
falls('disc3D volume', d1.eV, d2.eV, f)
falls('disc3D fire', d1.eA, d2.eA, f)

b = [circularBasin(n) for n in ('basin-r0.5', 'basin-r1', 'basin-r2')]
for c1, c2 in zip(b, b[1:]):
    falls('%s -> %s volume' % (c1.name, c2.name), c1.eV, c2.eV, 3)
    falls('%s -> %s fire' % (c1.name, c2.name), c1.eA, c2.eA, 3)
chk.true('basin-r2 has 4 times the cells of basin-r1 (2-D)',
         b[2].mesh.nCells == 4*b[1].mesh.nCells,
         '%d, %d' % (b[1].mesh.nCells, b[2].mesh.nCells))
circularBasin('basin-hemi')

b1, b2 = circularBasin3D('basin3D-r0.25'), circularBasin3D('basin3D-r0.5')
f = 0.9*(b2.N/b1.N)**2
falls('basin3D fire', b1.eA, b2.eA, f)
falls('basin3D volume', b1.eV, b2.eV, f)
falls('basin3D volume vs N-gon body', b1.eVN, b2.eVN, f)

rectangularPit('pit-quarter')
rectangularPit('pit-full')
rectangularPit('pit-5.4')

chk.done()
