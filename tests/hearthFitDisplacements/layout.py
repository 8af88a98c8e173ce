"""The sensors of hearthFitDisplacements (run) and the planted truth, an
implementation independent of hearthFit's (src/numerics/identifiability/
sensorDisplacements):
    python3 layout.py nominal.csv        the nominal sensors file
    python3 layout.py truth.csv planted.csv
                                         the truth's sensors, moved, and
                                         the planted values

Layout (Mansour 2015 §5.2.4.3, first experiment, her Fig. 5.16 not
printed): 10 sensors with r/R = 0.18 + 0.04 i and depth/R = 0.18 +
0.1978 i (i = 0..9), R = 5 cm: her ranges 0.18 <= r/R <= 0.54 and
0.18 <= z/R <= 1.96 spread evenly. The wedge's y = 0 plane holds them
(x = r; z up, the plate at z = 0).

Truth: each sensor moved by s_i along the normal n_i of the confocal
ellipse (foci at r = +-R on the plate) through its nominal position,
n_i = u1 + u2 (u the unit vectors from the foci; the normal bisects the
focal radii), with sum s_i n_i = 0 (5.20) and the shifts of her first
experiment (shift_r 1.4 mm, shift_z 9.8 mm deeper: -9.8 mm here, z
up). s = the orthogonal projection of v_i = cos(1.7 i + 0.3) on the
null space of the 2 x 10 matrix [n_i] (normal equations, 2 x 2), scaled
to her first experiment's spread of dz, 5.5 mm (std over the sensors)."""
import math
import sys

R = 0.05
N = 10
SHIFT_R, SHIFT_Z = 1.4e-3, -9.8e-3


def nominal():
    return [(R*(0.18 + 0.04*i), -R*(0.18 + 0.1978*i)) for i in range(N)]


def normal_angle(r, z):
    d1 = math.hypot(r - R, z)
    d2 = math.hypot(r + R, z)
    nr = (r - R)/d1 + (r + R)/d2
    nz = z/d1 + z/d2
    return math.atan2(nz, nr)


def planted():
    pos = nominal()
    phi = [normal_angle(r, z) for r, z in pos]
    a = [[math.cos(p) for p in phi], [math.sin(p) for p in phi]]
    v = [math.cos(1.7*i + 0.3) for i in range(N)]
    # s = v - A^T (A A^T)^-1 A v
    g = [[sum(a[j][i]*a[k][i] for i in range(N)) for k in range(2)]
         for j in range(2)]
    b = [sum(a[j][i]*v[i] for i in range(N)) for j in range(2)]
    det = g[0][0]*g[1][1] - g[0][1]*g[1][0]
    lam = [(g[1][1]*b[0] - g[0][1]*b[1])/det,
           (g[0][0]*b[1] - g[1][0]*b[0])/det]
    s = [v[i] - a[0][i]*lam[0] - a[1][i]*lam[1] for i in range(N)]
    # scaled to her spread of dz, 5.5 mm (population standard deviation)
    dz = [s[i]*math.sin(phi[i]) for i in range(N)]
    m = sum(dz)/N
    f = 5.5e-3/math.sqrt(sum((x - m)**2 for x in dz)/N)
    return pos, phi, [f*x for x in s]


def write_sensors(path, pos, comment):
    with open(path, 'w') as f:
        f.write(comment)
        f.write('name, x, y, z\n')
        for i, (r, z) in enumerate(pos):
            f.write('s%d, %.17g, 0, %.17g\n' % (i + 1, r, z))


if __name__ == '__main__':
    if len(sys.argv) == 2:
        write_sensors(sys.argv[1], nominal(),
                      '# name, x, y, z [m]: the nominal positions (the fit'
                      ' starts there),\n# written by layout.py\n')
        sys.exit(0)
    pos, phi, s = planted()
    moved = [(r + s[i]*math.cos(phi[i]) + SHIFT_R,
              z + s[i]*math.sin(phi[i]) + SHIFT_Z)
             for i, (r, z) in enumerate(pos)]
    if not all(z < -2e-3 and r > 0 for r, z in moved):
        sys.exit('layout.py: a moved sensor is not inside the soil')
    write_sensors(sys.argv[1], moved,
                  '# the truth: nominal + s_i n_i + shift (layout.py)\n')
    with open(sys.argv[2], 'w') as f:
        f.write('sensor,r0,z0,phi_deg,s,dr,dz\n')
        for i, (r, z) in enumerate(pos):
            f.write('s%d,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n'
                    % (i + 1, r, z, math.degrees(phi[i]), s[i],
                       s[i]*math.cos(phi[i]), s[i]*math.sin(phi[i])))
        f.write('shift_r,,,,%.17g,,\nshift_z,,,,%.17g,,\n'
                % (SHIFT_R, SHIFT_Z))
