"""Exact erfc histories T = Ti + (T0 - Ti) erfc(z/(2 sqrt(a t))) at the
depths of the sensors file, every 30 s for 6 h: makeExact.py SENSORS OUT"""
import math, sys
a, T0, Ti = 2.5e-7, 600.0, 20.0
names, depths = [], []
for line in open(sys.argv[1]):
    c = [x.strip() for x in line.split('#')[0].split(',')]
    if len(c) == 4 and c[0] != 'name':
        names.append(c[0]); depths.append(abs(float(c[3])))
with open(sys.argv[2], 'w') as f:
    f.write('time_s,' + ','.join(names) + '\n')
    for k in range(0, 721):
        t = 30.0*k
        row = [Ti if t == 0 else Ti + (T0 - Ti)*math.erfc(z/(2*math.sqrt(a*t)))
               for z in depths]
        f.write('%.17g,' % t + ','.join('%.17g' % T for T in row) + '\n')
