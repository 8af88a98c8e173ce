"""Isothermal pressure diffusion of dry air in dry sand: a 1 m column at
p0 + 10 Pa, open at the top (p0), closed at the bottom. Darcy flow with the
ideal gas gives phi dp/dt = (K_g/mu_g) div(p grad p), linearised
dp/dt = D_p d2p/dz2 with D_p = p0 K_g/(mu_g phi) = 0.0319 m2/s (K_g from the
Kozeny-Carman law at alpha_l = 0: 0.998e-12 m2), whose solution is
    p - p0 = dp (4/pi) sum_n sin(k_n z)/(2n+1) exp(-k_n^2 D_p t),
    k_n = (2n+1) pi/(2H), z the depth.
Errors: linearisation dp/p0 = 1e-4; 1 cm cells (second order), backward
Euler steps of 5 ms against the slowest time scale 4H^2/(pi^2 D_p) = 12.7 s.
Measured: 0.08 % of dp at 1 s, 0.01 % at 5 s; the test allows 0.2 %."""
import math
import hearthcheck as hc

c = hc.Check('pendularPressureDiffusion')
N, H, p0, dp = 100, 1.0, 101325.0, 10.0
phi, Ckc, mu = 0.26, 3.11e-11, 1.22e-5
Kg = Ckc*phi**3/(1 - phi)**2
Dp = p0*Kg/(mu*phi)


def exact(z, t):
    s = 0
    for n in range(400):
        k = (2*n + 1)*math.pi/(2*H)
        s += math.sin(k*z)/(2*n + 1)*math.exp(-k*k*Dp*t)
    return p0 + dp*4/math.pi*s


for t in (1, 2, 5):
    p = hc.read_internal_field('%d/p' % t)
    err = max(abs(p[i] - exact(H - (i + 0.5)*H/N, t)) for i in range(N))
    c.le('max |p - exact|/dp at t = %d s' % t, err/dp, 2e-3)

bal = hc.read_energy_balances('log.pendularFoam')
c.le('air imbalance (relative), worst write',
     max(abs(b[2]) for b in bal[1::3]), 1e-8)
c.done()
