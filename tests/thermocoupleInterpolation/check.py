"""Sensor readings in the first cell layer under a fire surface on a wedge
column (run) against T = T0 + (Tw - T0) erfc(z/(2 sqrt(alpha t))), at 1 h
and 2 h, for each interpolation scheme of the thermocouples function object.

cellLinear (src/functionObjects/thermocouples/interpolationCellLinear:
linear from the cell centre between the fire surface and the centres of
its cells, cellPoint elsewhere) is checked; the other schemes are printed, and the old default
cellPoint must exceed the tolerance at the shallow sensors (the test
discriminates: it fails with the old default). The default of the
thermocouples function object (no interpolationScheme) must read exactly
as cellLinear. A sensor on a face (d1, d2)
is read from the deeper cell (cellPoint's value for cellLinear). Measured
on 2026-12-01, largest |error| over both times:

    scheme                  cells  d0       d0.25    d0.5     d1      d2
    cellLinear              4 mm   1.2e-7   0.0131   0.0298   0.0298  0.0586
                            2 mm   6.8e-8   0.0035   0.0075   0.0113  0.0225
    cellPoint (old default) 4 mm   13.84    6.93     0.0687   0.0298  0.0586
                            2 mm   7.39     3.70     0.0283   0.0113  0.0225
    cellPointWallModified   = cellPoint (no wall patch)
    cell, cellPatchConstrained: the cell value (20.6 K off at d0, 4 mm)
    cellLinear with the Gauss gradient everywhere (its first version):
                            4 mm   1.2e-7   0.0131   0.0298   0.118   0.204
      (at a face the centred reconstruction errs by -h^2 T''/8, cellPoint
      by +h^2 T''/8, which here cancels part of the solver's error: the
      cells are 0.03, 0.09, 0.14, 0.20 K too cold in cells 1-4 at 1 h)
    cellLinear without the boundary normal gradient (Gauss only, planted
    bug tests/lib/mutations/cellLinearGaussOnly): d0 0.030 K at 4 mm

cellPoint's d0 error halves with h (first order: the point values of the
fire surface average the hot face with the cold wedge faces); cellLinear's
first-layer errors (d0.25, d0.5) fall by 3.7 and 4.0 (second order).

Tolerances: the errors are those of the cell values (backward Euler in
time and second order in space) plus the reconstruction's (h^2 T''/8 =
0.06 K at 8 mm depth, 4 mm cells, T'' = 2.9e4 K/m2 at 1 h). Allowed: 0.1 K
at 4 mm, 0.04 K at 2 mm (1.7 x the measured 0.059 and 0.023 K), the ratio
of the 4 mm to the 2 mm error of the first-layer sensors at least 3 (order
> 1.5; measured 3.7), and the depth-0 sensor within 0.01 K of the exact
solution (the face value; 1e-8 m below the surface the exact value is
1.3e-4 K below it). cellPoint must be off by more than 3 K at d0 on both
meshes (13.8 K and 7.4 K).

Symmetry: the 4 mm column with symmetry front/back patches (a cell next
to a symmetry plane) gives the same solution; the same tolerances apply.

Serial = parallel: the 2 mm case on 2 ranks split at 0.15 m depth (sensors
mid- and mid+ either side of the processor faces, read by cellPoint; the
fire-surface cells, one column here, have no processor face). The linear
solver (PCG/DIC, tolerance 1e-12) differs between serial and parallel, so
the fields agree only to that; the check is that cellLinear's
serial/parallel difference is no larger than 1e-6 K plus that of the cell
values (scheme cell), which the interpolation cannot reduce."""
import csv
import hearthcheck as hc

alpha = 0.756/(1500*1300)
T0, Tw = 293.15, 973.15
times = (3600.0, 7200.0)
schemes = ('cell', 'cellPoint', 'cellPatchConstrained',
           'cellPointWallModified', 'cellLinear')
shallow = ('d0', 'd0.25', 'd0.5', 'd1', 'd2')


def read(case, scheme):
    rows = list(csv.reader(open(
        '%s/postProcessing/tc_%s/0/sensors.csv' % (case, scheme))))
    names = [n.strip() for n in rows[0][1:]]
    return {float(r[0]): dict(zip(names, map(float, r[1:])))
            for r in rows[1:]}


def depth(name, h):
    return {'d0': 1e-8, 'd0.25': 0.25*h, 'd0.5': 0.5*h, 'd1': h,
            'd2': 2*h}[name]


c = hc.Check('thermocoupleInterpolation')
errors = {}
for nz in (75, 150):
    h = 0.3/nz
    for s in schemes:
        data = read('nz%d' % nz, s)
        err = {}
        for n in shallow:
            err[n] = max(abs(data[t][n] - hc.erfc_solution(
                depth(n, h), t, T0, Tw, alpha)) for t in times)
        errors[nz, s] = err
        print('  %3d cells %-22s' % (nz, s)
              + ' '.join('%s %.4f' % (n, err[n]) for n in shallow) + ' K')

for nz, tol in ((75, 0.1), (150, 0.04)):
    e = errors[nz, 'cellLinear']
    c.le('cellLinear, %g mm cells: max |T - erfc|, d0.25..d2 [K]'
         % (300.0/nz), max(e[n] for n in shallow[1:]), tol)
    c.le('cellLinear, %g mm cells: |T - erfc| at depth 0 [K]'
         % (300.0/nz), e['d0'], 0.01)
    e0 = errors[nz, 'cellPoint']['d0']
    c.true('cellPoint (old default), %g mm cells: |T - erfc| at depth 0 '
           '> 3 K (it fails)' % (300.0/nz), e0 > 3.0, '%.4g K' % e0)

first = ('d0.25', 'd0.5')
coarse = max(errors[75, 'cellLinear'][n] for n in first)
fine = max(errors[150, 'cellLinear'][n] for n in first)
c.true('cellLinear, first layer (d0.25, d0.5): error ratio 4 mm / 2 mm '
       '>= 3 (2nd order: 4)', coarse/fine >= 3.0, '%.3g' % (coarse/fine))

# symmetry instead of wedge front/back: the same 1-D solution and readings
for s in ('cellPoint', 'cellLinear'):
    w, y = read('nz75', s), read('nzsym75', s)
    dmax = max(abs(w[t][n] - y[t][n]) for t in times for n in shallow)
    print('  symmetry - wedge, %s: %.3g K' % (s, dmax))
ysym = read('nzsym75', 'cellLinear')
e = max(abs(ysym[t][n] - hc.erfc_solution(depth(n, 0.004), t, T0, Tw,
        alpha)) for t in times for n in shallow)
c.le('cellLinear, 4 mm cells, symmetry sides: max |T - erfc| [K]', e, 0.1)
ysym = read('nzsym75', 'cellPoint')
e = max(abs(ysym[t]['d0'] - hc.erfc_solution(1e-8, t, T0, Tw, alpha))
        for t in times)
c.true('cellPoint (old default), symmetry sides: |T - erfc| at depth 0 '
       '> 3 K (it fails)', e > 3.0, '%.4g K' % e)

# the default (no interpolationScheme keyword) is cellLinear
for nz in (75, 150):
    dflt, lin = read('nz%d' % nz, 'default'), read('nz%d' % nz, 'cellLinear')
    d = max(abs(dflt[t][n] - lin[t][n]) for t in times for n in lin[t])
    c.le('default scheme - cellLinear, %g mm cells [K]' % (300.0/nz), d, 0)

diff = {}
for s in ('cell', 'cellLinear'):
    ser, par = read('nz150', s), read('parallel', s)
    diff[s] = max(abs(ser[t][n] - par[t][n])
                  for t in times for n in ser[t])
c.le('cellLinear serial - parallel, all sensors (cell values differ by '
     '%.2e) [K]' % diff['cell'], diff['cellLinear'], diff['cell'] + 1e-6)
c.done()
