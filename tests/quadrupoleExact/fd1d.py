"""Independent reference for tests/quadrupoleExact: 1-D transient conduction
in layered (and graded) soil by finite volumes and Crank-Nicolson, in pure
Python (no numpy).

Grid: nodes z_0 = 0 < z_1 < ... < z_N = depth_max, uniform spacing h down to
z_uniform (every layer interface and output depth must be a node there),
then spacings growing by the factor 'stretch' (the substrate far below; the
bottom node is held at the initial temperature, far enough for the heat not
to reach it). Control volumes between the mid-points of the nodes
(half-volume at the surface). Heat capacity of a control volume: the
mid-point rule on each half (each half lies in one layer); conductance of
a face: k at the face mid-point over the node spacing. Second order in
space on the uniform part; Crank-Nicolson (second order in time), the
tridiagonal matrix factorised once.

Surface: 'temperature' (the node z_0 follows theta(t)) or 'flux' (theta(t)
enters the half control volume of z_0). theta is the piecewise-linear
history (rise above the initial temperature, or flux), linear between
rows, held after the last.

Layers: dicts with thickness, bTop, aTop, aBottom, gamma (the model of
quadrupoleTemperature: b = bTop exp(2 gamma xi), a linear in z,
xi = 2 z/(sqrt(aTop) + sqrt(a(z))), c = b/sqrt(a), k = b sqrt(a)).
"""
import math


def layer_props(L, z):
    """(k, c) at z from the top of layer L."""
    a = L['aTop'] + (L['aBottom'] - L['aTop'])*z/L['thickness']
    xi = 2.0*z/(math.sqrt(L['aTop']) + math.sqrt(a))
    b = L['bTop']*math.exp(2.0*L['gamma']*xi)
    return b*math.sqrt(a), b/math.sqrt(a)


class Soil:
    def __init__(self, layers, substrate):
        self.layers = layers
        self.substrate = substrate      # (b, a)
        self.tops = []
        z = 0.0
        for L in layers:
            self.tops.append(z)
            z += L['thickness']
        self.H = z

    def props(self, z, below):
        """(k, c) at depth z; at an interface, of the layer below if
        'below' else of the layer above."""
        for L, top in zip(self.layers, self.tops):
            bottom = top + L['thickness']
            inside = (top <= z < bottom) if below else (top < z <= bottom)
            if inside:
                return layer_props(L, z - top)
        b, a = self.substrate
        return b*math.sqrt(a), b/math.sqrt(a)


def history_value(rows, t):
    """theta(t) of the piecewise-linear history (t > 0)."""
    if t <= rows[0][0]:
        return rows[0][1]
    for (t0, v0), (t1, v1) in zip(rows, rows[1:]):
        if t0 <= t <= t1 and t1 > t0:
            return v0 + (v1 - v0)*(t - t0)/(t1 - t0)
    return rows[-1][1]


def make_grid(h, z_uniform, depth_max, stretch):
    z = [0.0]
    n = int(round(z_uniform/h))
    for i in range(1, n + 1):
        z.append(i*h)
    dz = h
    while z[-1] < depth_max:
        dz *= stretch
        z.append(z[-1] + dz)
    return z


def solve(soil, bc, rows, h, dt, t_end, out_depths, out_times,
          z_uniform, depth_max, stretch):
    """Temperature rise at out_depths (and the surface first) at out_times
    (multiples of dt). Returns {time: [T_surface, T_d1, ...]}."""
    z = make_grid(h, z_uniform, depth_max, stretch)
    N = len(z) - 1
    # node indices of the outputs
    idx = [0]
    for d in out_depths:
        i = int(round(d/h))
        if abs(z[i] - d) > 1e-9*h:
            raise ValueError('output depth %g is not a node' % d)
        idx.append(i)
    for top in soil.tops[1:] + [soil.H]:
        i = int(round(top/h))
        if abs(z[i] - top) > 1e-9*h:
            raise ValueError('interface %g is not a node' % top)

    # conductances of the faces i+1/2 and capacities of the nodes
    K = []
    for i in range(N):
        zm = 0.5*(z[i] + z[i + 1])
        k, _ = soil.props(zm, True)
        K.append(k/(z[i + 1] - z[i]))
    C = [0.0]*(N + 1)
    for i in range(N):
        d = z[i + 1] - z[i]
        _, c_lo = soil.props(z[i] + 0.25*d, True)
        _, c_hi = soil.props(z[i + 1] - 0.25*d, False)
        C[i] += 0.5*d*c_lo
        C[i + 1] += 0.5*d*c_hi

    # unknowns: nodes 0..N-1 (flux) or 1..N-1 (temperature); z_N held at 0
    first = 1 if bc == 'temperature' else 0
    n = N - first
    # (C/dt + L/2) T^{n+1} = (C/dt - L/2) T^n + sources
    # L T_i = -K_{i-1/2}(T_{i-1} - T_i) - K_{i+1/2}(T_{i+1} - T_i) (positive)
    lo = [0.0]*n
    di = [0.0]*n
    up = [0.0]*n
    for m in range(n):
        i = m + first
        kl = K[i - 1] if i > 0 else 0.0
        kr = K[i]
        di[m] = C[i]/dt + 0.5*(kl + kr)
        lo[m] = -0.5*kl if m > 0 else 0.0
        up[m] = -0.5*kr if m < n - 1 else 0.0
    # factorise (Thomas)
    cp = [0.0]*n
    dp = [0.0]*n
    dp[0] = di[0]
    for m in range(1, n):
        w = lo[m]/dp[m - 1]
        cp[m] = w
        dp[m] = di[m] - w*up[m - 1]

    T = [0.0]*(N + 1)
    out = {}
    want = set(int(round(t/dt)) for t in out_times)
    nsteps = int(round(t_end/dt))
    # surface value at t = 0: the initial state (temperature), or the
    # first row's flux (held from 0+)
    theta_old = 0.0 if bc == 'temperature' else history_value(rows, 0.0)
    for s in range(1, nsteps + 1):
        t_new = s*dt
        theta_new = history_value(rows, t_new)
        rhs = [0.0]*n
        for m in range(n):
            i = m + first
            kl = K[i - 1] if i > 0 else 0.0
            kr = K[i]
            Tl = T[i - 1] if i > 0 else 0.0
            Tr = T[i + 1]
            rhs[m] = (C[i]/dt - 0.5*(kl + kr))*T[i] + 0.5*(kl*Tl + kr*Tr)
        if bc == 'temperature':
            # the old surface value is in the explicit half above
            rhs[0] += 0.5*K[0]*theta_new
        else:
            rhs[0] += 0.5*(theta_old + theta_new)
        # solve
        y = rhs
        for m in range(1, n):
            y[m] -= cp[m]*y[m - 1]
        y[n - 1] /= dp[n - 1]
        for m in range(n - 2, -1, -1):
            y[m] = (y[m] - up[m]*y[m + 1])/dp[m]
        for m in range(n):
            T[m + first] = y[m]
        if bc == 'temperature':
            T[0] = theta_new
        theta_old = theta_new
        if s in want:
            out[s] = [T[i] for i in idx]
    return {round(s*dt, 9): v for s, v in out.items()}, len(z)
