"""The residual of ahcFoam's discrete energy equation, recomputed from the
written fields of each step (testAhcResidual), relative to the largest rate
of storage of the step.

Tolerance 1e-6: the case asks the solver for a last change of T below
1e-9 K (and a normalised linear residual below 1e-11). A change of 1e-9 K
in a cell inside the evaporation band (apparent capacity theta_0 rho_l L/
(sqrt(2 pi) dT) = 7e7 J/(m3 K)) moves its storage rate by 1e-9 x 7e7 / 5 s
= 0.014 W/m3, against largest rates of ~3e6 W/m3: 5e-9 relative; measured
4.8e-8 at worst (the convergence test extrapolates the last change with
the observed rate). A conductivity lagged a step leaves (k_e(T^n) -
k_e(T^{n+1})) grad T at the drying front: measured 0.06 to 28 relative
in the steps where a cell dries; the test requires the case to show at
least 1e-2 (1e4 times the tolerance) somewhere, so that it can tell the
two apart."""
import hearthcheck as hc

c = hc.Check('ahcImplicitResidual')
steps = []
with open('log.testAhcResidual') as f:
    for line in f:
        w = line.split()
        if w and w[0] == 'step':
            steps.append((float(w[1]), float(w[3]), float(w[5])))
c.true('every step checked (120 pairs of written steps)', len(steps) == 120,
       '%d' % len(steps))
worst = max(steps, key=lambda s: s[1])
c.le('largest residual, new time level (t = %g s)' % worst[0], worst[1], 1e-6)
lag = max(steps, key=lambda s: s[2])
c.true('a lagged conductivity would leave > 1e-2 (t = %g s)' % lag[0],
       lag[2] > 1e-2, '%.3g' % lag[2])
c.done()
