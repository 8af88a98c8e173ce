#!/usr/bin/env python3
"""Write the quadrupoleTemperature dictionaries of the tutorial from the soil
of system/soilProfileDict (the same profiles ahcFoam gets):

    system/quadrupoleDict          the graded metre in 100 uniform-gamma
                                   layers (thinner near the surface, z_i =
                                   (i/100)^2 m), each with the exact k and c
                                   at its faces: the reference (the layers'
                                   k, c within 7e-5 of the profile's; 3e-3 K
                                   from 400 layers)
    system/quadrupoleDict.2layers  2 uniform-gamma layers (0-0.25-1 m), each
                                   with the exact effusivity at its top and
                                   its exact heat capacity and thermal
                                   resistance: the quick approximation of
                                   Krapez & Profice
and below 1 m the uniform semi-infinite soil. Surface: the fire record
constant/fire.csv (min, C), the sensor depths of system/thermocouples.csv,
every 5 min for 24 h.

Reads only what this tutorial's dictionary uses: per property, layers
with 'from', 'to' and a value that is a number or a 'polynomial' of depth.
Standard library only.
"""
import math
import re
import sys


def tokens(text):
    text = re.sub(r'//[^\n]*', '', text)
    text = re.sub(r'/\*.*?\*/', '', text, flags=re.S)
    return re.findall(r'[(){};]|[^\s(){};]+', text)


def block(tok, i):
    """tok[i] == '{' or '(': -> index after the matching close."""
    depth = 0
    for j in range(i, len(tok)):
        if tok[j] in '({':
            depth += 1
        elif tok[j] in ')}':
            depth -= 1
            if depth == 0:
                return j + 1
    sys.exit('makeQuadrupoleDict.py: unbalanced brackets')


def entries(tok):
    """Top-level 'keyword value;' or 'keyword { }' -> {keyword: tokens}"""
    out, i = {}, 0
    while i < len(tok):
        key = tok[i]
        if tok[i + 1] == '{':
            j = block(tok, i + 1)
            out[key] = tok[i + 2:j - 1]
            i = j
        else:
            j = i + 1
            while tok[j] != ';':
                j = block(tok, j) if tok[j] in '({' else j + 1
            out[key] = tok[i + 1:j]
            i = j + 1
    return out


def profile(prop):
    """[(from, to, f)] of a property's layers, f(depth) -> value"""
    layers = entries(entries(prop)['layers'])
    out = []
    for name, body in layers.items():
        e = entries(body)
        value = e['value']
        if len(value) == 1:
            v = float(value[0])
            f = (lambda v: lambda z: v)(v)
        elif value[0] == 'polynomial':
            nums = [float(t) for t in value if t not in ('(', ')',
                                                         'polynomial')]
            coeffs = list(zip(nums[0::2], nums[1::2]))
            f = (lambda cs: lambda z: sum(a*z**p for a, p in cs))(coeffs)
        else:
            sys.exit('makeQuadrupoleDict.py: layer %s: only numbers and'
                     ' polynomials are read' % name)
        out.append((float(e['from'][0]),
                    float(e['to'][0]) if 'to' in e else float('inf'), f))
    return out


with open('system/soilProfileDict') as fh:
    top = entries(tokens(fh.read()))
kProfile = profile(top['kappaSolid'])
cProfile = profile(top['rhoCpSolid'])
graded = kProfile[0][1]
assert kProfile[0][0] == 0 and cProfile[0][0] == 0 \
    and cProfile[0][1] == graded and len(kProfile) == len(cProfile) == 2, \
    'expected a graded layer from 0 and a uniform soil below it'


def value(prof, z):
    for a, b, f in prof:
        if a <= z < b:
            return f(z)
    raise ValueError(z)


k = lambda z: value(kProfile, z)
c = lambda z: value(cProfile, z)
b = lambda z: math.sqrt(k(z)*c(z))
a = lambda z: k(z)/c(z)


def simpson(f, z0, z1, n=200):
    h = (z1 - z0)/n
    return h/3*(f(z0) + f(z1) + sum((4 if i % 2 else 2)*f(z0 + i*h)
                                    for i in range(1, n)))


def num(x):
    return repr(float(x))


def layer_faces(z0, z1):
    """k, c exact at both faces (quadrupoleTemperature computes gamma)"""
    return ['thickness %s;' % num(z1 - z0),
            'conductivity %s;' % num(k(z0)),
            'volumetricHeatCapacity %s;' % num(c(z0)),
            'conductivityBottom %s;' % num(k(z1)),
            'volumetricHeatCapacityBottom %s;' % num(c(z1))]


def layer_CR(z0, z1):
    """b exact at the top; heat capacity C and resistance R exact: a
    uniform-gamma layer has C = b_E (e^(2u) - 1)/(2 gamma) and
    R = (1 - e^(-2u))/(2 gamma b_E), u = gamma xi_L; xi_L is set through
    diffusivityBottom (xi_L = 2 L/(sqrt(a_top) + sqrt(a_bottom)))."""
    C = simpson(c, z0, z1)
    R = simpson(lambda z: 1/k(z), z0, z1)
    bE, aT = b(z0), a(z0)
    u = 0.5*math.log(C/(R*bE*bE))
    g = math.sinh(u)/math.sqrt(C*R)
    xi = u/g
    aB = (2*(z1 - z0)/xi - math.sqrt(aT))**2
    return ['thickness %s;' % num(z1 - z0),
            'effusivity %s;' % num(bE),
            'diffusivity %s;' % num(aT),
            'gamma %s;' % num(g),
            'diffusivityBottom %s;' % num(aB)]


with open('system/thermocouples.csv') as fh:
    depths = [-float(l.split(',')[3]) for l in fh
              if l.strip() and not l.startswith('#')]


def write(path, faces, layer, title, output):
    lines = ['/* ' + title + ' (written by makeQuadrupoleDict.py) */',
             'FoamFile { version 2.0; format ascii; class dictionary;'
             ' object quadrupoleDict; }',
             'initialTemperature 20;     // C, as the fire record',
             'layers', '{']
    for i in range(len(faces) - 1):
        lines.append('    l%d { %s }' % (i, ' '.join(layer(faces[i],
                                                          faces[i + 1]))))
    lines += ['}',
              'substrate { conductivity %s; volumetricHeatCapacity %s; }'
              % (num(k(graded)), num(c(graded))),
              'surface',
              '{',
              '    condition   temperature;',
              '    file        "constant/fire.csv";',
              '    timeUnit    min;',
              '}',
              'depths (%s);' % ' '.join(num(d) for d in depths),
              'endTime 86400;',
              'writeInterval 300;',
              'outputFile "%s";' % output, '']
    with open(path, 'w') as fh:
        fh.write('\n'.join(lines))


n = 100
write('system/quadrupoleDict', [graded*(i/n)**2 for i in range(n + 1)],
      layer_faces, '%d uniform-gamma layers, exact k and c at the faces' % n,
      'postProcessing/quadrupoleTemperature/temperature.csv')
write('system/quadrupoleDict.2layers', [0, 0.25*graded, graded], layer_CR,
      '2 uniform-gamma layers, exact C and R',
      'postProcessing/quadrupoleTemperature/temperature_2layers.csv')
