#!/usr/bin/env python3
"""pendularWaterTable: pendularFoam with a fixedPressure liquid patch
(liquidFlow's water table, p_l,f = p_0 - rho_l |g| (z_f - z_wt)) under an
isothermal 1-m column of an exponential soil (S_e = exp(-p_c/p_c0), p_c0 =
4905 Pa: a = rho_l g/p_c0 = 2 1/m; k_rl = S; K = 1e-12 m2; S_wr = S_gr = 0,
so S = S_e), the gas closed (its pressure p_g read from the results).

(a) hydrostatic: the top closed to the liquid, the water table 1.5 m below
    the bottom face; from alpha_l = 0.06 the column drains to equilibrium,
    where every face's potential p_l - rho_l g.x is that of the water
    table. Two-point finite volumes are exact for it (the discrete fluxes
    all vanish at the exact cell-centre pressures, the boundary face's
    included), so the cell values equal the closed form
        S(z_c) = exp(-(p_g,c - p_l(z_c))/p_c0),
        p_l(z) = p_0 - rho_l g (z - z_wt)
    to Newton's tolerance (pTol 1e-6 Pa: 1e-10 m of head; p written to
    10 digits, 1e-5 Pa: 1e-9 m; 1e-8 m asked; the slowest
    mode, D = K p_c0/(mu phi) = 1.2e-5 m2/s, decays as exp(-pi^2 D t/(4
    L^2)) at least; the head at 1e6, 1.5e6 and 2e6 s the same to 1e-16 m,
    measured with air's vapour diffusivity). The vapour diffuses 1e6 times slower than in air: the
    menisci's Kelvin law (the vapour) is not the liquid's exponential p_c,
    so with air's 2e-5 m2/s vapour diffuses along the column at the
    liquid's equilibrium, held by a liquid counter-flow (1.3e-7 m of head
    at the top, measured). The water that left through the bottom (liquid
    only: the gas is closed) = (rho_l - rho_v) phi A dz sum(S0 - S(z_c)):
    the liquid lost less the vapour filling the pores it left (rho_v =
    p_wsat(20 C) M_w/(R T), 1.7e-5 of rho_l; its Kelvin factor and the
    vapour's redistribution below 1e-7 of the outflow).
Heights z are from the bottom face (at y = 1 m).
(b) Gardner's (1958) steady evaporation (E = 9.81e-8 m/s, the top's flux
    9.81e-5 kg/m2/s) with the water table ln(10)/2 m below the bottom face
    (S_f = 0.1 at p_g = p_0): the closed form from the face's saturation
    S_b = exp(-(p_g - p_l,f)/p_c0) (hearthcheck.gardner_head), on 50, 100,
    200 cells: first order (k_rl upwind).
(c) the balances pendularFoam reports within 1e-10;
(d) 2 ranks = serial, the hydrostatic and the 100-cell Gardner columns.
(e) infiltration: a fixedFlux inflow q = 5.0228e-6 kg/m2/s through the
    top, the bottom impermeable (the water table replaced), k_rl = S^3,
    p_c0 = 490.5 Pa (a sharp wetting front: D(S) = K k_rl p_c'/mu_l ~ S^2),
    from alpha_l = 0.01 on 50 cells to t = 5e6 s (the front near 0.9 m
    depth). The water gained, the stored change pendularFoam prints (the
    cells' contents now less at the start), equals q A t (conservation:
    1e-10 relative, the balances' class); behind the front the flux is
    gravity's alone (unit gradient, no capillary gradient), K k_rl(S)
    rho_l^2 g/mu_l = q: S_q = (q mu_l/(K rho_l^2 g))^(1/3) = 0.0800004 at
    mid-column (z = 0.5 m, between the two middle cell centres) within
    1e-4 relative (2.8e-5 measured; the front's tail: 4.0e-7 on 100 cells,
    2.4e-6 on 200, where the Newton tolerances take over; the 100- and
    200-cell runs cost 25286 and 109001 iterations, not in the suite).

(f) ponding, the saturated zone (ponding/: 5 cm, 10 cells, K = 1e-11 m2,
    mu_l = 1e-3 Pa s, 20 C): a saturated column (liquid-only cells) under
    h = 3 cm of ponded water (the top's p_l,f = p_atm + rho_l g h, above
    the face's p_g), drained freely at the bottom (p_l,f = p_atm). Steady,
    the potential p_l + rho_l g y is linear between the faces, which
    two-point finite volumes reproduce exactly: the flow per area is
        q = rho_l K rho_l g (h + L)/(mu_l L) = 0.15696 kg/m2/s,
    its transient (the storage c_s = 4.5e-10 1/Pa: the column's pressure
    diffusivity K/(mu_l phi c_s) = 85 m2/s; the dissolved air front, the
    pond's Henry air pushed in, through the column in L phi/(q/rho_l) =
    83 s) over by 300 s: the top's and the bottom's flows over 300-400 s
    within 1e-6 of q A (100 s) (the Newton tolerance pTol 1e-4 Pa of
    the 785 Pa potential drop is 1.3e-7);
(g) ponded filling: the same column from alpha_l = 0.5 (two-phase, gas
    open at the top), K = 1e-12 m2, the bottom impermeable: the water
    gained between the first write (25 s) and each later one, sum (W -
    W_25) V from the written W, plus the change of the BDF2 term of the
    log's water balance (0 with backward Euler, the saturated zone's
    default; with BDF2 given the W fields alone were 7.1 % off, 4.7e-14
    with the term, measured 2026-12-04), equals the inflow through the
    top the log prints over that time (1e-10 of the water gained, the
    balances' class); a write holds both phase states (the column fills from the
    top, the cells switch to liquid-only); at 250 s every cell liquid-only
    and p_l hydrostatic under the pond, p_atm + rho_l g (h - y_c) (y_c <
    0 the cell centre; two-point finite volumes exact), within 1e-3 Pa (10
    pTol; written to 10 digits, 1e-4 Pa).

check.py gardnerInitial N PATH  the exact Gardner S (S_b = 0.1) at N cells
check.py check SCRATCH          the comparisons
"""
import math
import os
import re
import sys

import hearthcheck as hc
from hearthTutorial import pendular_balances  # noqa: E402

PC0 = 4905.0
A = 2.0                     # 1/m: rho_l g/p_c0
RHO, G = 1000.0, 9.81
PHI = 0.4
AREA = 1e-4                 # m2: the column's cross-section
H = 1.0
P0 = 101325.0
S0 = 0.06                   # (a) initial alpha_l
Y0 = 1.0                    # the bottom face's height (y) [m]
ZWT_A = -1.5                # (a) the water table, from the bottom face
ZWT_B = -math.log(10)/A     # (b): S_f = 0.1 at p_g = p_0
KS = 1e-12*RHO*G/1e-3       # m/s
E = 9.81e-5/RHO             # m/s


def read_field(case, name):
    """The internal field name at the last written time of case (a list;
    a uniform field as one float)."""
    times = [d for d in os.listdir(case)
             if re.match(r'^[0-9.e+]+$', d) and float(d) > 0]
    last = max(times, key=float)
    values = hc.read_internal_field(os.path.join(case, last, name))
    return values[0] if len(values) == 1 else values


def cells(case, n):
    alpha = read_field(case, 'alphaL')
    p = read_field(case, 'p')
    if not isinstance(p, list):
        p = [p]*n
    return alpha, p


def hydrostatic_s(pg, z, zwt):
    return math.exp(-(pg - (P0 - RHO*G*(z - zwt)))/PC0)


def last_outflow(log, patch='bottom'):
    """The water that left through patch since the start (the last
    water balance of the log; 0 if it names no flow through patch)."""
    balances = pendular_balances(log)
    return balances[-1]['water'].get('out_' + patch, 0.0) if balances \
        else None


def last_water_stored_change(log):
    """The stored change of the last water balance of the log [kg]."""
    balances = pendular_balances(log)
    return balances[-1]['water'].get('stored') if balances else None


def water_flows(log):
    """{t: {patch: water out through it since the start [kg]}} of every
    water balance of the log."""
    return {b['time']: {k[4:]: v for k, v in b['water'].items()
                        if k.startswith('out_')}
            for b in pendular_balances(log)}


def field_at(case, time, name):
    """The internal field name of case at a written time (list; a uniform
    field as PONDED_N values)."""
    dirs = [d for d in os.listdir(case)
            if re.match(r'^[0-9.e+]+$', d) and abs(float(d) - time) < 1e-9]
    values = hc.read_internal_field(os.path.join(case, dirs[0], name))
    return values*PONDED_N if len(values) == 1 else values


# (f), (g): the ponded column
PONDED_N, PONDED_L, PONDED_H = 10, 0.05, 0.03
PONDED_AREA = 1e-4
P_POND = P0 + RHO*G*PONDED_H


def check_ponding(c, scratch):
    """(f) and (g); returns the cases (for the balances)."""
    # (f) the steady flow through the saturated column
    case = os.path.join(scratch, 'pondedFlow')
    flows = water_flows(os.path.join(case, 'log.pendularFoam'))
    q = RHO*1e-11*RHO*G*(PONDED_H + PONDED_L)/(1e-3*PONDED_L)
    exact = q*PONDED_AREA*100
    top = -(flows[400]['top'] - flows[300]['top'])
    bottom = flows[400]['bottom'] - flows[300]['bottom']
    print('pondedFlow: 300-400 s in through top %.12g kg, out through bottom'
          ' %.12g kg, Darcy q A dt %.12g kg' % (top, bottom, exact))
    c.le('pondedFlow: |inflow (top) - Darcy| / Darcy, 300-400 s',
         abs(top - exact)/exact, 1e-6)
    c.le('pondedFlow: |outflow (bottom) - Darcy| / Darcy, 300-400 s',
         abs(bottom - exact)/exact, 1e-6)
    gas = field_at(case, 400, 'gasPresent')
    c.true('pondedFlow: every cell liquid-only at 400 s', max(gas) == 0,
           '%d of %d' % (sum(g == 0 for g in gas), PONDED_N))

    # (g) the ponded filling
    fill = os.path.join(scratch, 'pondedFill')
    flows = water_flows(os.path.join(fill, 'log.pendularFoam'))
    times = sorted(flows)
    volume = PONDED_AREA*PONDED_L/PONDED_N
    w0 = field_at(fill, times[0], 'W')
    # the stored change of the time scheme: with BDF2 the W fields' change
    # plus the change of its term C^N (variableStepBdf2; 0 with backward
    # Euler)
    bdf2 = {b['time']: b['water'].get('bdf2', 0.0)
            for b in pendular_balances(os.path.join(fill, 'log.pendularFoam'))}
    gained = [sum(w - v for w, v in zip(field_at(fill, t, 'W'), w0))*volume
              + bdf2[t] - bdf2[times[0]]
              for t in times]
    inflow = [-(flows[t]['top'] - flows[times[0]]['top']) for t in times]
    err = max(abs(g - i) for g, i in zip(gained, inflow))/max(gained)
    print('pondedFill: water gained %.6g kg from %g to %g s (inflow %.6g)'
          % (gained[-1], times[0], times[-1], inflow[-1]))
    c.true('pondedFill: writes at 25 to 250 s', len(times) == 10,
           '%s' % times)
    c.le('pondedFill: max |water gained (W fields) - inflow (log)| /'
         ' water gained', err, 1e-10)
    liquidOnly = [sum(g == 0 for g in field_at(fill, t, 'gasPresent'))
                  for t in times]
    print('pondedFill: liquid-only cells at each write %s' % liquidOnly)
    c.true('pondedFill: a write with both phase states',
           any(0 < n < PONDED_N for n in liquidOnly), '%s' % liquidOnly)
    c.true('pondedFill: every cell liquid-only at 250 s',
           liquidOnly[-1] == PONDED_N)
    pl = field_at(fill, times[-1], 'pl')
    dz = PONDED_L/PONDED_N
    hydro = [P_POND - RHO*G*(-PONDED_L + (i + 0.5)*dz)
             for i in range(PONDED_N)]
    c.le('pondedFill: max |p_l - hydrostatic under the pond| at 250 s [Pa]',
         max(abs(a - b) for a, b in zip(pl, hydro)), 1e-3)
    return [case, fill]


def gardner_initial(n, path):
    s = [math.exp(A*hc.gardner_head((i + 0.5)*H/n, A, E/KS, 0.1))
         for i in range(n)]
    with open(path) as f:
        text = f.read()
    field = 'nonuniform List<scalar> %d\n(\n%s\n)' % (
        n, '\n'.join('%.12g' % v for v in s))
    text = re.sub(r'internalField\s+uniform\s+\S+;',
                  'internalField   ' + field + ';', text)
    with open(path, 'w') as f:
        f.write(text)


def gardner_error(case, n):
    """max |h - h_Gardner| [m] at the cell centres, Gardner from the
    face's S_b at the bottom cell's p_g (the face's: the gas closed)."""
    alpha, p = cells(case, n)
    pl_face = P0 - RHO*G*(0 - ZWT_B)
    sb = math.exp(-(p[0] - pl_face)/PC0)
    return max(abs(math.log(alpha[i])/A
                   - hc.gardner_head((i + 0.5)*H/n, A, E/KS, sb))
               for i in range(n)), sb


def at_least(c, what, value, bound):
    return c.true(what, value >= bound, '%.4g >= %.4g' % (value, bound))


def check(scratch):
    c = hc.Check('pendularWaterTable')
    logs = []

    # (a) hydrostatic equilibrium
    n = 50
    case = os.path.join(scratch, 'hydrostatic')
    alpha, p = cells(case, n)
    dz = H/n
    exact = [hydrostatic_s(p[i], (i + 0.5)*dz, ZWT_A) for i in range(n)]
    print('hydrostatic: alpha_l %.6g (bottom) to %.6g (top), p_g %.3f Pa'
          % (alpha[0], alpha[-1], p[0]))
    # the head's error ln(S/S_exact)/a [m]: the written p's 1e-5 Pa is
    # 1e-9 m of head, Newton's pTol 1e-6 Pa 1e-10 m (3.1e-10 m measured;
    # WTol 1e-11 of the largest water content 4e-11 m at the top cell)
    err = max(abs(math.log(a/e))/A for a, e in zip(alpha, exact))
    c.le('hydrostatic: max |h - h_exact| at the cell centres [m]', err, 1e-8)
    c.true('hydrostatic: every cell below alphaLMax 0.1',
           max(alpha) < 0.1, 'max alpha_l %.4g' % max(alpha))
    rhov = 2339.2*0.018/(8.31*293.15)   # IAPWS p_wsat(20 C), the case's M_w, R
    drained = (RHO - rhov)*PHI*AREA*dz*sum(S0 - e for e in exact)
    # the water lost: the flow out plus, with BDF2 (the default here), its
    # term C^N of the balance (the BDF2 flows sum_n dt_n F^{n+1} differ
    # from the change of the water by C^N, variableStepBdf2: 12 % of it
    # here, measured 2026-12-04)
    log = os.path.join(case, 'log.pendularFoam')
    out = last_outflow(log) + pendular_balances(log)[-1]['water'].get('bdf2', 0.0)
    print('hydrostatic: out through bottom (plus the BDF2 term) %.10g kg,'
          ' (rho_l - rho_v) phi A sum(S0 - S) dz %.10g kg' % (out, drained))
    c.le("hydrostatic: |out - (rho_l - rho_v) phi A sum(S0 - S) dz| / that",
         abs(out - drained)/drained, 1e-6)
    logs.append(case)

    # (a) again, the bottom open to the gas at a fixed T
    case = os.path.join(scratch, 'hydrostatic_open')
    alpha, p = cells(case, n)
    exact = [hydrostatic_s(p[i], (i + 0.5)*dz, ZWT_A) for i in range(n)]
    print('hydrostatic, gas open: alpha_l %.6g to %.6g, p_g %.3f Pa'
          % (alpha[0], alpha[-1], p[0]))
    c.le('hydrostatic, gas open: max |h - h_exact| [m]',
         max(abs(math.log(a/e))/A for a, e in zip(alpha, exact)), 1e-8)
    logs.append(case)

    # (b) Gardner from the water table
    err = {}
    for n in (50, 100, 200):
        case = os.path.join(scratch, 'gardner_%d' % n)
        err[n], sb = gardner_error(case, n)
        print('gardner N = %d: S_b = %.8f, max |h - h_Gardner| = %.6g m'
              % (n, sb, err[n]))
        logs.append(case)
    for n in (50, 100):
        order = math.log(err[n]/err[2*n])/math.log(2)
        at_least(c, 'gardner: observed order %d -> %d cells' % (n, 2*n),
                 order, 0.85)
    c.le('gardner: N = 200 error / first-order extrapolation of N = 100',
         err[200]/(err[100]/2), 1.2)
    # a plausible wrong answer: Gardner at 1.1 E is farther than twice the
    # 100-cell error (tests/pendularGardner's)
    n = 100
    wrong = max(abs(hc.gardner_head((i + 0.5)*H/n, A, 1.1*E/KS, 0.1)
                    - hc.gardner_head((i + 0.5)*H/n, A, E/KS, 0.1))
                for i in range(n))
    at_least(c, 'gardner: 1.1 E, max |dh| / N = 100 error',
             wrong/err[100], 2)

    # (e) infiltration at a constant flux
    case = os.path.join(scratch, 'infiltration')
    n, q, t = 50, 5.0228e-6, 5e6
    stored = last_water_stored_change(os.path.join(case, 'log.pendularFoam'))
    print('infiltration: stored change %.10g kg, q A t %.10g kg'
          % (stored, q*AREA*t))
    c.le('infiltration: |water gained - q A t| / q A t',
         abs(stored - q*AREA*t)/(q*AREA*t), 1e-10)
    alpha = read_field(case, 'alphaL')
    sq = (q*1e-3/(1e-12*RHO**2*G))**(1.0/3)
    mid = 0.5*(alpha[n//2 - 1] + alpha[n//2])
    print('infiltration: S(z = 0.5 m) %.8g, S_q %.8g; top cell %.8g'
          % (mid, sq, alpha[-1]))
    c.le('infiltration: |S(mid-column) - S_q| / S_q (gravity-drained)',
         abs(mid - sq)/sq, 1e-4)
    logs.append(case)

    # (f), (g) ponding
    logs += check_ponding(c, scratch)

    # (c) balances
    for case in logs + [os.path.join(scratch, 'hydrostatic_parallel'),
                        os.path.join(scratch, 'gardner_100_parallel')]:
        c.le('%s: largest relative imbalance (water, air, energy)'
             % os.path.basename(case),
             hc.worst_relative_imbalance(
                 os.path.join(case, 'log.pendularFoam')), 1e-10)

    # (d) 2 ranks = serial
    for name in ('hydrostatic', 'gardner_100'):
        ser = read_field(os.path.join(scratch, name), 'alphaL')
        par = read_field(os.path.join(scratch, name + '_parallel'), 'alphaL')
        c.le('%s: 2 ranks - serial, max |alpha_l| difference / max alpha_l'
             % name, max(abs(a - b) for a, b in zip(par, ser))/max(ser), 1e-9)
    c.done()


if __name__ == '__main__':
    if sys.argv[1] == 'gardnerInitial':
        gardner_initial(int(sys.argv[2]), sys.argv[3])
    else:
        check(sys.argv[2])
