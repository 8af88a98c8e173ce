"""Summary of a case written by bin/hearthCase, after its Allrun:

    python3 hearthCaseSummary.py CASE      (prints the table)

- each thermocouple's peak [C] and the time of the peak [h]
  (postProcessing/thermocouples/0/sensors.csv);
- the depth of each isotherm of TMax under the centre of the fire and
  under its rim (90 % of its radius), measured from the fire's surface
  (hearthAlteration's summary.csv at the last time, plus lineStart of
  hearthCaseInfo where the lines start under the surface: scannedPit);
- the energy balance of the whole hearth: the solver's balance of the mesh
  (added up over the parts of a resumed run: hearthCaseRestart.runTotals)
  times the factor from the mesh to the whole hearth (pi/tan(angle/2) for
  an axisymmetric wedge, 4 for a quarter pit, 1 otherwise:
  system/hearthCaseInfo);
- the water evaporated, whole hearth: ahcFoam, the liquid water of the
  soil at the start of the run minus at the end (its energy balances: each
  part's own start and end, added up); pendularFoam, the water that left
  through the patches (its water balance);
- where the files are.
Also writes CASE/summary.csv (name,value,unit) for tests.
"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import hearthTutorial as ht      # noqa: E402
import hearthCaseRestart as hr   # noqa: E402


def main(case):
    inf = hr.info(case)
    solver, factor = inf['solver'], float(inf['factor'])
    figures = []
    out = []
    w = out.append
    w('Summary of %s (%s, whole hearth = mesh x %.6g)'
      % (os.path.abspath(case), solver, factor))
    w('')
    s = ht.sensors_of(case)
    t = s.pop('time_s')
    w('%-20s %12s %12s' % ('sensor', 'peak [C]', 'at [h]'))
    for name, T in s.items():
        p, tp = ht.peak(t, T)
        w('%-20s %12.1f %12.2f' % (name, p, tp/3600))
        figures += [('peak_' + name, p, 'C'), ('peakTime_' + name, tp/3600, 'h')]
    w('')
    rows = ht.alteration_summary(case)
    below = float(inf.get('lineStart', 0))    # 0 m: an isotherm not found
    w('%-20s %12s %12s' % ('isotherm of TMax', 'centre [cm]', 'rim [cm]'))
    for r in rows:
        c, e = (float(r[k]) + below if float(r[k]) > 0 else 0.0
                for k in ('depth_centre_m', 'depth_rim_m'))
        w('%-20s %12.2f %12.2f' % ('%g C' % float(r['threshold_C']),
                                   100*c, 100*e))
        figures += [('depthCentre_%gC' % float(r['threshold_C']), 100*c, 'cm'),
                    ('depthRim_%gC' % float(r['threshold_C']), 100*e, 'cm')]
    w('(depths below the fire surface: the basin or pit floor, under the '
      'rim at %s m from the axis)' % inf['rim'])
    w('')
    # the balances of a run resumed (hearthCase -resume) add up over its
    # parts (log.<solver>.<time>, then log.<solver>): each part's flows,
    # stored change and water from its own start
    tot = hr.runTotals(case, solver)
    parts = tot['parts']
    heatIn, stored, imb, water = (tot[k]*factor for k in
                                  ('heatIn', 'stored', 'imbalance', 'water'))
    time = tot['time']
    w('Energy balance of the whole hearth at t = %.4g h:' % (time/3600))
    w('    heat in through the patches  %14.6g MJ' % (heatIn/1e6))
    w('    stored in the soil           %14.6g MJ' % (stored/1e6))
    w('    imbalance                    %14.3g J (relative %.2g)'
      % (imb, abs(imb)/max(abs(stored), 1e-300)))
    w('Water evaporated (whole hearth)  %14.6g kg' % water)
    figures += [('heatIn', heatIn/1e6, 'MJ'), ('stored', stored/1e6, 'MJ'),
                ('water', water, 'kg')]
    w('')
    w('Files in %s:' % os.path.abspath(case))
    w('    sensors.png, postProcessing/thermocouples/0/sensors.csv')
    w('    TMaxSection.png, TMaxSection.csv')
    w('    postProcessing/hearthAlteration/<time>/summary.csv')
    w('    log.%s (balances%s), summary.txt, summary.csv' % (
        solver, '' if len(parts) == 1 else
        '; resumed: the parts up to %s s in log.%s.<time>'
        % (', '.join('%g' % b['time'] for b in parts[:-1]), solver)))
    print('\n'.join(out))
    with open(os.path.join(case, 'summary.csv'), 'w') as f:
        f.write('name,value,unit\n')
        for n, v, u in figures:
            f.write('%s,%.10g,%s\n' % (n, v, u))


if __name__ == '__main__':
    try:
        main(sys.argv[1] if len(sys.argv) > 1 else '.')
    except hr.RestartError as e:
        sys.exit('hearthCaseSummary: %s' % e)
