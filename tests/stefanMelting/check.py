"""Stefan melting (Mansour 2015 ch. 3 data) against the Neumann solution.

Exact (corrected eq. 2.8): lambda = 0.292768, front at 9.039 cm at 50 h,
passing 5 cm at 15.30 h, T(5 cm, 30 h) = 5.519 C.

Three resolutions refine h, dT and the largest step together (h = 2, 1,
0.5 mm; dT = 0.5, 0.25, 0.125 K; 60, 30, 15 s). AHC smears the latent heat
over ~4 dT, so the error is first order in (h, dT, dt): the test checks the
finest level against tolerances of about twice its measured error, and that
the error falls monotonically with refinement."""
import math
import os
import hearthcheck as hc

c = hc.Check('stefanMelting')
ex = hc.NeumannStefan(L=338e3, T0=-10, Tw=20, Tf=0, kl=0.556, ks=2.22,
                      Cl=4200, Cs=2000, rho=1000)
c.true('exact lambda = 0.292768', abs(ex.lam - 0.292768) < 1e-6, '%.6f' % ex.lam)


def front_position(case):
    tdir = '180000'
    z = hc.read_internal_field(os.path.join(case, tdir, 'Cz'))
    T = hc.read_internal_field(os.path.join(case, tdir, 'T'))
    pts = sorted((-zz, TT - 273.15) for zz, TT in zip(z, T))
    for (d0, T0), (d1, T1) in zip(pts, pts[1:]):
        if T0 >= 0 > T1:
            return d0 + (d1 - d0)*T0/(T0 - T1)
    return float('nan')


rms, e30, efront, epass = [], [], [], []
for level in (1, 2, 3):
    case = 'level%d' % level
    _, times, cols = hc.read_probes(os.path.join(case, 'postProcessing/probes/0/T'))
    T5 = [v - 273.15 for v in cols[0]]
    err = [Ts - ex.T(0.05, t) for t, Ts in zip(times, T5)]
    rms.append(math.sqrt(sum((times[i+1] - times[i])*0.5*(err[i]**2 + err[i+1]**2)
                             for i in range(len(times) - 1))/times[-1]))
    i30 = min(range(len(times)), key=lambda k: abs(times[k] - 30*3600))
    e30.append(abs(T5[i30] - ex.T(0.05, times[i30])))
    # time at which 5 cm passes 0 C (liquid fraction 1/2)
    tpass = next(times[i] + (times[i+1] - times[i])*(0 - T5[i])/(T5[i+1] - T5[i])
                 for i in range(len(T5) - 1) if T5[i] < 0 <= T5[i+1])
    epass.append(abs(tpass - ex.time_front_at(0.05))/3600)
    efront.append(abs(front_position(case) - ex.front(180000)))
    print('  level %d: RMS error of T(5 cm, t) %.4f K, |T(5 cm, 30 h) err| %.4f K,'
          ' front at 50 h err %.3f mm, 5 cm passage err %.3f h'
          % (level, rms[-1], e30[-1], 1000*efront[-1], epass[-1]))

c.le('finest: RMS error of the 5 cm history [K]', rms[-1], 0.15)
c.le('finest: |T(5 cm, 30 h) - 5.519 C| [K]', e30[-1], 0.17)
c.le('finest: |front(50 h) - 9.039 cm| [mm]', 1000*efront[-1], 0.65)
c.le('finest: |t(front at 5 cm) - 15.30 h| [h]', epass[-1], 0.26)
c.true('RMS error falls at first order', rms[0] > 1.6*rms[1] > 2.56*rms[2],
       ' > '.join('%.4f' % r for r in rms))
c.true('front error falls with refinement', efront[0] > efront[2],
       ' , '.join('%.3f mm' % (1000*e) for e in efront))
c.done()
