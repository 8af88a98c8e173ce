"""Liquid bridge between two equal spheres (standard library only): the meniscus shape
of Mansour (2015) §2.2 and the liquid fraction of the cell of §2.1.

Non-dimensional: lengths in R_0 (the sphere radius), so R_0 = 1. The cell
(Mansour §2.1, Fig. 2.3; its extent is read from the figure: r in [0, 1],
z in [0, eps + 1]) is the quarter of the two-grain pattern between the
mid-gap plane z = 0 and the plane z = c = eps + 1 through the centre of the
upper sphere (radius 1, centre (0, c)); eps is HALF the gap.

Meniscus (Young-Laplace, constant total curvature kappa, eqs. 2.2-2.7):
with the arc length s and the tangent angle beta (r' = cos beta,
z' = sin beta, so eq. 2.6 holds exactly and r'z'' - z'r'' = beta'),
eq. 2.7 reads

    beta' = kappa - sin(beta)/r,    V_b' = pi r^2 sin(beta)   (eq. 2.8)

integrated (RK4) from the start point A until the curve enters the sphere
at B; the contact angle (through the liquid) is theta = beta_B - phi_B,
phi_B = arcsin(r_B) (§2.2.2). Start points (§2.2; the printed z' = 0 and
r' = 0 of the two cases are swapped: a bridge's neck on the mid-plane is
vertical, a drop's apex on the axis horizontal):

    contacting    (bridge):  r = r0, z = 0,  beta = pi/2
    noncontacting (drop):    r = 0,  z = z0, beta = 0, beta' = kappa/2

A shooting on kappa (bisection) for the prescribed theta at a given r0 or
z0 (Mansour shot on r0 at a given kappa: the same family). The liquid
volume in the cell is V = V_b - V_c, V_c = pi h^2 (3 - h)/3 the cap of the
sphere below z_B, h = z_B - eps (§2.2.1); the liquid fraction is V over
the void volume of the cell pi (1 + eps) - 2 pi/3 (§2.4: liquid volume
over void volume).

toroidal approximation (option): the meridian a circle arc (radius rho,
neck r0; the classical approximation Mansour's exact shape replaces),
meeting the sphere at the prescribed theta.

The drops of the non-contacting state are spherical caps (§2.2: "exactly
spherical caps"): drop_cap() gives them in closed form, an independent
check of the integration (tests/grainBridge).
"""

import bisect
import math


def void_volume(eps):
    """Void volume of the cell (R_0 = 1): cylinder minus half sphere."""
    return math.pi*(1.0 + eps) - 2.0*math.pi/3.0


def cap_volume(h):
    """Volume of a cap of height h of the unit sphere."""
    return math.pi*h*h*(3.0 - h)/3.0


class Profile:
    """A meniscus: points (r, z) from A to B, contact data, volumes."""

    def __init__(self, r, z, beta_b, kappa, eps, state):
        self.r = list(r)
        self.z = list(z)
        self.kappa = kappa
        self.eps = eps
        self.state = state
        self.rB, self.zB = self.r[-1], self.z[-1]
        self.theta = beta_b - math.asin(min(1.0, self.rB))
        self.volume = None          # set by the builder
        self.area = None

    def liquid_fraction(self):
        return self.volume/void_volume(self.eps)

    def r_at(self, z):
        """Radius of the meniscus at height z (linear between points); the
        profile rises monotonically (beta in (0, pi), integrate checks)."""
        i = bisect.bisect_left(self.z, z)
        i = min(max(i, 1), len(self.z) - 1)
        z0, z1 = self.z[i - 1], self.z[i]
        w = (z - z0)/(z1 - z0) if z1 > z0 else 0.0
        return self.r[i - 1] + w*(self.r[i] - self.r[i - 1])

    def is_liquid(self, rc, zc):
        """The point (rc, zc) lies in the liquid: between the start height
        and B, inside the meniscus and outside the sphere."""
        c = 1.0 + self.eps
        return (
            self.z[0] <= zc <= self.zB and rc < self.r_at(zc)
            and rc*rc + (zc - c)**2 > 1.0
        )


def _rhs(y, kappa):
    r, z, beta, vb, area = y
    sb = math.sin(beta)
    curv = kappa - sb/r if r > 1e-12 else 0.5*kappa
    return [math.cos(beta), sb, curv, math.pi*r*r*sb, 2.0*math.pi*r]


def _axpy(y, a, k):
    return [yi + a*ki for yi, ki in zip(y, k)]


def _rk4(y, h, kappa):
    k1 = _rhs(y, kappa)
    k2 = _rhs(_axpy(y, 0.5*h, k1), kappa)
    k3 = _rhs(_axpy(y, 0.5*h, k2), kappa)
    k4 = _rhs(_axpy(y, h, k3), kappa)
    return [yi + h/6.0*(a + 2*b + 2*c + d)
            for yi, a, b, c, d in zip(y, k1, k2, k3, k4)]


def integrate(start, kappa, eps, ds=2e-3, keep=False):
    """Integrate from start = (r, z, beta) until the curve enters the
    sphere. Returns (state vector at B, list of points) or None if the
    curve leaves the cell (r > 1, z < 0), turns back or runs too long."""
    c = 1.0 + eps
    y = [start[0], start[1], start[2], 0.0, 0.0]
    pts = [(y[0], y[1])] if keep else None

    def f(y):
        return y[0]*y[0] + (y[1] - c)**2 - 1.0

    s = 0.0
    while s < 6.0:
        yn = _rk4(y, ds, kappa)
        if yn[0] > 1.0 + 1e-12 or yn[1] < -1e-12 or yn[0] < -1e-12 \
                or not (0.0 < yn[2] < math.pi):
            return None
        if f(yn) < 0:
            # Bisection on the step into the sphere
            lo, hi = 0.0, ds
            for _ in range(50):
                mid = 0.5*(lo + hi)
                if f(_rk4(y, mid, kappa)) < 0:
                    hi = mid
                else:
                    lo = mid
            yb = _rk4(y, lo, kappa)
            if keep:
                pts.append((yb[0], yb[1]))
            return yb, pts
        y = yn
        s += ds
        if keep:
            pts.append((y[0], y[1]))
    return None


def _theta(start, kappa, eps, ds):
    res = integrate(start, kappa, eps, ds)
    if res is None:
        return None
    yb = res[0]
    return yb[2] - math.asin(min(1.0, yb[0]))


def shoot(start, theta, eps, kmin=-40.0, kmax=40.0, n=161, ds=2e-3):
    """kappa giving the contact angle theta [rad] from start (r, z, beta):
    scan [kmin, kmax] for a sign change of theta(kappa) - theta, then
    bisect. Where the scan passes from curvatures whose curve reaches the
    sphere to curvatures whose curve does not (it turns horizontal first:
    small contact angles), the last curvature that reaches it is found by
    bisection and enters the scan, so that a root between it and the scan
    point is not missed. None if there is no such kappa."""
    def g(k):
        t = _theta(start, k, eps, ds)
        return None if t is None else t - theta

    def edge(a, b):
        # a reaches the sphere, b does not: the reaching end next to b
        # (to 2^-30 of the scan step)
        for _ in range(30):
            m = 0.5*(a + b)
            if g(m) is None:
                b = m
            else:
                a = m
        return a

    ks = [kmin + (kmax - kmin)*i/(n - 1) for i in range(n)]
    prev, prevK = None, None
    for k in ks:
        gk = g(k)
        pts = []
        if gk is None and prev is not None:
            e = edge(prev[0], k)
            pts = [(e, g(e))]
        elif gk is not None and prev is None and prevK is not None:
            e = edge(k, prevK)
            prev = (e, g(e))
        if gk is not None:
            pts.append((k, gk))
        for kk, gg in pts:
            if prev is not None and prev[1]*gg <= 0:
                a, ga = prev
                b = kk
                for _ in range(60):
                    m = 0.5*(a + b)
                    gm = g(m)
                    if gm is None:
                        b = m
                        continue
                    if ga*gm <= 0:
                        b = m
                    else:
                        a, ga = m, gm
                return 0.5*(a + b)
            prev = (kk, gg)
        if gk is None:
            prev = None
        prevK = k
    return None


def _build(start, kappa, eps, state, ds):
    yb, pts = integrate(start, kappa, eps, ds, keep=True)
    r, z = zip(*pts)
    p = Profile(r, z, yb[2], kappa, eps, state)
    h = yb[1] - eps
    p.volume = yb[3] - cap_volume(h)
    if state == "noncontacting":
        # The drop's region starts at its apex: add nothing below z0
        pass
    p.area = yb[4]
    return p


def bridge(r0, theta, eps, ds=2e-3):
    """Contacting state: the bridge of neck radius r0 (on z = 0) meeting
    the sphere at theta [rad]; None if none."""
    start = (r0, 0.0, 0.5*math.pi)
    k = shoot(start, theta, eps, ds=ds)
    return None if k is None else _build(start, k, eps, "contacting", ds)


def drop(z0, theta, eps, ds=2e-3):
    """Non-contacting state: the drop hanging from the sphere with its
    apex at (0, z0), 0 <= z0 < eps; None if none."""
    start = (0.0, z0, 0.0)
    k = shoot(start, theta, eps, kmin=1e-3, kmax=400.0, n=401, ds=ds)
    return None if k is None else _build(start, k, eps, "noncontacting", ds)


def drop_cap(z0, theta, eps):
    """The same drop in closed form: the sphere of radius rho, centre
    (0, z0 + rho), meeting the unit sphere (centre (0, c)) at theta:
    D^2 = 1 + rho^2 - 2 rho cos(theta), D = c - z0 - rho. Returns
    (rho, volume of the drop outside the grain)."""
    c = 1.0 + eps
    a = c - z0                      # D = a - rho
    # (a - rho)^2 = 1 + rho^2 - 2 rho cos(theta)
    rho = (a*a - 1.0)/(2.0*(a - math.cos(theta)))
    d = z0 + rho
    D = c - d
    # Plane of the intersection circle (from the grain centre, downwards)
    zB = c - (1.0 + D*D - rho*rho)/(2.0*D)
    vdrop = math.pi*(zB - z0)**2*(3.0*rho - (zB - z0))/3.0
    return rho, vdrop - cap_volume(zB - eps)


def toroidal(r0, theta, eps, n=4000):
    """Toroidal approximation: the meridian a circle of radius rho centred
    at (r0 + rho, 0) (vertical at the neck), rho chosen so that it meets
    the sphere at theta. Returns a Profile (volume by the midpoint rule of
    pi r^2 dz on n steps of the circle's angle)."""
    c = 1.0 + eps

    def meet(rho):
        # Up the circle from the neck (t = 0, beta = pi/2 - t) to the sphere
        pts = [(r0, 0.0)]
        vb = 0.0
        for i in range(1, n + 1):
            t = 0.5*math.pi*i/n
            r, z = r0 + rho - rho*math.cos(t), rho*math.sin(t)
            if r*r + (z - c)**2 < 1.0:
                # Bisection on t in the last step
                lo, hi = 0.5*math.pi*(i - 1)/n, t
                for _ in range(50):
                    m = 0.5*(lo + hi)
                    rm, zm = r0 + rho - rho*math.cos(m), rho*math.sin(m)
                    if rm*rm + (zm - c)**2 < 1.0:
                        hi = m
                    else:
                        lo = m
                r, z = r0 + rho - rho*math.cos(lo), rho*math.sin(lo)
                rp, zp = pts[-1]
                vb += math.pi*(0.5*(r + rp))**2*(z - zp)
                pts.append((r, z))
                return pts, 0.5*math.pi - lo, vb
            rp, zp = pts[-1]
            vb += math.pi*(0.5*(r + rp))**2*(z - zp)
            pts.append((r, z))
        return None

    def g(rho):
        m = meet(rho)
        if m is None:
            return None
        return m[1] - math.asin(min(1.0, m[0][-1][0])) - theta

    prev = None
    for i in range(121):
        rho = 1e-3*10.0**(4.0*i/120)
        v = g(rho)
        if v is not None and prev is not None and prev[1]*v <= 0:
            a, ga, b = prev[0], prev[1], rho
            for _ in range(50):
                m = 0.5*(a + b)
                gm = g(m)
                if gm is None or ga*gm <= 0:
                    b = m
                else:
                    a, ga = m, gm
            rho = 0.5*(a + b)
            pts, beta, vb = meet(rho)
            r, z = zip(*pts)
            p = Profile(r, z, beta, float('nan'), eps, "contacting")
            p.rho = rho
            p.volume = vb - cap_volume(z[-1] - eps)
            return p
        prev = (rho, v) if v is not None else None
    return None
