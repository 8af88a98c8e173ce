"""Read a pendularFoam run of the heat pipe (latest time) and locate its
dry-out front; imported by check.py."""
import os
import re

Swr = 0.15
L = 2.4


def field(path):
    s = open(path).read()
    m = re.search(r'internalField\s+nonuniform\s+List<scalar>\s*\d+\s*\((.*?)\)'
                  r'\s*;', s, re.S)
    return [float(v) for v in m.group(1).split()]


def latest(case):
    times = [d for d in os.listdir(case)
             if re.fullmatch(r'[0-9.e+-]+', d) and d != '0']
    return max(times, key=float)


def profile(case):
    """(x of the cell centres from the cold end, S, T) at the latest time."""
    t = latest(case)
    S = field(os.path.join(case, t, 'alphaL'))
    T = field(os.path.join(case, t, 'T'))
    dx = L/len(S)
    return [(i + 0.5)*dx for i in range(len(S))], S, T, float(t)


def front(x, S):
    """Where S falls through S_wr (the liquid immobile: S_e = 0), linear
    between the centres of the last cell above S_wr and the next."""
    for i in range(len(S) - 1):
        if S[i] >= Swr > S[i + 1]:
            return x[i] + (x[i + 1] - x[i])*(S[i] - Swr)/(S[i] - S[i + 1])
    return None


def interp(xs, ys, x):
    for i in range(len(xs) - 1):
        if xs[i] <= x <= xs[i + 1]:
            w = (x - xs[i])/(xs[i + 1] - xs[i])
            return ys[i] + w*(ys[i + 1] - ys[i])
    return ys[0] if x < xs[0] else ys[-1]
