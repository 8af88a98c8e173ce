"""scanSurface: the scanned surface of etc/meshes/scannedPit, shared by
bin/prepareScan (which puts the scan in the ground frame and closes it with
the ground) and bin/hearthCase (which places sensors and alteration lines
under the prepared surface).

read_stl, read_obj: the triangles of a surface file (lists of 3 points).
rotation_to_z: the smallest rotation taking a unit vector to +z.
die: print 'prepareScan: MESSAGE' on stderr and exit 1 (prepareScan's
    error, kept so that the readers stop the way prepareScan always has).
heightAt(tris, x, y): the height of the highest triangle of the prepared
    surface above the point (x, y) (a vertical line from the air down
    meets it first), None if the line misses the surface.
rimOnAxis(rim): where the closed rim polyline crosses the half-line
    y = 0, x > 0: (x, z), linearly along the segment crossed.
readPrepared(outdir): the triangles of OUTDIR/fire.stl and the rim points
    of OUTDIR/rim.eMesh, as prepareScan wrote them.
"""
import math
import struct
import sys


def die(msg):
    print("prepareScan: " + msg, file=sys.stderr)
    sys.exit(1)


def read_stl(name):
    data = open(name, "rb").read()
    tris = []
    head = data[:512].lstrip().lower()
    if head.startswith(b"solid") and b"facet" in data[:2000].lower():
        verts = []
        for line in data.decode("ascii", "replace").splitlines():
            w = line.split()
            if w and w[0].lower() == "vertex":
                verts.append(tuple(float(x) for x in w[1:4]))
        if len(verts) % 3:
            die("%s: the number of vertices is not a multiple of 3" % name)
        tris = [verts[i:i + 3] for i in range(0, len(verts), 3)]
    else:
        if len(data) < 84:
            die("%s: not an STL file" % name)
        n = struct.unpack("<I", data[80:84])[0]
        if len(data) < 84 + 50 * n:
            die("%s: truncated binary STL (%d triangles announced)" % (name, n))
        for i in range(n):
            v = struct.unpack("<12f", data[84 + 50 * i:84 + 50 * i + 48])
            tris.append([v[3:6], v[6:9], v[9:12]])
    return tris


def read_obj(name):
    pts, tris = [], []
    for line in open(name, errors="replace"):
        w = line.split()
        if not w:
            continue
        if w[0] == "v":
            pts.append(tuple(float(x) for x in w[1:4]))
        elif w[0] == "f":
            idx = []
            for t in w[1:]:
                k = int(t.split("/")[0])
                idx.append(k - 1 if k > 0 else len(pts) + k)
            for j in range(1, len(idx) - 1):
                tris.append([pts[idx[0]], pts[idx[j]], pts[idx[j + 1]]])
    return tris


def sub(a, b):
    return [a[0] - b[0], a[1] - b[1], a[2] - b[2]]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0]]


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def norm(a):
    return math.sqrt(dot(a, a))


def rotation_to_z(n):
    """The smallest rotation taking the unit vector n to +z (Rodrigues)."""
    z = [0.0, 0.0, 1.0]
    c = dot(n, z)
    k = cross(n, z)
    s = norm(k)
    if s < 1e-12:
        if c > 0:
            return [[1, 0, 0], [0, 1, 0], [0, 0, 1]]
        return [[1, 0, 0], [0, -1, 0], [0, 0, -1]]
    k = [x / s for x in k]
    K = [[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]]
    KK = [[sum(K[i][m] * K[m][j] for m in range(3)) for j in range(3)]
          for i in range(3)]
    return [[(1 if i == j else 0) + s * K[i][j] + (1 - c) * KK[i][j]
             for j in range(3)] for i in range(3)]


def heightAt(tris, x, y):
    """Barycentric test of (x, y) in each triangle's projection, then
    the plane's height there; the highest (the first met from above)"""
    best = None
    for a, b, c in tris:
        det = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1])
        if det == 0:
            continue        # a vertical triangle: met by its neighbours
        l1 = ((x - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (y - a[1])) / det
        l2 = ((b[0] - a[0]) * (y - a[1]) - (x - a[0]) * (b[1] - a[1])) / det
        eps = 1e-12
        if l1 < -eps or l2 < -eps or l1 + l2 > 1 + eps:
            continue
        z = a[2] + l1 * (b[2] - a[2]) + l2 * (c[2] - a[2])
        if best is None or z > best:
            best = z
    return best


def rimOnAxis(rim):
    """The rim's crossing of y = 0, x > 0 (the farthest if several)"""
    out = None
    for i in range(len(rim)):
        p, q = rim[i], rim[(i + 1) % len(rim)]
        if (p[1] > 0) == (q[1] > 0) and p[1] != 0:
            continue
        if q[1] == p[1]:
            continue
        t = -p[1] / (q[1] - p[1])
        if not 0 <= t <= 1:
            continue
        x = p[0] + t * (q[0] - p[0])
        if x > 0 and (out is None or x > out[0]):
            out = (x, p[2] + t * (q[2] - p[2]))
    return out


def readPrepared(outdir):
    import os
    tris = read_stl(os.path.join(outdir, "fire.stl"))
    with open(os.path.join(outdir, "rim.eMesh")) as f:
        text = f.read()
    body = text.split("}", 1)[1]
    n = int(body.split()[0])
    pts = []
    for line in body.split("(", 1)[1].splitlines():
        w = line.strip().strip("()").split()
        if len(w) == 3:
            pts.append(tuple(float(v) for v in w))
        if len(pts) == n:
            break
    return tris, pts
