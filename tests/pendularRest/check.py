"""A closed column of wet sand at rest (uniform 20 C, 101325 Pa, alpha_l =
0.005, every patch impermeable and insulated; cells graded 1:5) stays at
rest for an hour: no spurious Darcy flow, no drift of T, p or alpha_l (to
rounding), balances closed."""
import hearthcheck as hc

c = hc.Check('pendularRest')


def vectors(path):
    txt = open(path).read()
    body = txt.split('internalField')[1]
    if 'nonuniform' not in body.split(';')[0]:
        return [tuple(float(v) for v in body.split('(')[1].split(')')[0].split())]
    body = body.split('(', 1)[1]
    return [tuple(float(v) for v in line.strip('() \n').split())
            for line in body.split('\n') if line.strip().startswith('(')]


U = vectors('3600/U')
c.le('max |U| after 1 h [m/s]', max(sum(x*x for x in u)**0.5 for u in U), 1e-15)
for field, start in (('T', 293.15), ('p', 101325.0), ('alphaL', 0.005)):
    vals = hc.read_internal_field('3600/' + field)
    c.le('max |%s - initial|/initial' % field,
         max(abs(v - start) for v in vals)/start, 1e-12)
bal = hc.read_energy_balances('log.pendularFoam')
c.le('largest stored change (water and air kg, energy J)',
     max(abs(b[0]) for b in bal) if bal else 1, 1e-12)
c.done()
