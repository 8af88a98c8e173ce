"""Energy balance of ahcFoam with latent heat, in three wet-clay cases
(porosity 0.15, pores full of water, energyConsistent AHC, irreversible):

  hotWall  1-D, surface held at 700 C for 3 h
  flux     1-D, imposed time-varying surface gradient (uniformFixedGradient
           table: ramp, hold, ramp down, insulated for the last hour) and a
           fixedGradient loss at the bottom
  cooling  axisymmetric wedge, disc fire at 700 C for 1 h, then the surface
           cooled to 50 C: the dried soil under it cools below 100 C

At every write the solver's balance must close: |stored change - heat in|
<= 1e-6 |stored change|. The latent heat must be a substantial part of the
stored change (>= 20 % at the end), else the test would say little about
the phase change.

The stored change is recomputed here from the written fields (T, TMax,
liquidWater; 17 digits) and the cell volumes (postProcess -func
writeCellVolumes), with the porousMedium / energyConsistent enthalpy
re-implemented from its documented formulas:

  H = ((1 - phi)(rho C)_s + (phi - theta0)(rho C)_v) T + theta0 h*(T; TMax)
  h(T) = (rho C)_l T + ((rho C)_v - (rho C)_l) S(T) + rho_l L sigma(T)
  h*(T; m) = h(T) if T >= m, else h(m) - C_sens(sigma(m)) (m - T)

and the latent part from the written liquid water, L rho_l sum V (theta0 -
theta_l). Both must match what the log reports to 1e-9 (relative): the
fields are written with 17 digits, so this leaves only summation round-off
(the stored change is ~1/10 of the enthalpies it is the difference of).

The water: at every write the log states the liquid water now, at the start
of the run and the water evaporated since (hearthTutorial's reader). The
initial water is recomputed from 0/T and the cell volumes, rho_l sum V theta0
(1 - sigma(T0)), the water now from the written liquidWater; the evaporated
water, initial - now, must match the log to 1e-9 of itself at every write,
from the first write on (the first write comes after evaporation started: its
evaporated water is checked to be more than 1e-3 of the last write's; reading
it as the first write's water minus the last's, as hearthCaseSummary did
before 2026-12-05, misses that much and is printed). hotWallResumed is hotWall
resumed from its 7200 s write as hearthCase -resume does (log.ahcFoam.7200
kept): its second part's initial water must be that of the 7200 s fields, and
the water of the whole run added up over the parts (hearthCaseRestart
.runTotals, what the summary prints) must equal the initial water from 0/
minus the written water at 10800 s, to 1e-9 of it; the same for hotWall.
The latent part of the stored change, a change since the start as the stored
change is, must be L times the water evaporated (1e-9), at every write of
each run and of the resumed part (before 2026-12-05 the solver printed the
latent enthalpy held, 13.5 J at 8400 s where 1.0 J evaporated since 7200 s,
and a sensible part of -10.1 J)."""
import math
import os
import re
import hearthcheck as hc
import hearthCaseRestart as hr

c = hc.Check('energyBalanceLatent')
BALANCE_TOL = 1e-6
RECOMPUTE_TOL = 1e-9


# --------------------------------------------------------------------------
# Material, from constant/porousProperties

def material(case):
    with open(os.path.join(case, 'constant', 'porousProperties')) as f:
        txt = f.read()

    def phase(name):
        m = re.search(r'\b%s\s*\{([^}]*)\}' % name, txt)
        return {k: float(v) for k, v in
                re.findall(r'(\w+)\s+([-+0-9.eE]+)\s*;', m.group(1))}

    def value(key, body=txt):
        return float(re.search(r'\b%s\s+([-+0-9.eE]+)\s*;' % key,
                               body).group(1))

    pc = re.search(r'phaseChange\s*\{([^}]*)\}', txt).group(1)
    assert re.search(r'type\s+energyConsistent\s*;', pc)
    assert not re.search(r'irreversible\s+(false|off|no)\s*;', pc)
    return dict(s=phase('solid'), l=phase('liquid'), v=phase('vapour'),
                phi=value('porosity'), theta0=value('waterContent'),
                Tv=value('Tv', pc), dT=value('dT', pc),
                L=value('latentHeat', pc))


class Enthalpy:
    """porousMedium::enthalpy with energyConsistent, irreversible."""

    def __init__(self, m):
        self.m = m
        self.rhoCpS = m['s']['rho']*m['s']['Cp']
        self.rhoCpL = m['l']['rho']*m['l']['Cp']
        self.rhoCpV = m['v']['rho']*m['v']['Cp']
        self.rhoL = m['l']['rho']

    def x(self, T):
        return (T - self.m['Tv'])/(math.sqrt(2.0)*self.m['dT'])

    def sigma(self, T):
        return 0.5*(1.0 + math.erf(self.x(T)))

    def S(self, T):
        xi = self.x(T)
        return 0.5*math.sqrt(2.0)*self.m['dT']*(
            xi + xi*math.erf(xi) + math.exp(-xi*xi)/math.sqrt(math.pi))

    def h(self, T):
        return (self.rhoCpL*T + (self.rhoCpV - self.rhoCpL)*self.S(T)
                + self.rhoL*self.m['L']*self.sigma(T))

    def hStar(self, T, TMax):
        if T >= TMax:
            return self.h(T)
        s = self.sigma(TMax)
        return self.h(TMax) - (self.rhoCpL*(1 - s) + self.rhoCpV*s)*(TMax - T)

    def H(self, T, TMax):
        m = self.m
        return (((1 - m['phi'])*self.rhoCpS + (m['phi'] - m['theta0'])
                 * self.rhoCpV)*T + m['theta0']*self.hStar(T, TMax))

    def latent(self, T, TMax):
        return (self.m['theta0']*self.rhoL*self.m['L']
                * self.sigma(max(T, TMax)))


# --------------------------------------------------------------------------
# Log

def balances(log):
    """Every energy balance of an ahcFoam log: dicts with t, heat (per
    patch), heatIn, stored, latent, imbalance, water."""
    out, cur = [], None
    with open(log) as f:
        for line in f:
            m = re.match(r'Energy balance at t = (\S+) s', line)
            if m:
                cur = {'t': m.group(1), 'heat': {}}
                out.append(cur)
                continue
            if cur is None:
                continue
            m = re.match(r'\s+heat in through (\S+) = (\S+)', line)
            if m:
                cur['heat'][m.group(1)] = float(m.group(2))
            m = re.match(r'\s+heat in \(all patches\) = (\S+)', line)
            if m:
                cur['heatIn'] = float(m.group(1))
            m = re.match(r'\s+stored change\s+= (\S+) \(latent (\S+),', line)
            if m:
                cur['stored'], cur['latent'] = map(float, m.groups())
            m = re.match(r'\s+imbalance\s+= (\S+)', line)
            if m:
                cur['imbalance'] = float(m.group(1))
            m = re.match(r'\s+liquid water\s+= (\S+) kg', line)
            if m:
                cur['water'] = float(m.group(1))
    return out


def rel(a, b):
    return abs(a - b)/max(abs(b), 1e-300)


def initial_water(case, en):
    """rho_l sum V theta0 (1 - sigma(T0)) [kg] from 0/T and 0/V (no 0/TMax:
    TMax starts at T)"""
    assert not os.path.exists(os.path.join(case, '0', 'TMax'))
    V = hc.read_internal_field(os.path.join(case, '0', 'V'))
    T0 = hc.read_internal_field(os.path.join(case, '0', 'T'))
    T0 = T0*len(V) if len(T0) == 1 else T0
    return en.rhoL*en.m['theta0']*sum(v*(1 - en.sigma(t))
                                      for v, t in zip(V, T0))


def written_water(case, time, en):
    """rho_l sum V theta_l [kg] from the liquidWater written at time"""
    V = hc.read_internal_field(os.path.join(case, '0', 'V'))
    theta = hc.read_internal_field(os.path.join(case, time, 'liquidWater'))
    return en.rhoL*sum(v*th for v, th in zip(V, theta))


def check_water(case, en):
    """The log's initial and evaporated water at every write against the
    fields (module docstring)"""
    W0 = initial_water(case, en)
    eb = hc.energy_balances(os.path.join(case, 'log.ahcFoam'))
    if not c.true('%s: every balance states the initial and evaporated'
                  ' water, from t = 0 s' % case,
                  bool(eb) and all('evaporated' in b and b['waterStart'] == 0
                             for b in eb)):
        return
    worstInitial = max(rel(b['initialLiquidWater'], W0) for b in eb)
    evap = [W0 - written_water(case, '%g' % b['time'], en) for b in eb]
    worstEvap = max(rel(b['evaporated'], e) for b, e in zip(eb, evap))
    old = eb[0]['liquidWater'] - eb[-1]['liquidWater']
    print('    water: initial %.10g kg (0/ fields); evaporated %.6g kg by the'
          ' first write (%g s), %.6g kg by the last; first minus last'
          ' write %.6g kg (%.2g low)'
          % (W0, evap[0], eb[0]['time'], evap[-1], old, rel(old, evap[-1])))
    c.le('%s: initial liquid water, log vs 0/ fields (relative)' % case,
         worstInitial, RECOMPUTE_TOL)
    c.le('%s: water evaporated since t = 0, log vs fields (relative),'
         ' worst write' % case, worstEvap, RECOMPUTE_TOL)
    c.true('%s: water already evaporated at the first write (> 1e-3 of the'
           ' last write\'s)' % case, evap[0] > 1e-3*evap[-1],
           '%.3g of it' % (evap[0]/evap[-1]))
    latent_vs_water(case, eb, en)


def latent_vs_water(what, eb, en):
    """The latent part of the stored change against L times the water
    evaporated, both since the start of the run (energyConsistent: the
    latent enthalpy is rho_l L theta0 sigma), at every write, to 1e-9"""
    c.le('%s: latent change vs L x water evaporated (relative), worst write'
         % what, max(rel(b['latent'], en.m['L']*b['evaporated'])
                     for b in eb), RECOMPUTE_TOL)


# --------------------------------------------------------------------------

def check_case(case, endTime, nWrites):
    print('%s:' % case)
    mat = material(case)
    en = Enthalpy(mat)
    V = hc.read_internal_field(os.path.join(case, '0', 'V'))
    T0 = hc.read_internal_field(os.path.join(case, '0', 'T'))
    T0 = T0*len(V) if len(T0) == 1 else T0
    H0 = sum(v*en.H(t, t) for v, t in zip(V, T0))

    bal = balances(os.path.join(case, 'log.ahcFoam'))
    c.true('%s: %d energy balances, the last at %g s' % (case, nWrites,
                                                          endTime),
           len(bal) == nWrites and abs(float(bal[-1]['t']) - endTime) < 1e-6,
           '%d, last at %s s' % (len(bal), bal[-1]['t'] if bal else '-'))

    worstBal = worstStored = worstLatent = worstWater = 0.0
    for b in bal:
        d = os.path.join(case, b['t'])
        T = hc.read_internal_field(os.path.join(d, 'T'))
        TMax = hc.read_internal_field(os.path.join(d, 'TMax'))
        theta = hc.read_internal_field(os.path.join(d, 'liquidWater'))
        assert len(T) == len(TMax) == len(theta) == len(V)

        stored = sum(v*en.H(t, tm) for v, t, tm in zip(V, T, TMax)) - H0
        latent = (mat['theta0']*en.rhoL*mat['L']*sum(V)
                  - en.rhoL*mat['L']*sum(v*th for v, th in zip(V, theta)))
        latentT = sum(v*en.latent(t, tm) for v, t, tm in zip(V, T, TMax))
        b['fields'] = (T, TMax, theta)

        worstBal = max(worstBal, abs(b['imbalance'])/abs(b['stored']))
        worstStored = max(worstStored, rel(stored, b['stored']))
        worstLatent = max(worstLatent, rel(latent, b['latent']),
                          rel(latentT, b['latent']))
        worstWater = max(worstWater, rel(
            en.rhoL*sum(v*th for v, th in zip(V, theta)), b['water']))
        print('    t = %6s s: stored %.6g J, latent %4.1f %%, imbalance %.2e'
              ' (relative %.2e), recomputed stored - log %.1e (relative)'
              % (b['t'], b['stored'], 100*b['latent']/b['stored'],
                 b['imbalance'], b['imbalance']/b['stored'],
                 rel(stored, b['stored'])))

    c.le('%s: |imbalance| / |stored change|, worst write' % case,
         worstBal, BALANCE_TOL)
    c.le('%s: |imbalance - (stored - heat in)|, worst write [J]' % case,
         max(abs(b['imbalance'] - (b['stored'] - b['heatIn'])) for b in bal),
         1e-12*max(abs(b['stored']) for b in bal))
    c.true('%s: latent >= 20 %% of the stored change at the end' % case,
           bal[-1]['latent'] >= 0.2*bal[-1]['stored'],
           '%.1f %%' % (100*bal[-1]['latent']/bal[-1]['stored']))
    c.le('%s: stored change recomputed from T, TMax, V vs log' % case,
         worstStored, RECOMPUTE_TOL)
    c.le('%s: latent from liquidWater (and from TMax) vs log' % case,
         worstLatent, RECOMPUTE_TOL)
    c.le('%s: liquid water mass from liquidWater vs log' % case,
         worstWater, RECOMPUTE_TOL)
    check_water(case, en)
    return mat, bal


def dried_and_cooled(mat, en, fields):
    """Cells dried (TMax > Tv + 4 dT: sigma > 1 - 3.2e-5) now below Tv - 4 dT:
    their number, and the largest of theta_l/theta0 (irreversible: <= 1 -
    sigma(Tv + 4 dT) = 3.2e-5) and of what reversible drying would give
    instead, 1 - sigma(T) (>= 1 - 3.2e-5)."""
    T, TMax, theta = fields
    hot, cold = mat['Tv'] + 4*mat['dT'], mat['Tv'] - 4*mat['dT']
    cells = [i for i in range(len(T)) if TMax[i] > hot and T[i] < cold]
    return (len(cells),
            max([theta[i]/mat['theta0'] for i in cells] or [float('nan')]),
            min([1 - en.sigma(T[i]) for i in cells] or [float('nan')]))


def latent_never_decreases(case, bal):
    lat = [b['latent'] for b in bal]
    c.true('%s: latent energy never decreases (irreversible drying)' % case,
           all(b >= a*(1 - 1e-12) for a, b in zip(lat, lat[1:])),
           ' '.join('%.5g' % v for v in lat))


# hotWall: a drying front at the end: dry at the surface, wet at depth
mat, bal = check_case('hotWall', 10800, 9)
theta = bal[-1]['fields'][2]
Cz = hc.read_internal_field(os.path.join('hotWall', '0', 'Cz'))
front = max(-z for z, th in zip(Cz, theta) if th < 0.5*mat['theta0'])
c.true('hotWall: a drying front 1 to 10 cm deep at 3 h, wet below',
       0.01 < front < 0.10 and max(theta) > 0.999*mat['theta0'],
       'front (theta_l = theta0/2) at %.2f cm' % (100*front))

# hotWall, and hotWall resumed from 7200 s: the water of the whole run as
# the summary adds it up over the parts, each from its own start
en = Enthalpy(mat)
W0 = initial_water('hotWall', en)
for case in ('hotWall', 'hotWallResumed'):
    try:
        tot = hr.runTotals(case, 'ahcFoam')
    except hr.RestartError as e:
        c.true('%s: runTotals' % case, False, str(e))
        continue
    parts = tot['parts']
    nParts = 1 if case == 'hotWall' else 2
    evap = W0 - written_water(case, '10800', en)
    print('%s: %d part(s), water evaporated %.10g kg (summary), %.10g kg'
          ' (fields)' % (case, len(parts), tot['water'], evap))
    c.true('%s: %d part(s) to 10800 s' % (case, nParts),
           len(parts) == nParts and tot['time'] == 10800)
    c.le('%s: water evaporated of the whole run (runTotals) vs 0/ and'
         ' 10800 s fields (relative)' % case, rel(tot['water'], evap),
         RECOMPUTE_TOL)
    if nParts == 2 == len(parts):
        c.true('hotWallResumed: the second part starts at 7200 s',
               parts[1]['waterStart'] == 7200)
        # its stored change counts from 7200 s, and so must its latent part
        latent_vs_water('hotWallResumed, second part',
                        hc.energy_balances(parts[1]['log']), en)
        c.le('hotWallResumed: the second part\'s initial water vs the'
             ' 7200 s fields (relative)',
             rel(parts[1]['initialLiquidWater'],
                 written_water('hotWall', '7200', en)), RECOMPUTE_TOL)

# flux: the imposed gradient is switched off after 2 h: no more heat in
# through the surface; the dried layer then cools from inside (T < TMax)
mat, bal = check_case('flux', 10800, 9)
q = [b['heat']['surface'] for b in bal]
c.true('flux: heat in through the surface grows while imposed, then is'
       ' constant', all(b > a for a, b in zip(q[:5], q[1:6]))
       and abs(q[-1] - q[5]) <= 1e-12*q[-1],
       ' '.join('%.4g' % v for v in q))
T, TMax, theta = bal[-1]['fields']
nCool = sum(1 for t, tm in zip(T, TMax) if tm > mat['Tv'] + 4*mat['dT']
            and t < tm - 10)
c.true('flux: dried cells cooling (T < TMax - 10 K) at the end', nCool >= 5,
       '%d cells' % nCool)
latent_never_decreases('flux', bal)

# cooling: soil dried under the fire and then cooled below 100 C keeps no
# water (irreversible branch), and the balance holds through the cooling
mat, bal = check_case('cooling', 9000, 10)
n, wet, wetReversible = dried_and_cooled(mat, Enthalpy(mat),
                                        bal[-1]['fields'])
hot = 1 - Enthalpy(mat).sigma(mat['Tv'] + 4*mat['dT'])
c.true('cooling: dried cells now below Tv - 4 dT, without water',
       n >= 20 and wet <= hot*(1 + 1e-9),
       '%d cells, theta_l/theta0 <= %.3g (reversible: >= %.6f)'
       % (n, wet, wetReversible))
latent_never_decreases('cooling', bal)
# the recomputation does see the irreversible branch: with TMax ignored
# (reversible drying, h*(T; T) = h(T)) the stored change is far off
en = Enthalpy(mat)
V = hc.read_internal_field(os.path.join('cooling', '0', 'V'))
T0 = hc.read_internal_field(os.path.join('cooling', '0', 'T'))
T0 = T0*len(V) if len(T0) == 1 else T0
T, TMax, theta = bal[-1]['fields']
storedReversible = sum(v*(en.H(t, t) - en.H(t0, t0))
                       for v, t, t0 in zip(V, T, T0))
c.true('cooling: recomputed with reversible drying, the stored change'
       ' differs', rel(storedReversible, bal[-1]['stored']) > 1e3*RECOMPUTE_TOL,
       'by %.3g (relative)' % rel(storedReversible, bal[-1]['stored']))

c.done()
