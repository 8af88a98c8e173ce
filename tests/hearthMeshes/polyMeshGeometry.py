"""Reading an ascii OpenFOAM polyMesh and computing the geometric invariants
the hearthMeshes test checks: patch areas and the enclosed volume, with the
face areas and centres computed as OpenFOAM does (triangles fanned about the
average of the face's points), so that the volume of the domain,
(1/3) sum over boundary faces of x_f . S_f, equals the sum of OpenFOAM's cell
volumes. Standard library only."""
import math
import os
import re


def _body(path):
    """Text of an OpenFOAM file after its FoamFile header, comments removed."""
    with open(path) as f:
        txt = f.read()
    txt = re.sub(r'/\*.*?\*/', '', txt, flags=re.S)
    txt = re.sub(r'//[^\n]*', '', txt)
    i = txt.find('FoamFile')
    if i >= 0:
        depth, j = 0, txt.index('{', i)
        while True:
            if txt[j] == '{':
                depth += 1
            elif txt[j] == '}':
                depth -= 1
                if depth == 0:
                    break
            j += 1
        txt = txt[j + 1:]
    return txt


def _list_start(txt):
    m = re.search(r'(\d+)\s*\(', txt)
    return int(m.group(1)), m.end()


def read_points(path):
    txt = _body(path)
    n, i = _list_start(txt)
    vals = re.findall(r'\(\s*([^()\s]+)\s+([^()\s]+)\s+([^()\s]+)\s*\)', txt[i:])
    assert len(vals) >= n, path
    return [(float(x), float(y), float(z)) for x, y, z in vals[:n]]


def read_faces(path):
    txt = _body(path)
    n, i = _list_start(txt)
    faces = [[int(v) for v in m.group(2).split()]
             for m in re.finditer(r'(\d+)\s*\(([^()]*)\)', txt[i:])]
    assert len(faces) >= n, path
    return faces[:n]


def read_boundary(path):
    """{patch name: (type, startFace, nFaces)}, in file order."""
    txt = _body(path)
    out = {}
    for m in re.finditer(r'(\w+)\s*\{([^{}]*)\}', txt):
        d = dict(re.findall(r'(\w+)\s+([^;]+);', m.group(2)))
        out[m.group(1)] = (d['type'], int(d['startFace']), int(d['nFaces']))
    return out


def _sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def _cross(a, b):
    return (a[1]*b[2] - a[2]*b[1], a[2]*b[0] - a[0]*b[2], a[0]*b[1] - a[1]*b[0])


def _dot(a, b):
    return a[0]*b[0] + a[1]*b[1] + a[2]*b[2]


def _mag(a):
    return math.sqrt(_dot(a, a))


def face_centre_area(p):
    """OpenFOAM's primitiveMesh face centre and area vector of points p."""
    if len(p) == 3:
        c = tuple((p[0][k] + p[1][k] + p[2][k])/3.0 for k in range(3))
        n = _cross(_sub(p[1], p[0]), _sub(p[2], p[0]))
        return c, (0.5*n[0], 0.5*n[1], 0.5*n[2])
    m = len(p)
    est = tuple(sum(q[k] for q in p)/m for k in range(3))
    sumN = [0.0, 0.0, 0.0]
    sumA = 0.0
    sumAc = [0.0, 0.0, 0.0]
    for i in range(m):
        a, b = p[i], p[(i + 1) % m]
        c = tuple(a[k] + b[k] + est[k] for k in range(3))
        n = _cross(_sub(b, a), _sub(est, a))
        mn = _mag(n)
        for k in range(3):
            sumN[k] += n[k]
            sumAc[k] += mn*c[k]
        sumA += mn
    if sumA < 1e-300:
        return est, (0.0, 0.0, 0.0)
    return tuple(sumAc[k]/(3.0*sumA) for k in range(3)), \
        (0.5*sumN[0], 0.5*sumN[1], 0.5*sumN[2])


class PolyMesh:
    """The boundary of an ascii polyMesh: patch areas, enclosed volume."""

    def __init__(self, case):
        d = os.path.join(case, 'constant', 'polyMesh')
        self.points = read_points(os.path.join(d, 'points'))
        self.faces = read_faces(os.path.join(d, 'faces'))
        self.patches = read_boundary(os.path.join(d, 'boundary'))
        self.nCells = 1 + max(int(v) for v in
                              _body(os.path.join(d, 'owner')).split()[2:]
                              if v.isdigit())

    def patch_faces(self, name):
        _, start, n = self.patches[name]
        for f in self.faces[start:start + n]:
            yield [self.points[i] for i in f]

    def patch_points(self, name):
        """Indices of the points of a patch."""
        _, start, n = self.patches[name]
        return sorted({i for f in self.faces[start:start + n] for i in f})

    def area(self, name):
        return sum(_mag(face_centre_area(p)[1]) for p in self.patch_faces(name))

    def volume(self):
        """(1/3) sum over all boundary faces of x_f . S_f."""
        v = 0.0
        for name in self.patches:
            for p in self.patch_faces(name):
                c, s = face_centre_area(p)
                v += _dot(c, s)
        return v/3.0
