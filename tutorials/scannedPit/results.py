"""scannedPit: the summary of the run (results.txt).

    python3 results.py NPROCS SECONDS

For each line of system/hearthAlterationDict, the distance from its start to
the scanned surface (the first crossing of constant/triSurface/fire.stl,
the scan as meshed: ground frame, centred) and, for each threshold, the
thickness of soil behind the surface whose TMax reached it: hearthAlteration's
distance from the start minus the distance to the surface."""
import csv
import math
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                '..', '..', 'etc', 'python'))
from hearthTutorial import Figures  # noqa: E402

nProcs, seconds = sys.argv[1], sys.argv[2]


def read_stl(path):
    """Triangles of an ASCII STL and the name of the solid of each."""
    tris, v, solid = [], [], ''
    for line in open(path):
        w = line.split()
        if w and w[0] == 'solid':
            solid = w[1] if len(w) > 1 else ''
        elif w and w[0] == 'vertex':
            v.append(tuple(float(x) for x in w[1:4]))
            if len(v) == 3:
                tris.append((v, solid))
                v = []
    return tris


def first_hit(o, d, tris):
    """Smallest t > 0 with o + t d on a triangle (Moller-Trumbore), the
    triangle's solid, its slope [deg from horizontal] and the cosine of
    the angle between the line and the triangle's normal."""
    best = (None, '', None, None)
    for (a, b, c), solid in tris:
        e1 = [b[k] - a[k] for k in range(3)]
        e2 = [c[k] - a[k] for k in range(3)]
        p = [d[1]*e2[2] - d[2]*e2[1], d[2]*e2[0] - d[0]*e2[2],
             d[0]*e2[1] - d[1]*e2[0]]
        det = sum(e1[k]*p[k] for k in range(3))
        if abs(det) < 1e-14:
            continue
        s = [o[k] - a[k] for k in range(3)]
        u = sum(s[k]*p[k] for k in range(3))/det
        if u < 0 or u > 1:
            continue
        q = [s[1]*e1[2] - s[2]*e1[1], s[2]*e1[0] - s[0]*e1[2],
             s[0]*e1[1] - s[1]*e1[0]]
        v = sum(d[k]*q[k] for k in range(3))/det
        if v < 0 or u + v > 1:
            continue
        t = sum(e2[k]*q[k] for k in range(3))/det
        if t > 0 and (best[0] is None or t < best[0]):
            n = [e1[1]*e2[2] - e1[2]*e2[1], e1[2]*e2[0] - e1[0]*e2[2],
                 e1[0]*e2[1] - e1[1]*e2[0]]
            slope = math.degrees(math.acos(min(1.0, abs(n[2])/math.sqrt(
                sum(x*x for x in n)))))
            cosine = abs(sum(d[k]*n[k] for k in range(3)))/math.sqrt(
                sum(x*x for x in n))
            best = (t, solid, slope, cosine)
    return best


txt = open('system/hearthAlterationDict').read()
lines = {}
for m in re.finditer(r'(\w+)\s*\{\s*start\s*\(([^)]*)\)\s*;\s*end\s*\(([^)]*)\)',
                     txt):
    s = [float(x) for x in m.group(2).split()]
    e = [float(x) for x in m.group(3).split()]
    L = math.sqrt(sum((e[k] - s[k])**2 for k in range(3)))
    lines[m.group(1)] = (s, [(e[k] - s[k])/L for k in range(3)])
tris = read_stl('constant/triSurface/fire.stl')
hits = {n: first_hit(s, d, tris) for n, (s, d) in lines.items()}
surf = {n: h[0] for n, h in hits.items()}

d = 'postProcessing/hearthAlteration'
t = sorted(os.listdir(d), key=float)[-1]
rows = list(csv.DictReader(open(os.path.join(d, t, 'summary.csv'))))
allmesh = open('log.Allmesh').read()
cells = re.search(r'cells: *(\d+)', allmesh).group(1)
layers = re.search(r'boundary layers: (.*)', allmesh).group(1)
scan = re.search(r'prepareScan: (.*)', allmesh).group(1)

# figures.csv: what the README prints (tests/tutorialScannedPit)
fig = Figures()
fig.add('cells', float(cells), '')
number = r'(-?[\d.]+)'
m = re.search(r'(\d+) triangles .*rim of (\d+) points .*pit %s m deep.*'
              r'area %s m2, volume %s m3' % (number, number, number), scan)
for k, (name, unit) in enumerate((('triangles', ''), ('rimPoints', ''),
                                  ('pitDepth', 'm'), ('area', 'm2'),
                                  ('volume', 'm3'))):
    fig.add(name, float(m.group(k + 1)), unit)
m = re.search(r'%s of \d+ on average .*coverage %s\), %s m thick'
              % (number, number, number), layers)
for k, (name, unit) in enumerate((('layersMean', ''), ('layerCoverage', ''),
                                  ('layerThickness', 'm'))):
    fig.add(name, float(m.group(k + 1)), unit)
for n in lines:
    if surf[n] is None:
        continue
    fig.add('surface_%s' % n, 100*surf[n], 'cm')
    fig.add('slope_%s' % n, hits[n][2], 'deg')
    fig.add('cosine_%s' % n, hits[n][3], '')
    for r in rows:
        dep = float(r['depth_%s_m' % n])
        th = '%g' % float(r['threshold_C'])
        fig.add('depth%s_%s' % (th, n),
                100*(dep - surf[n]) if dep > 0 else None, 'cm')
        fig.add('normal%s_%s' % (th, n),
                100*(dep - surf[n])*hits[n][3] if dep > 0 else None, 'cm')
if os.path.exists('TMaxSection.csv'):
    for r in csv.DictReader(open('TMaxSection.csv')):
        th = '%g' % float(r['TMax_C'])
        for key, name in (('depth_under_centre_m', 'sectionDepth'),
                          ('largest_horizontal_extent_m', 'sectionWidth')):
            v = r[key]
            fig.add('%s%s' % (name, th),
                    100*float(v) if v not in ('', 'nan') else None, 'cm')
fig.write()

print('scannedPit: a synthetic scanned pit, floor at 600 C and walls at 400 C '
      'for %g h on wet clay (phi = 10 %%)' % (float(t)/3600))
print('  scan: %s' % scan)
print('  mesh: %s cells; boundary layers: %s' % (cells, layers))
print('  ahcFoam on %s rank(s): %s s wall time (mesh to reconstructPar)'
      % (nProcs, seconds))
print()
print('  Soil altered behind the scanned surface at t = %s s [cm] (from '
      'hearthAlteration;' % t)
print('  "surface": distance from the line\'s start to the scan; the patch and')
print('  its slope there)')
head = '  %-10s %8s %-6s %5s' % ('line', 'surface', 'patch', 'slope') + ''.join(
    ' %9s' % ('%g C' % float(r['threshold_C'])) for r in rows)
print(head)
for n in lines:
    out = '  %-10s %8s %-6s %5s' % (
        n, '%.1f' % (100*surf[n]) if surf[n] else '-', hits[n][1],
        '%.0f' % hits[n][2] if surf[n] else '-')
    for r in rows:
        dep = float(r['depth_%s_m' % n])
        if surf[n] is None or dep <= 0:
            out += ' %9s' % '-'
        else:
            out += ' %9.1f' % (100*(dep - surf[n]))
    print(out)
print()
print('  The same thicknesses normal to the surface (x the cosine of the angle')
print('  between the line and the normal of the scan where the line meets it;')
print('  a horizontal line into a sloping wall crosses the layer obliquely)')
print('  %-10s %6s' % ('line', 'cosine') + ''.join(
    ' %9s' % ('%g C' % float(r['threshold_C'])) for r in rows))
for n in lines:
    if surf[n] is None:
        continue
    out = '  %-10s %6.2f' % (n, hits[n][3])
    for r in rows:
        dep = float(r['depth_%s_m' % n])
        out += ' %9s' % ('-' if dep <= 0 else
                         '%.1f' % (100*(dep - surf[n])*hits[n][3]))
    print(out)
if os.path.exists('TMaxSection.csv'):
    print()
    print('  TMax section y = 0 (plotTMaxSection, TMaxSection.png): depth '
          'below the ground under the centre, largest half-width [cm]')
    for r in csv.DictReader(open('TMaxSection.csv')):
        dz, w = r['depth_under_centre_m'], r['largest_horizontal_extent_m']
        print('  %5g C  %6s  %6s' % (float(r['TMax_C']),
              '%.1f' % (100*float(dz)) if dz not in ('', 'nan') else '-',
              '%.1f' % (100*float(w)) if w not in ('', 'nan') else '-'))
