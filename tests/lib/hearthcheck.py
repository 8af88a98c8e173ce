"""Helpers shared by the hearthFoam tests: reading OpenFOAM output and the
exact solutions the tests compare against (standard library only)."""
import math
import os
import re
import sys


# --------------------------------------------------------------------------
# Reading results

# Cost budgets (see tests/README.md): a solver test states the nonlinear
# iterations and rejected sub-steps its runs need, measured; a run may take
# up to 30 % more. The runs are deterministic (same binary, same input), so
# the margin is not for noise: it lets a harmless change of the numerics
# pass while a lost Jacobian term or acceleration (typically x2 to x10)
# fails. Rejected sub-steps are few and discrete: 2 more are always allowed.
COST_MARGIN = 0.3
REJECTED_SLACK = 2

# The tutorials' readers of probes files and internal fields
# (etc/python/hearthTutorial.py: one reader for the tests and the tutorials)
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                '..', '..', 'etc', 'python'))
from hearthTutorial import read_probes, read_internal_field  # noqa: E402,F401
from hearthTutorial import pendular_balances, energy_balances  # noqa: E402


def read_energy_balances(log):
    """Every balance of an ahcFoam or pendularFoam log (hearthTutorial's
    readers) -> list of (stored change, imbalance, relative), in order:
    per report, ahcFoam's energy; pendularFoam's water, air, energy."""
    blocks = pendular_balances(log)
    if blocks:
        return [(b[k].get('stored'), b[k]['imbalance'], b[k]['relative'])
                for b in blocks for k in ('water', 'air', 'energy')]
    return [(b.get('stored'), b['imbalance'], b['relative'])
            for b in energy_balances(log) if 'relative' in b]


def worst_relative_imbalance(log):
    """Largest imbalance of the water, air and energy balances of every
    report of a pendularFoam log, relative to the larger of the flows'
    scale (stored change and flows out, the solver's 'relative') and the
    amount in the domain (the air's flows are ~0: its own relative figure
    is 1 at 2e-20 kg)."""
    worst, found = 0.0, False
    for b in pendular_balances(log):
        for d in (b['water'], b['air'], b['energy']):
            imb, rel = abs(d['imbalance']), abs(d['relative'])
            scale = imb/rel if rel > 0 else 0.0
            worst = max(worst, imb/max(scale, abs(d.get('inDomain', 0.0)),
                                       1e-300))
            found = True
    if not found:
        raise ValueError('no balance report in ' + log)
    return worst


def read_solver_cost(log):
    """Cost of an ahcFoam or pendularFoam run (or of a richardsResidual
    test's, 'richards:') from its log: the sums over
    the time steps of the per-step summary line
      '<solver>: deltaT = .., iterations = N, sub-steps = M, rejected = R, ..'
    -> dict(steps, iterations, subSteps, rejected). A log without such a
    line (the solver failed at once) gives zero steps. pendularFoam's
    Newton engine ends the line with its air guards of the step,
      '.., refused for less than no air = A, air projections = P'
    (pendularNewton::airLost, airProjection): their sums are airLost and
    airProjections (0 without them)."""
    cost = dict(steps=0, iterations=0, subSteps=0, rejected=0, airLost=0,
                airProjections=0)
    pattern = re.compile(r'^(ahcFoam|pendularFoam|richards): deltaT = \S+, iterations = '
                         r'(\d+), sub-steps = (\d+), rejected = (\d+)'
                         r'(?:.*, refused for less than no air = (\d+), air'
                         r' projections = (\d+))?')
    with open(log) as f:
        for line in f:
            m = pattern.match(line)
            if m:
                cost['steps'] += 1
                cost['iterations'] += int(m.group(2))
                cost['subSteps'] += int(m.group(3))
                cost['rejected'] += int(m.group(4))
                cost['airLost'] += int(m.group(5) or 0)
                cost['airProjections'] += int(m.group(6) or 0)
    return cost


def read_air_guards(log):
    """pendularFoam's Newton engine's air guards since the start, at each
    write (the line after the air partial pressure's report) -> list of
    dict(airLost, projections, chordSentBack, chordProjected, belowZero):
    sub-steps refused by airLost, cells projected onto p_a >= 0 by pTol or
    more, chord steps sent back by their air projection and taken after a
    projection below pTol, cells with p_a < 0 in converged solves."""
    pattern = re.compile(
        r'^Air guards of the Newton engine since the start(?: of this run)?: (\d+) sub-steps'
        r' refused for less than no air \(airLost\), (\d+) cell projections'
        r' onto p_a >= 0 by pTol or more; chord steps: (\d+) sent back by'
        r' their air projection, (\d+) taken with cells projected by less'
        r' than pTol; (\d+) cells with p_a < 0 in converged solves', re.M)
    keys = ('airLost', 'projections', 'chordSentBack', 'chordProjected',
            'belowZero')
    with open(log) as f:
        return [dict(zip(keys, map(int, m))) for m in pattern.findall(f.read())]


def cost_allowance(stated, margin=COST_MARGIN, slack=0):
    """Largest count a budget of `stated` allows: stated (1 + margin),
    and at least stated + slack."""
    return max(int(math.floor(stated*(1 + margin) + 1e-9)), stated + slack)


# --------------------------------------------------------------------------
# Exact solutions

def erfc_solution(z, t, T0, Tw, alpha):
    """Semi-infinite solid at T0, surface held at Tw from t = 0."""
    if t <= 0:
        return T0
    return T0 + (Tw - T0)*math.erfc(z/(2.0*math.sqrt(alpha*t)))


def gardner_head(z, a, e_over_ks, s_b=1.0):
    """Pressure head h [m] at height z [m] of Gardner's (1958) steady
    evaporation at the rate E through an exponential soil, K = K_s exp(a h),
    S_e = exp(a h), from S_e = s_b at z = 0 (s_b = 1: a water table):
    Darcy's flux -K (dh/dz + 1) = E integrates to
        exp(a h(z)) = (s_b + E/K_s) exp(-a z) - E/K_s
    (defined for z < ln(1 + s_b K_s/E)/a; tests/richardsGardner/README.md
    eq. 4 derives the water-table form). S_e(z) = exp(a h(z))."""
    return math.log((s_b + e_over_ks)*math.exp(-a*z) - e_over_ks)/a


class NeumannStefan:
    """Two-phase Neumann solution: semi-infinite solid at T0 < Tf, wall held
    at Tw > Tf, melting front xi = 2 lam sqrt(alpha_l t). The transcendental
    equation is the corrected form of Muhieddine 2009 eq. 2.8 (its last term
    has T_f - T_w where T_w - T_f is meant):
      exp(-lam^2)/erf(lam)
      - ks/kl nu (Tf - T0)/(Tw - Tf) exp(-nu^2 lam^2)/erfc(nu lam)
      = sqrt(pi) lam L/(Cl (Tw - Tf)),  nu = sqrt(alpha_l/alpha_s)."""

    def __init__(self, L, T0, Tw, Tf, kl, ks, Cl, Cs, rho):
        self.T0, self.Tw, self.Tf = T0, Tw, Tf
        self.al = kl/(rho*Cl)
        self.as_ = ks/(rho*Cs)
        self.nu = math.sqrt(self.al/self.as_)
        nu = self.nu

        def f(lam):
            return (math.exp(-lam*lam)/math.erf(lam)
                    - ks/kl*nu*(Tf - T0)/(Tw - Tf)
                    * math.exp(-nu*nu*lam*lam)/math.erfc(nu*lam)
                    - math.sqrt(math.pi)*lam*L/(Cl*(Tw - Tf)))
        a, b = 1e-6, 5.0
        for _ in range(200):
            c = 0.5*(a + b)
            if f(a)*f(c) <= 0:
                b = c
            else:
                a = c
        self.lam = 0.5*(a + b)

    def front(self, t):
        return 2.0*self.lam*math.sqrt(self.al*t)

    def T(self, x, t):
        if t <= 0:
            return self.T0
        xs = x/(2.0*math.sqrt(self.al*t))
        if xs < self.lam:
            return self.Tw + (self.Tf - self.Tw)*math.erf(xs)/math.erf(self.lam)
        return self.T0 + (self.Tf - self.T0)*math.erfc(self.nu*xs) \
            / math.erfc(self.nu*self.lam)

    def time_front_at(self, x):
        return (x/(2.0*self.lam))**2/self.al


# --------------------------------------------------------------------------
# Reporting

class Check:
    """Collects named comparisons; exit status 1 if any failed."""

    def __init__(self, name):
        self.name = name
        self.failed = 0

    def le(self, what, value, tol):
        ok = value <= tol
        self.failed += not ok
        print('  %s %-60s %.4g <= %.4g' % ('ok  ' if ok else 'FAIL', what, value, tol))
        return ok

    def true(self, what, cond, detail=''):
        self.failed += not cond
        print('  %s %-60s %s' % ('ok  ' if cond else 'FAIL', what, detail))
        return cond

    def cost(self, what, log, iterations, rejected, margin=COST_MARGIN):
        """The run of `log` within its cost budget: the nonlinear iterations
        and rejected sub-steps it was measured to need when the budget was
        set (`iterations`, `rejected`), plus the margin. A run much cheaper
        than its budget passes but says so: the budget is then stale."""
        return self._cost(what, [log], iterations, rejected, margin,
                          REJECTED_SLACK)

    def cost_sum(self, what, logs, iterations, rejected, margin):
        """The runs of `logs` together within an aggregate cost budget: the
        sums of their nonlinear iterations and rejected sub-steps within
        `iterations` and `rejected` (1 + margin), each run with steps. For
        runs whose single counts follow round-off of the Newton path (the
        sub-step sequence) while their sum does not: the margin is then the
        sum's measured spread, stated where the budget is."""
        return self._cost(what, logs, iterations, rejected, margin, 0)

    def _cost(self, what, logs, iterations, rejected, margin, slack):
        costs = [read_solver_cost(log) for log in logs]
        its = sum(c['iterations'] for c in costs)
        rej = sum(c['rejected'] for c in costs)
        stepped = all(c['steps'] > 0 for c in costs)
        maxIter = cost_allowance(iterations, margin)
        maxRejected = cost_allowance(rejected, margin, slack)
        ok = stepped and its <= maxIter and rej <= maxRejected
        self.failed += not ok
        print('  %s cost of %-52s %d iterations (budget %d, allowed %d), '
              '%d rejected (budget %d, allowed %d), %s'
              % ('ok  ' if ok else 'FAIL', what, its, iterations, maxIter,
                 rej, rejected, maxRejected,
                 '%d steps' % costs[0]['steps'] if len(logs) == 1
                 else '%d runs%s' % (len(logs), '' if stepped
                                     else ' (a run without steps)')))
        if ok and its < 0.5*iterations:
            print('       note: under half its budget: lower the budget to '
                  'the new count if the saving is understood')
        return ok

    def done(self):
        print('%s: %s' % (self.name, 'PASS' if not self.failed else 'FAIL'))
        sys.exit(1 if self.failed else 0)


# --------------------------------------------------------------------------
# Command line (tests/Alltest, after a test's run passed):
#   python3 hearthcheck.py budget NAME COSTBUDGET SCRATCH
# checks every run listed in the test's costBudget file, lines of
#   <log, relative to the test's scratch folder>  <iterations>  <rejected>
# or, for an aggregate budget (Check.cost_sum), one line
#   sum  <iterations>  <rejected>  <margin>
# and the logs it sums, one a line (<log> alone); '#' starts a comment.


def check_budget_file(name, budget_file, scratch):
    c = Check(name + ' cost budget')
    with open(budget_file) as f:
        rows = [line.split('#')[0].split() for line in f]
    rows = [r for r in rows if r]
    sums = [r for r in rows if r[0] == 'sum']
    summed = [r[0] for r in rows if len(r) == 1]
    for r in rows:
        if r[0] == 'sum' or len(r) == 1:
            continue
        if len(r) != 3:
            c.true('%s: a line is <log> <iterations> <rejected>, <log> or'
                   ' sum <iterations> <rejected> <margin>'
                   % budget_file, False, ' '.join(r))
            continue
        log = os.path.join(scratch, r[0])
        if not os.path.isfile(log):
            c.true('run of %s found' % r[0], False, 'no %s' % log)
            continue
        c.cost(r[0], log, int(r[1]), int(r[2]))
    if sums or summed:
        if not c.true('%s: one line sum <iterations> <rejected> <margin>'
                      ' and the logs it sums' % budget_file,
                      len(sums) == 1 and len(sums[0]) == 4 and summed,
                      '%d sum lines, %d logs' % (len(sums), len(summed))):
            c.done()
        logs = [os.path.join(scratch, r) for r in summed]
        missing = [r for r, log in zip(summed, logs)
                   if not os.path.isfile(log)]
        if missing:
            c.true('runs of the sum found', False, 'no ' + ', '.join(missing))
        else:
            c.cost_sum('the sum of %d runs' % len(logs), logs,
                       int(sums[0][1]), int(sums[0][2]), float(sums[0][3]))
    c.true('the budget lists runs', bool(rows), budget_file)
    c.done()


# --------------------------------------------------------------------------
# Tutorial figures (tests/tutorial*/): the figures a tutorial's results
# script wrote to figures.csv (name,value,unit, etc/python/hearthTutorial.py)
# against the values its README prints, listed in the test's file
#   <name>  <value as printed in the README>  <tolerance>   # why
# ('_' in the printed value stands for a space, as in 142_857; the
# tolerance 'below' checks |value| < printed, for a bound the README
# states).
# The printed value must also appear in one of the READMEs given (as a
# number: not inside a longer one), so that a README edited without its
# test, or a test without its README, fails.
#   python3 hearthcheck.py figures NAME EXPECTED FIGURES_CSV README...


def read_figures(path):
    """figures.csv -> dict name -> (value, unit)"""
    out = {}
    with open(path) as f:
        next(f)
        for line in f:
            r = line.strip().split(',')
            if len(r) == 3:
                out[r[0]] = (float(r[1]), r[2])
    return out


def printed_in(text, printed):
    """printed (e.g. '520.5' or '-3.7e-12') stands as a number in text"""
    return re.search(r'(?<![\d.])%s(?![\d])' % re.escape(printed),
                     text) is not None


def check_figures(name, expected, figures_csv, readmes):
    c = Check(name + ' figures')
    figures = read_figures(figures_csv)
    text = ''
    for r in readmes:
        with open(r) as f:
            text += f.read()
    with open(expected) as f:
        rows = [line.split('#')[0].split() for line in f]
    rows = [r for r in rows if r]
    for r in rows:
        if len(r) != 3:
            c.true('%s: a line is <name> <printed> <tolerance|below>' % expected,
                   False, ' '.join(r))
            continue
        fig, printed = r[0], r[1].replace('_', ' ')
        if fig not in figures:
            c.true('%s in figures.csv' % fig, False, 'missing')
            continue
        value, unit = figures[fig]
        ref = float(printed.replace(' ', ''))
        if r[2] == 'below':             # the README states a bound
            ok = abs(value) < ref
            test = '|value| < %s' % printed
        else:
            ok = abs(value - ref) <= float(r[2])
            test = '|diff| %.3g <= %s' % (abs(value - ref), r[2])
        inReadme = printed_in(text, printed)
        c.failed += not (ok and inReadme)
        print('  %s %-32s %12.6g %-4s README %-9s %s%s'
              % ('ok  ' if ok and inReadme else 'FAIL', fig, value, unit,
                 printed, test,
                 '' if inReadme else '  (%s not in the README)' % printed))
    c.true('the test lists figures', bool(rows), expected)
    c.done()


if __name__ == '__main__':
    if len(sys.argv) == 5 and sys.argv[1] == 'budget':
        check_budget_file(*sys.argv[2:])
    if len(sys.argv) >= 6 and sys.argv[1] == 'figures':
        check_figures(sys.argv[2], sys.argv[3], sys.argv[4], sys.argv[5:])
    print('usage: hearthcheck.py budget NAME COSTBUDGET SCRATCH\n'
          '       hearthcheck.py figures NAME EXPECTED FIGURES_CSV README...')
    sys.exit(2)
