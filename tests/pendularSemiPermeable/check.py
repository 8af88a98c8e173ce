"""Dry sand (20 C, 10 cm, closed bottom) under a semi-permeable top that
lets vapour through but no air, the vapour pressure there given by the
relativeHumidity condition: air at 20 C and 50 % (1169.60 Pa). Vapour diffuses in and, as the air cannot
leave, adds to its pressure: the final state (after 3000 s, 11 diffusion
times H^2 phi/(tau_s D_wa)) is exactly known: p_w = 1169.60 Pa everywhere
and p_g = 101325 + 1169.60 Pa (the air, at the same temperature and volume,
keeps its partial pressure; the menisci of the Kelvin range hold 1.5e-9 of
the pores). Checked: no air through the top (exactly 0), p_w and p_g within
1e-3 Pa of their final values, the water that entered equals the water
stored (balance 1e-8), the air's stored change is round-off."""
import re
import hearthcheck as hc

c = hc.Check('pendularSemiPermeable')
pwb, p0 = 1169.5968683, 101325.0
pw = hc.read_internal_field('3000/pw')
p = hc.read_internal_field('3000/p')
c.le('max |p_w - p_w,top| at 3000 s [Pa]', max(abs(x - pwb) for x in pw), 1e-3)
c.le('max |p_g - (p0 + p_w,top)| at 3000 s [Pa]', max(abs(x - p0 - pwb) for x in p), 1e-3)
log = open('log.pendularFoam').read()
air = [block.split('in the domain')[0] for block in log.split('Air balance at t = ')[1:]]
c.true('no air through the top at any write (3 writes)',
       len(air) == 3 and all('out through top' not in block for block in air),
       '%d writes' % len(air))
bal = hc.read_energy_balances('log.pendularFoam')     # water, air, energy
c.le('worst relative imbalance, water and energy',
     max(abs(b[2]) for k, b in enumerate(bal) if k % 3 != 1), 1e-8)
# the air neither enters nor leaves: its stored change is round-off
c.le('worst air imbalance relative to the air in the column',
     max(abs(b[1]) for b in bal[1::3])/3.136e-6, 1e-12)
water = re.findall(r'Water balance at t = 3000 s \[kg\]:\n    out through top = (\S+)', log)
c.true('vapour entered through the top', bool(water) and float(water[0]) < 0,
       water[0] if water else 'none')
c.done()
