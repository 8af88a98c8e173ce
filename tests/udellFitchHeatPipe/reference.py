#!/usr/bin/env python3
"""Udell & Fitch's steady heat pipe (tests/udellFitchReference/heatPipe.py,
the four ODEs of Huang, Kolditz & Shao 2015) with the closures of this
test's pendularFoam case instead of the reference's property correlations,
so that the two solve the same problem:

  rho_l 958.4 kg/m3, mu_l 2.938e-4 Pa s, mu_g 1.2e-5 Pa s (constant: the
  pendular medium's gas viscosity; the reference mixes air and steam),
  sigma 0.0588 N/m (constant: the 'linear' law with b = 0; with sigma(T) the
  ODEs' dp_c/dx would miss a dT/dx term), conductivity the geometric mean
  k_s^(1 - phi) (S k_l + (1 - S) k_g)^phi (conductivityModel geometric of
  the pendular medium, k_s 2.8, k_l 0.68, k_g 0.0256 W/(m K); the
  reference: Somerton's), latent heat L(T) = 2.2564e6 + (1890 - 4200)
  (T - 373.15) J/kg with the IAPWS-97 saturation pressure (thermo 'iapws'
  of heatPipe.py; the solver: Wagner-Pruss, within 0.1 %), effective
  vapour diffusivity tau D_wa = 1e-5 m2/s (constant, as the solver's; the
  reference's Millington-Quirk D_pm makes its front independent of it, a
  constant one does not: 2.1157 m at 3e-6, 1.9890 m at 2e-5 m2/s, which
  run checks the solver against), M_w 0.018016, M_a 0.02897 kg/mol,
  R 8.3144621.

Prints the front x_f (S_e -> 0, S = S_wr), T there, the dry-zone
conductivity and the hot-end temperature T_h = T_f + q (L - x_f)/k_dry
that carries q = 100 W/m2 through the dry zone of the 2.4 m column (the
solver's hot end is at fixed T: pendularFoam's Newton residual conducts
through a patch only where T is fixed), and writes the profile
(x, S, T) to argv[1]; argv[2], if given, replaces tau D_wa = 1e-5 m2/s.
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                '..', 'udellFitchReference'))
import heatPipe as hp  # noqa: E402

L = 2.4
kS, kL, kG = 2.8, 0.68, 0.0256
phi = hp.phi

hp.R, hp.Mw, hp.Ma = 8.3144621, 0.018016, 0.02897
hp.sigma = 0.0588
hp.thermo = 'iapws'
hp.rhoW = lambda T: 958.4
hp.muW = lambda T: 2.938e-4
hp.muGas = lambda T, x: 1.2e-5
hp.lambdaPM = lambda Sw, T: kS**(1 - phi)*(Sw*kL + (1 - Sw)*kG)**phi
hp.latentHeat = lambda T: 2.2564e6 + (1890 - 4200)*(T - 373.15)
hp.Dpm = lambda Sw, T, pg: 1e-5


def main():
    # Optional second argument: the effective diffusivity tau D_wa [m2/s];
    # third: the diffusion law, 'mole' (Huang's closed form, default) or
    # 'mass' (pendularFoam's Fick in mass fraction: heatPipe.rhsBalance)
    if len(sys.argv) > 2 and sys.argv[2]:
        D = float(sys.argv[2])
        hp.Dpm = lambda Sw, T, pg: D
    if len(sys.argv) > 3:
        if sys.argv[3] not in ('mole', 'mass'):
            sys.exit('reference.py: diffusion law mole or mass, not %r'
                     % sys.argv[3])
        if sys.argv[3] == 'mass':
            hp.form, hp.diffusion = 'balance', 'mass'
    xf, err, h = hp.front()
    _, prof = hp.integrate(h, keep=True)
    Tf = prof[-1][4]
    kDry = hp.lambdaPM(0, Tf)
    Th = Tf - hp.q*(L - xf)/kDry
    print('REFERENCE front %.5f m (change at last halving %.1e m) '
          'T_front %.4f K k_dry %.5f W/(m K) T_hot %.4f K'
          % (xf, err, Tf, kDry, Th))
    if len(sys.argv) > 1 and sys.argv[1]:
        with open(sys.argv[1], 'w') as out:
            out.write('x,S,T\n')
            for (xp, Se, pg, u, T) in prof:
                out.write('%.8g,%.8g,%.8g\n'
                          % (xp, hp.Swr + Se*(1 - hp.Swr), T))
            out.write('%.8g,%.8g,%.8g\n' % (L, 0, Th))


if __name__ == '__main__':
    main()
