"""Write the quadrupoleTemperature dictionaries of the test into
<dir>/system/<name>Dict (and the 30-day flux history <dir>/flux.csv); the
results go to <dir>/postProcessing/<name>.csv. Usage:

    python3 makeQuadrupoleDicts.py DIR

Part (b), references of the finite-volume runs (the soil in 200 and 400
uniform-gamma layers, quadratic spacing, exact k and c at every face; the
difference of the two estimates the error of the finer):
    bTemperature200/400   imposed surface temperature, depths, hourly
    bFlux200/400          imposed surface flux, surface and depths, hourly
    bHeat                 imposed temperature, 1600 depths to 2 m (heat
                          content by quadrature)
Part (c), the surface temperature under 30 days of a diurnal surface flux
(hourly rows; the paper's meteorological forcing had 20 min ones), hourly:
    cRef                  200 uniform-gamma layers, quadratic (the reference)
    cPaperRef             50 uniform-gamma layers, regular (the paper's)
    g_<fit>_<spacing>_<n> n uniform-gamma layers (fit faces, eq12, CR)
    k_<rule>_<spacing>_<n> n classical uniform layers (rule mean; mid for
                          the paper's 15 regular and 5 quadratic and 2)
"""
import math
import os
import sys

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gradedSoil as gs  # noqa: E402

DEPTHS = [0.01, 0.02, 0.05, 0.1, 0.2, 0.5]
HOURLY = 'endTime 86400; writeInterval 3600;'

# Part (c)
DAYS = 30
STEP = 3600                 # s: rows of the history and output interval
GAMMA_N = [1, 2, 3, 5]
CLASSICAL_N = [1, 2, 3, 5, 10, 15, 20]
MID = [('regular', 2), ('regular', 15), ('quadratic', 2), ('quadratic', 5)]


def surface_flux(t):
    """A synthetic ground heat flux [W/m2]: the sun's half-sine by day
    (peak 150 W/m2 under a clear sky), a weather cycle of 7.3 days
    modulating it between 10 % and 100 %, a constant loss of 26 W/m2
    (about zero mean over the 30 days)."""
    d = t/86400.0
    sun = max(0.0, math.sin(2.0*math.pi*(d - 0.25)))
    sky = 0.55 + 0.45*math.cos(2.0*math.pi*d/7.3)
    return 150.0*sky*sun - 26.0


def heat_depths():
    """Depths for the heat content: 0.5 mm to 0.4 m, 2 mm to 2 m."""
    return ([round(0.0005*i, 10) for i in range(1, 801)]
            + [round(0.4 + 0.002*i, 10) for i in range(1, 801)])


def cases():
    """name -> (layers, surface body, depths, output, initial T)"""
    out = {}
    T = 'condition temperature;\n    table %s;' \
        % gs.history_text(gs.TEMPERATURE_HISTORY)
    F = 'condition flux;\n    table %s;' % gs.history_text(gs.FLUX_HISTORY)
    for n in (200, 400):
        L = gs.gamma_layers(gs.faces(n, 'quadratic'))
        out['bTemperature%d' % n] = (L, T, DEPTHS, HOURLY, gs.T_INITIAL)
        out['bFlux%d' % n] = (L, F, DEPTHS, HOURLY, gs.T_INITIAL)
    out['bHeat'] = (gs.gamma_layers(gs.faces(400, 'quadratic')), T,
                    heat_depths(), HOURLY, gs.T_INITIAL)

    C = 'condition flux;\n    file "flux.csv";'
    every = 'endTime %d; writeInterval %d;' % (DAYS*86400, STEP)
    out['cRef'] = (gs.gamma_layers(gs.faces(200, 'quadratic')), C, [],
                   every, 0.0)
    out['cPaperRef'] = (gs.gamma_layers(gs.faces(50, 'regular')), C, [],
                        every, 0.0)
    for sp in ('regular', 'quadratic'):
        for n in GAMMA_N:
            if n == 1 and sp == 'quadratic':
                continue            # the same single layer
            for fit in ('faces', 'eq12', 'CR'):
                out['g_%s_%s_%d' % (fit, sp, n)] = \
                    (gs.gamma_layers(gs.faces(n, sp), fit), C, [], every, 0.0)
        for n in CLASSICAL_N:
            if n == 1 and sp == 'quadratic':
                continue
            for rule in ('mean', 'mid'):
                if rule == 'mid' and (sp, n) not in MID:
                    continue
                out['k_%s_%s_%d' % (rule, sp, n)] = \
                    (gs.classical_layers(gs.faces(n, sp), rule), C, [], every,
                     0.0)
    return out


def main(d):
    os.makedirs(os.path.join(d, 'system'), exist_ok=True)
    with open(os.path.join(d, 'flux.csv'), 'w') as f:
        f.write('# time_s,flux_W_m2 (into the soil)\n')
        for i in range(DAYS*86400//STEP + 1):
            f.write('%d,%.12g\n' % (i*STEP, surface_flux(i*STEP)))
    for name, (L, surf, depths, output, T0) in sorted(cases().items()):
        with open(os.path.join(d, 'system', name + 'Dict'), 'w') as f:
            f.write(gs.quadrupole_dict(L, surf, depths, output,
                                       'postProcessing/%s.csv' % name, T0))


if __name__ == '__main__':
    main(sys.argv[1])
