"""The solvers' start-up report (tests/solverStartupReport/run) against an
independent computation from the soil dictionaries.

    check.py setFields CASE ALPHAMAX  write the column's nonuniform 0/T and
                                      0/alphaL (10 cells)
    check.py check SCRATCH            compare the tables of the runs

The expected values are this file's own formulas (README "Start-up
report"), with the phase properties read from each case's
constant/soilProperties. Tolerance 1e-6 relative (1e-12 absolute for a
zero): the table prints 10 significant digits, the formulas are the same
arithmetic in another order: they agree to 3e-10 (measured). The check
discriminates down to the smallest term: leaving out the Kelvin factor of
the vapour density (exp(Vm sigma K/(R T)) = 1) moves W_0 of the driest
column cell by 3.9e-6 and fails."""
import math
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                '..', 'lib'))
from hearthcheck import Check  # noqa: E402

N_COLUMN = 10
RTOL = 1e-6


def columnFields(alphaMax):
    """T [K] and alpha_l of the column's cells: 288..297 K, alphaMax
    (0.1..1) over the cells"""
    T = [288.0 + i for i in range(N_COLUMN)]
    alpha = [alphaMax*(0.1 + 0.1*i) for i in range(N_COLUMN)]
    return T, alpha


def setFields(case, alphaMax):
    T, alpha = columnFields(alphaMax)
    for name, values in (('T', T), ('alphaL', alpha)):
        path = os.path.join(case, '0', name)
        txt = open(path).read()
        new = 'internalField   nonuniform List<scalar> %d(%s);' % (
            len(values), ' '.join(repr(v) for v in values))
        txt, n = re.subn(r'^internalField\s+uniform\s+\S+;', new, txt,
                         flags=re.M)
        if n != 1:
            sys.exit('setFields: no uniform internalField in %s' % path)
        open(path, 'w').write(txt)


# --------------------------------------------------------------------------
# The dictionary and the log

def soil(case):
    """The values of constant/soilProperties used here"""
    txt = open(os.path.join(case, 'constant', 'soilProperties')).read()
    txt = re.sub(r'//.*', '', txt)
    d = {}
    for phase in ('solid', 'liquid', 'gas'):
        m = re.search(r'\b%s\s*\{([^}]*)\}' % phase, txt)
        for key in ('rho', 'Cp', 'kappa'):
            d[phase + '_' + key] = float(
                re.search(r'\b%s\s+([^;\s]+);' % key, m.group(1)).group(1))

    def value(key):
        m = re.search(r'^\s*%s\s+([^;\s]+);' % key, txt, re.M)
        return float(m.group(1)) if m else None
    for key in ('porosity', 'waterContent', 'Tv', 'dT', 'latentHeat',
                'CpAir', 'Ma', 'CpVapour', 'Mw', 'R', 'latentHeatTemperature'):
        d[key] = value(key)
    m = re.search(r'alphaLMax\s+([^;\s]+);', txt)
    d['alphaLMax'] = float(m.group(1)) if m else None
    m = re.search(r'\bR0\s+([^;\s]+);', txt)
    d['R0'] = float(m.group(1)) if m else None
    m = re.search(r'^\s*conductivityModel\s+(\w+);', txt, re.M)
    d['law'] = m.group(1)
    m = re.search(r'constantCoeffs\s*\{\s*kappa\s+([^;\s]+);', txt)
    d['kConstant'] = float(m.group(1)) if m else None
    m = re.search(r'table\s*\(((?:\s*\([^)]*\))+)\s*\)', txt)
    d['table'] = [tuple(float(v) for v in row.split())
                  for row in re.findall(r'\(([^()]*)\)', m.group(1))] \
        if m else None
    return d


def report(log):
    """The rows {key: (min, max) or None} and the warnings of a log"""
    lines = open(log).read().splitlines()
    start = [i for i, l in enumerate(lines) if l.startswith('Start-up report of ')]
    end = [i for i, l in enumerate(lines) if l == 'start-up report ends']
    if len(start) != 1 or len(end) != 1:
        return None, None
    rows = {}
    for line in lines[start[0] + 2:end[0]]:
        f = line.split()
        rows[f[0]] = None if f[1] == '-' else (float(f[1]), float(f[2]))
    warnings = [l for l in lines
                if l.startswith('--> FOAM Warning : start-up: ')]
    return rows, warnings


def compare(check, name, rows, expected):
    """Every expected row (value or (min, max); None: no value) and no
    other row"""
    check.true('%s: the rows expected, no other' % name,
               sorted(rows) == sorted(expected),
               ' '.join(sorted(set(rows) ^ set(expected))))
    for key, want in expected.items():
        got = rows.get(key, 'missing')
        if want is None or got is None or got == 'missing':
            check.true('%s %s: no value' % (name, key),
                       want is None and got is None, str(got))
            continue
        if not isinstance(want, tuple):
            want = (want, want)
        err = max(abs(g - w)/max(abs(w), 1e-12/RTOL)
                  for g, w in zip(got, want))
        check.le('%s %s = %.10g..%.10g (expected %.10g..%.10g)'
                 % ((name, key) + got + want), err, RTOL)


# --------------------------------------------------------------------------
# ahcFoam (porousMedium): harmonic or tabulated law, energyConsistent

def ahcExpected(case, T0):
    s = soil(case)
    phi, theta = s['porosity'], s['waterContent']
    alpha = theta/phi
    rhoCpS = s['solid_rho']*s['solid_Cp']
    rhoCpL = s['liquid_rho']*s['liquid_Cp']
    rhoCpG = s['gas_rho']*s['gas_Cp']
    # the water as liquid, or as vapour like the rest of the pore gas
    wet = (1 - phi)*rhoCpS + (phi - theta)*rhoCpG + theta*rhoCpL
    dry = (1 - phi)*rhoCpS + phi*rhoCpG

    def k(a):
        if s['law'] == 'harmonic':
            kf = a*s['liquid_kappa'] + (1 - a)*s['gas_kappa']
            return 1/((1 - phi)/s['solid_kappa'] + phi/kf)
        rows = s['table']
        if not rows[0][0] <= a <= rows[-1][0]:
            return None
        for (a0, k0), (a1, k1) in zip(rows, rows[1:]):
            if a0 <= a <= a1:
                return k0 + (k1 - k0)*(a - a0)/(a1 - a0)
    kDry, kWet, kSat = k(0), k(alpha), k(1)
    Tv, dT = s['Tv'], s['dT']
    return {
        'T_0': T0, 'phi': phi, 'theta_0': theta,
        'w_0': theta*s['liquid_rho']/((1 - phi)*s['solid_rho']),
        'alpha_l_0': alpha, 'rhoCp_dry': dry, 'rhoCp_wet': wet,
        'k_e_dry': kDry, 'k_e_wet': kWet, 'k_e_sat': kSat,
        'a_dry': kDry/dry, 'a_wet': kWet/wet,
        'L_water': theta*s['liquid_rho']*s['latentHeat'],
        'T_v': Tv, 'T_evap_low': Tv - 2*dT, 'T_evap_high': Tv + 2*dT,
        'T_min': 0.0, 'T_0_min': 200.0}


# --------------------------------------------------------------------------
# pendularFoam (pendularMedium): the column's laws, written out here

def pSatWagnerPruss(T):
    """Wagner & Pruss (2002) saturation pressure [Pa] (IAPWS)"""
    Tc, pc = 647.096, 22.064e6
    a = [-7.85951783, 1.84408259, -11.7866497, 22.6807411, -15.9618719,
         1.80122502]
    t = 1 - T/Tc
    return pc*math.exp(Tc/T*(a[0]*t + a[1]*t**1.5 + a[2]*t**3 + a[3]*t**3.5
                             + a[4]*t**4 + a[5]*t**7.5))


def sigmaVargaftik(T):
    """Vargaftik et al. (1983) surface tension of water [N/m]"""
    t = (647.15 - T)/647.15
    return 0.2358*t**1.256*(1 - 0.625*t)


def pendularExpected(case, T, alpha, p):
    s = soil(case)
    phi = s['porosity']
    rhoS, CpS = s['solid_rho'], s['solid_Cp']
    rhoL, CpL = s['liquid_rho'], s['liquid_Cp']
    Mw, Ma, R = s['Mw'], s['Ma'], s['R']
    CpA, CpW, L, TL = s['CpAir'], s['CpVapour'], s['latentHeat'], \
        s['latentHeatTemperature']
    cols = {k: [] for k in ('theta_0', 'W_0', 'w_0', 'rhoCp_dry',
                            'rhoCp_wet', 'L_water')}
    for Tc, a in zip(T, alpha):
        # Kelvin-Laplace: asymptotic toroidal meniscus K = -5.06/(R0 sqrt(a))
        K = -5.06/(s['R0']*math.sqrt(a))
        pw = pSatWagnerPruss(Tc)*math.exp(
            Mw/rhoL*sigmaVargaftik(Tc)*K/(R*Tc))
        rhoW = Mw*pw/(R*Tc)
        rhoA = Ma*(p - pw)/(R*Tc)
        W = phi*(a*rhoL + (1 - a)*rhoW)
        cols['theta_0'].append(phi*a)
        cols['W_0'].append(W)
        cols['w_0'].append(W/((1 - phi)*rhoS))
        # the air at fixed p_a: rho_a Cp_a (T - T_L) has slope rho_a Cp_a T_L/T
        cols['rhoCp_wet'].append(
            (1 - phi)*rhoS*CpS + phi*a*rhoL*CpL
            + phi*(1 - a)*(rhoA*CpA*TL/Tc + rhoW*CpW))
        cols['rhoCp_dry'].append(
            (1 - phi)*rhoS*CpS + phi*Ma*p/(R*Tc)*CpA*TL/Tc)
        cols['L_water'].append(phi*a*rhoL*L)
    k = s['kConstant']
    e = {key: (min(v), max(v)) for key, v in cols.items()}
    e.update({
        'T_0': (min(T), max(T)), 'p_0': p, 'phi': phi,
        'alpha_l_0': (min(alpha), max(alpha)),
        'k_e_dry': k, 'k_e_wet': k, 'k_e_sat': k,
        'a_dry': (k/e['rhoCp_dry'][1], k/e['rhoCp_dry'][0]),
        'a_wet': (k/max(cols['rhoCp_wet']), k/min(cols['rhoCp_wet'])),
        'alpha_l_max': s['alphaLMax'],
        # the laws' common range: -25 C (supercooled) to the critical point
        'T_min': 248.15, 'T_d': 647.096, 'T_liquid_max': 647.096 - 10})
    return e


def checkAll(scratch):
    check = Check('solverStartupReport')
    logs = {}
    for name, solver in (('ahc', 'ahcFoam'), ('ahcTabulated', 'ahcFoam'),
                         ('ahcHot', 'ahcFoam'), ('ahcHotTMax', 'ahcFoam'),
                         ('column', 'pendularFoam'),
                         ('columnWet', 'pendularFoam')):
        case = os.path.join(scratch, name)
        rows, warnings = report(os.path.join(case, 'log.' + solver))
        ok = check.true('%s: one start-up report in log.%s' % (name, solver),
                        rows is not None)
        logs[name] = (case, rows, warnings) if ok else None
    if None in logs.values():
        return check.done()

    for name, T0 in (('ahc', 293.15), ('ahcTabulated', 293.15),
                     ('ahcHot', 371.0), ('ahcHotTMax', 371.0)):
        case, rows, warnings = logs[name]
        compare(check, name, rows, ahcExpected(case, T0))
    for name, alphaMax in (('column', 0.02), ('columnWet', 0.08)):
        case, rows, warnings = logs[name]
        T, alpha = columnFields(alphaMax)
        compare(check, name, rows, pendularExpected(case, T, alpha, 101325.0))

    # The README's example is the ahc case's table, line for line
    readme = os.path.join(os.path.dirname(os.path.abspath(__file__)),
                          '..', '..', 'README.md')
    lines = open(readme).read().splitlines()
    first = [i for i, l in enumerate(lines)
             if l.startswith('Start-up report of ahcFoam')]
    example = []
    if len(first) == 1:
        for l in lines[first[0]:]:
            example.append(l)
            if l == 'start-up report ends':
                break
    logLines = open(os.path.join(logs['ahc'][0], 'log.ahcFoam')).read() \
        .splitlines()
    i = logLines.index(example[0]) if example else -1
    check.true('README: the example table is the ahc case\'s',
               example and logLines[i:i + len(example)] == example)

    # Warnings: none in range; out of range one naming the range, its cells
    for name in ('ahc', 'ahcTabulated', 'ahcHotTMax', 'column'):
        check.true('%s: no start-up warning' % name, logs[name][2] == [],
                   ' | '.join(logs[name][2]))
    s = soil(logs['ahcHot'][0])
    x = (371.0 - s['Tv'])/(math.sqrt(2)*s['dT'])
    sigma = 0.5*(1 + math.erf(x))
    w = logs['ahcHot'][2]
    m = re.search(r'evaporation window \(T_v - 2 dT = 369\.15 K\): up to a'
                  r' fraction (\S+) of theta_0 .*\(80 cells\)$', w[0]) \
        if len(w) == 1 else None
    check.true('ahcHot: one warning, the window, sigma(371 K) = %.6g, 80 cells'
               % sigma, m is not None and
               abs(float(m.group(1)) - sigma) < 1e-5*sigma, ' | '.join(w))
    T, alpha = columnFields(0.08)
    nOut = sum(a > 0.05 for a in alpha)
    w = logs['columnWet'][2]
    m = re.search(r'alpha_l up to (\S+) above the pendular range alpha_l <= '
                  r'0\.05 .*\((\d+) cells\)$', w[0]) if len(w) == 1 else None
    check.true('columnWet: one warning, alpha_l up to %g > 0.05 in %d cells'
               % (max(alpha), nOut),
               m is not None and abs(float(m.group(1)) - max(alpha)) < 1e-9
               and int(m.group(2)) == nOut, ' | '.join(w))
    check.true('README: the example warning is columnWet\'s',
               len(w) == 1 and w[0] in lines, w[0] if w else '')
    return check.done()


if __name__ == '__main__':
    if sys.argv[1] == 'setFields':
        setFields(sys.argv[2], float(sys.argv[3]))
    else:
        sys.exit(checkAll(sys.argv[2]))
