"""column1D results: profiles against depth and histories of each column
run/<name> (pendularFoam's written fields, one every 30 min), CSV files,
gnuplot PNGs, figures.csv (name,value,unit of the figures README.md
states) and a summary on stdout.  Usage: columnResults.py NAME..."""
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                '..', '..', 'etc', 'python'))
import hearthTutorial as ht       # noqa: E402

P_ATM = 101325.0
PROFILE_HOURS = (0.5, 1, 1.5, 3, 6, 9, 12)
T_FRONT = {}        # (column, t [h]) -> T at the drying front [C]


def internal_field(path):
    """Cell values of an ascii volScalarField (uniform or list)."""
    txt = open(path).read()
    m = re.search(r'internalField\s+uniform\s+(\S+);', txt)
    if m:
        return None, float(m.group(1))
    m = re.search(r'internalField\s+nonuniform\s+List<scalar>\s*(\d+)\s*\(', txt)
    n = int(m.group(1))
    return [float(v) for v in txt[m.end():].split(')')[0].split()[:n]], None


def field(case, time, name, n):
    vals, uniform = internal_field(os.path.join(case, time, name))
    return vals if vals is not None else [uniform]*n


def column(case):
    """Depths of the cell centres (bottom first) and the column height."""
    txt = open(os.path.join(case, 'system/blockMeshDict')).read()
    H = float(re.search(r'^H\s+(\S+);', txt, re.M).group(1))
    n = int(re.search(r'^nCells\s+(\d+);', txt, re.M).group(1))
    return [H - (i + 0.5)*H/n for i in range(n)], H, n


def times(case):
    out = []
    for d in os.listdir(case):
        try:
            if float(d) > 0 and os.path.isfile(os.path.join(case, d, 'T')):
                out.append((float(d), d))
        except ValueError:
            pass
    return sorted(out)


def interp(z, zs, vs):
    pts = sorted(zip(zs, vs))
    for (a, va), (b, vb) in zip(pts, pts[1:]):
        if a <= z <= b:
            return va + (vb - va)*(z - a)/(b - a)
    return float('nan')


def front(zs, alpha, alpha0):
    pts = sorted(zip(zs, alpha))
    for (a, va), (b, vb) in zip(pts, pts[1:]):
        if va < alpha0/2 <= vb:
            return a + (b - a)*(alpha0/2 - va)/(vb - va)
    return None


def gnuplot(script):
    subprocess.run(['gnuplot'], input=script, text=True, check=True)


def main(names):
    hist = {}
    for name in names:
        case = os.path.join('run', name)
        zs, H, n = column(case)
        alpha0 = field(case, '0', 'alphaL', n)[0]
        rows = []
        hist[name] = []
        for t, d in times(case):
            T = field(case, d, 'T', n)
            alpha = field(case, d, 'alphaL', n)
            RH = field(case, d, 'RH', n)
            p = field(case, d, 'p', n)
            W = field(case, d, 'W', n)
            fr = front(zs, alpha, alpha0)
            if fr is not None:
                T_FRONT[(name, t/3600)] = interp(fr, zs, T) - 273.15
            hist[name].append((t/3600, [interp(z, zs, T) - 273.15 for z in (0.01, 0.02, 0.05)],
                               sum(W)*H/n, fr, max(p) - P_ATM, max(alpha)))
            if any(abs(t - 3600*h) < 1 for h in PROFILE_HOURS):
                for z, Tc, a, rh, pc in sorted(zip(zs, T, alpha, RH, p)):
                    rows.append((t/3600, z, Tc - 273.15, a, rh, pc - P_ATM))
        csvName = 'profiles_%s.csv' % name
        with open(csvName, 'w') as f:
            f.write('time_h,depth_m,T_C,alphaL,RH,pg_minus_patm_Pa\n')
            last = None
            for r in rows:
                if last is not None and r[0] != last:
                    f.write('\n\n')
                f.write('%g,%.5f,%.4f,%.6g,%.6g,%.6g\n' % r)
                last = r[0]
        blocks = ', '.join(
            "'%s' index %d using USING with lines title '%g h'" % (csvName, i, h)
            for i, h in enumerate(h for h in PROFILE_HOURS
                                  if any(abs(r[0] - h) < 1e-6 for r in rows)))
        gnuplot("""set terminal pngcairo size 1200,900
set output 'profiles_%s.png'
set datafile separator ','
set multiplot layout 2,2 title 'column1D %s: H = %g m, alpha_l = %g'
set xlabel 'depth [m]'
set key left top
set ylabel 'T [C]'
plot %s
set ylabel 'alpha_l'
set key right top
set logscale y
set yrange [1e-12:*]
plot %s
unset logscale y
set yrange [*:*]
set ylabel 'relative humidity'
plot %s
set ylabel 'p_g - p_{atm} [Pa]'
plot %s
unset multiplot
""" % (name, name, H, alpha0, blocks.replace('USING', '2:3'),
       blocks.replace('USING', '2:($4 > 0 ? $4 : 1e-12)'),
       blocks.replace('USING', '2:5'),
       blocks.replace('USING', '2:6')))

    with open('history.csv', 'w') as f:
        f.write('column,time_h,T_1cm_C,T_2cm_C,T_5cm_C,water_kg_m2,front_m,pg_max_excess_Pa,alpha_max\n')
        for name in names:
            for t, Ts, w, fr, dp, am in hist[name]:
                f.write('%s,%g,%.4f,%.4f,%.4f,%.6g,%s,%.4g,%.4g\n'
                        % (name, t, Ts[0], Ts[1], Ts[2], w, '' if fr is None else '%.5f' % fr, dp, am))
    curves = []
    for name in names:
        for k, z in ((3, 1), (4, 2), (5, 5)):
            curves.append("'< grep ^%s, history.csv' using 2:%d with linespoints title '%s %d cm'"
                          % (name, k, name, z))
    water = ["'< grep ^%s, history.csv' using 2:6 with linespoints title '%s'" % (n, n)
             for n in names]
    gnuplot("""set terminal pngcairo size 1200,500
set output 'history.png'
set datafile separator ','
set multiplot layout 1,2
set xlabel 'time [h]'
set ylabel 'T [C]'
set key right bottom
plot %s
set ylabel 'water in the column [kg/m2]'
set logscale y
set key right top
plot %s
unset multiplot
""" % (', '.join(curves), ', '.join(water)))

    print('column1D results (pendularFoam, model A)')
    for name in names:
        print('  %s:' % name)
        print('    %6s %8s %8s %8s %12s %9s %10s %9s'
              % ('t [h]', 'T 1 cm', 'T 2 cm', 'T 5 cm', 'water', 'front', 'p_g max', 'alpha max'))
        for t, Ts, w, fr, dp, am in hist[name]:
            if any(abs(t - h) < 1e-6 for h in PROFILE_HOURS):
                print('    %6g %8.2f %8.2f %8.2f %12.4g %9s %10.2f %9.3g'
                      % (t, Ts[0], Ts[1], Ts[2], w, '-' if fr is None else '%.4f' % fr, dp, am))
        print('    (T in C, water in kg/m2, front = depth of alpha_l = alpha_0/2 [m],'
              ' p_g max = largest p_g - p_atm [Pa])')
    figures(names, hist)


def figures(names, hist):
    """figures.csv: per column the front, largest alpha_l and gas
    overpressure at each write time and over the run, steps and
    balances"""
    fig = ht.Figures()
    for name in names:
        h = hist[name]
        for t, Ts, w, fr, dp, am in h:
            fig.add('front_%s_%gh' % (name, t), fr and 100*fr, 'cm')
            fig.add('Tfront_%s_%gh' % (name, t), T_FRONT.get((name, t)), 'C')
            fig.add('alphaMax_%s_%gh' % (name, t), am, '1')
            fig.add('pgMax_%s_%gh' % (name, t), dp, 'Pa')
        fig.add('alphaMax_%s' % name, max(r[5] for r in h), '1')
        fig.add('pgMax_%s' % name, max(r[4] for r in h), 'Pa')
        log = os.path.join('run', name, 'log.pendularFoam')
        steps, rejected, exe, _ = ht.log_stats(log)
        fig.add('steps_%s' % name, steps, '1')
        fig.add('rejected_%s' % name, rejected, '1')
        bal = ht.pendular_balances(log)
        for q in ('water', 'air', 'energy'):
            fig.add('largestRelativeImbalance_%s_%s' % (q, name),
                    max(abs(b[q]['relative']) for b in bal), '1')
    fig.write('figures.csv')


if __name__ == '__main__':
    main(sys.argv[1:])
