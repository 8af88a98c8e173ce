"""fireFromSensors (see Allrun).
    python3 results.py measure sensors.csv measured.csv
        the synthetic measurements: the truth run's sensors every 2 min
        (120 s .. end), linearly interpolated in time, plus Gaussian noise
        of 0.5 C (Python's random.gauss, seed 2026: reproducible);
    python3 results.py compare
        truth, estimate and 95 % band at the knots (results.txt on stdout,
        fireHistory.csv, fireHistory.png by gnuplot) and figures.csv (the
        figures README.md states, checked by tests/tutorialFireFromSensors).
Standard library and etc/python/hearthTutorial.py only."""
import csv
import math
import os
import random
import re
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                '..', '..', 'etc', 'python'))
import hearthTutorial as ht       # noqa: E402

SIGMA, SEED, EVERY = 0.5, 2026, 120.0


def truth(t):
    """The fire law of synthetic.T [C], t in s: ramp 20 -> 700 C over
    0.5 h, 700 C until 1 h, then 20 + 680 exp(-(t - 1 h)/1 h)."""
    if t <= 1800:
        return 20 + 680*t/1800
    if t <= 3600:
        return 700.0
    return 20 + 680*math.exp(-(t - 3600)/3600)


def measure(src, out):
    header, rows = ht.read_csv(src)
    times = [r[0] for r in rows]
    rng = random.Random(SEED)
    with open(out, 'w') as f:
        f.write(','.join(header) + '\n')
        k = 1
        while EVERY*k <= times[-1] + 1e-9:
            t = EVERY*k
            vals = [ht.interpolate(times, [r[c] for r in rows], t)
                    + rng.gauss(0.0, SIGMA) for c in range(1, len(header))]
            f.write('%g,' % t + ','.join('%.10g' % v for v in vals) + '\n')
            k += 1


def compare():
    with open('log.hearthFit') as f:
        log = f.read()
    m = re.search(r'weight w = (\S+) s\^3/K\^2: chi\^2 = (\S+) \(N = (\d+) data; '
                  r'unregularised (\S+)\)', log)
    w, chi2, N, chi2u = (float(m.group(1)), float(m.group(2)),
                         int(m.group(3)), float(m.group(4)))
    knots = re.search(r'^\s*knots\s+\(([^)]*)\);',
                      open('system/hearthFitDict').read(), re.M).group(1).split()
    knots = [float(k) for k in knots]
    with open('postProcessing/hearthFit/parameters.csv') as f:
        est = list(csv.DictReader(f))
    fig = ht.Figures()
    print('fireFromSensors: the fire history at the knots')
    print('weight w = %.3g s^3/K^2 (discrepancy principle: chi^2 = %.1f = N = %d;'
          ' unregularised %.1f)' % (w, chi2, N, chi2u))
    print('%8s %9s %9s %9s %9s %9s  %s' % ('t [min]', 'truth', 'estimate',
          'std err', 'lower', 'upper', 'truth in band'))
    inside, err = 0, []
    with open('fireHistory.csv', 'w') as f:
        f.write('time_min,truth_C,estimate_C,lower_C,upper_C\n')
        for t, e in zip(knots, est):
            T = truth(t)
            v, se = float(e['estimate']), float(e['std_error'])
            lo, hi = float(e['lower']), float(e['upper'])
            ok = lo <= T <= hi
            inside += ok
            err.append(v - T)
            print('%8.0f %9.1f %9.1f %9.1f %9.1f %9.1f  %s'
                  % (t/60, T, v, se, lo, hi, 'yes' if ok else 'NO'))
            f.write('%g,%.6g,%.6g,%.6g,%.6g\n' % (t/60, T, v, lo, hi))
    rms = math.sqrt(sum(e*e for e in err)/len(err))
    peak = max(float(e['estimate']) for e in est)
    print('truth inside the 95 %% band at %d of %d knots; RMS error %.1f C;'
          ' highest knot %.0f C (truth 700 C)' % (inside, len(knots), rms, peak))
    fig.add('weight', w, 's3/K2')
    fig.add('chi2', chi2, '1')
    fig.add('nData', N, '1')
    fig.add('chi2Unregularised', chi2u, '1')
    fig.add('knotsInBand', inside, '1')
    fig.add('nKnots', len(knots), '1')
    fig.add('rmsError', rms, 'C')
    fig.add('peakEstimate', peak, 'C')
    fig.write()
    subprocess.call(['gnuplot', '-e', '''
set terminal pngcairo size 900,560; set output "fireHistory.png";
set datafile separator ","; set key top right;
set xlabel "time [min]"; set ylabel "fire surface temperature [C]";
plot "fireHistory.csv" skip 1 using 1:4:5 with filledcurves lc rgb "#c8d8f0" title "95 % band",
     "" skip 1 using 1:2 with lines lw 2 lc rgb "black" title "truth",
     "" skip 1 using 1:3 with linespoints pt 7 lc rgb "#c03020" title "estimate"
'''])


if __name__ == '__main__':
    if sys.argv[1:2] == ['measure'] and len(sys.argv) == 4:
        measure(sys.argv[2], sys.argv[3])
    elif sys.argv[1:] == ['compare']:
        compare()
    else:
        sys.exit(__doc__)
