"""pendularFoam through the critical point of water (647.096 K): checks of
one run (a case directory) of tests/pendularCriticalPoint/run.

    python3 check.py NAME TMIN NHOT STATUS

- the run ended (exit status 0, 'End', no floating-point exception or stack
  trace);
- at the last write, at least NHOT cells above the critical point and the
  hottest cell above TMIN [K];
- every cell at or above the dry-out temperature 647.096 K holds no liquid
  (alpha_l = 0: liquid-free, all its water vapour) and p_w = rho_w R T/M_w
  with rho_w = W/phi;
- the water, air and energy balances printed at every write close to 1e-8
  (relative), as in tests/pendularColumnReference.
Prints the figures (max T, cells above T_c, worst balances, CPU time)."""
import os
import re
import sys
import hearthcheck as hc

name, TMIN, NHOT = sys.argv[1], float(sys.argv[2]), int(sys.argv[3])
status = int(sys.argv[4])
Td, phi, R, Mw = 647.096, 0.26, 8.31, 0.018
c = hc.Check('pendularCriticalPoint ' + name)

log = open('log.pendularFoam').read()
c.true('run ended (exit status 0, End)',
       status == 0 and re.search(r'^End\s*$', log, re.M) is not None,
       'exit status %d' % status)
c.true('no floating-point exception or stack trace',
       not re.search(r'sigFpe::sigHandler|printStack|^#\d+ ', log, re.M))
rejected = len(re.findall(r'step rejected', log))
cpu = re.findall(r'ExecutionTime = (\S+) s', log)
print('  (info) %d steps, %d sub-steps rejected, %s s of CPU'
      % (len(re.findall(r'^pendularFoam: deltaT', log, re.M)), rejected,
         cpu[-1] if cpu else '?'))

times = sorted((d for d in os.listdir('.') if re.match(r'^[0-9.e+-]+$', d)
                and d != '0'), key=float)
if not c.true('a time written', bool(times)):
    c.done()
last = times[-1]
T = hc.read_internal_field(last + '/T')
TMax = hc.read_internal_field(last + '/TMax')
alpha = hc.read_internal_field(last + '/alphaL')
W = hc.read_internal_field(last + '/W')
pw = hc.read_internal_field(last + '/pw')
hot = [i for i, t in enumerate(T) if t >= Td]
c.le('cells above T_c = 647.096 K at t = %s s (at least %d) [-]'
     % (last, NHOT), -len(hot), -NHOT)
c.le('hottest cell (TMax) above %g K [K, negated]' % TMIN, -max(TMax), -TMIN)
print('  (info) max T %.1f K (%.1f C), cells above T_c %d of %d'
      % (max(T), max(T) - 273.15, len(hot), len(T)))
c.le('alpha_l in the cells above T_c (liquid-free)',
     max([alpha[i] for i in hot] or [0]), 0)
c.le('|p_w - (W/phi) R T/M_w|/p_w above T_c (all water vapour)',
     max([abs(pw[i] - W[i]/phi*R*T[i]/Mw)/max(pw[i], 1e-300) for i in hot]
         or [0]), 1e-9)

bal = hc.read_energy_balances('log.pendularFoam')
kinds = ('water', 'air', 'energy')
for k, kind in enumerate(kinds):
    worst = max(abs(b[2]) for b in bal[k::3])
    c.le('worst relative %s imbalance (%d writes)' % (kind, len(bal[k::3])),
         worst, 1e-8)
c.done()
