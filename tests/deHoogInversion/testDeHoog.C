/*---------------------------------------------------------------------------*\
  hearthFoam: tests/deHoogInversion
-------------------------------------------------------------------------------
    The de Hoog, Knight & Stokes (1982) inversion of quadrupoleTemperature
    (src/numerics/deHoogInversion/deHoogInversion.H, plain
    C++) on transforms with known inverses, with its default parameters
    (M = 30, tolerance 1e-12, Tfactor 1), at 20 times per decade:

        F(s)              f(t)                               t
        1/(s + 0.7)       exp(-0.7 t)                        1e-3 .. 30
        1/s^2             t                                  1e-3 .. 1e4
        1/sqrt(s)         1/sqrt(pi t)                       1e-3 .. 1e4
        exp(-sqrt s)/s    erfc(1/(2 sqrt t))                 0.05 .. 1e4
        exp(-sqrt s)      exp(-1/(4t))/(2 sqrt(pi) t^1.5)    0.05 .. 1e4
        1/(s^2 + 1)       sin t                              1e-3 .. 40

    Error measure: |f_deHoog(t) - f(t)| / max |f| over the times of the
    decade of t (the times inverted with one series); it must be <= 1e-8.
    The pointwise relative error |f_deHoog - f|/|f| is printed as well and
    checked (<= 1e-8) for the functions that neither vanish nor decay
    exponentially in their range (t, 1/sqrt(pi t), erfc, the pulse above
    its peak region): for exp(-0.7 t) (3e-9 at t = 28) and sin t (zeros)
    it is meaningless.
    Also checked: exp(-sqrt s)/s at the powers of ten exactly (decade
    boundaries). Printed for information only: the parameters of
    Hollenbeck's invlap.m (M = 20, tolerance 1e-9, T = 2 max t), and sin t
    on [10, t1] for t1 = 40..99 (one series): the inversion of an
    oscillating function fails when 2T holds more than about 8 periods
    (error 1e-12 at t1 = 40, 3e-9 at 60, O(1) at 99, whatever M): a limit
    of the method that the (non-oscillating) diffusion responses do not
    meet.
\*---------------------------------------------------------------------------*/

#include "deHoogInversion.H"
#include <cstdio>
#include <string>

using namespace quadrupole;

struct testCase
{
    std::string name;
    std::function<complexReal(const complexReal&)> F;
    std::function<real(real)> f;
    real t0, t1;
    bool pointwise;
};

int failures = 0;

void check(const std::string& what, const real value, const real tol)
{
    const bool ok = value <= tol;
    failures += !ok;
    std::printf
    (
        "  %s %-60s %.3Lg <= %.3Lg\n",
        ok ? "ok  " : "FAIL", what.c_str(), value, tol
    );
}

std::vector<real> logTimes(const real t0, const real t1)
{
    std::vector<real> ts;
    const int n = int(std::floor(20*std::log10(t1/t0) + 1e-9L));
    for (int i = 0; i <= n; ++i)
    {
        ts.push_back(t0*std::pow(real(10), real(i)/20));
    }
    return ts;
}

// Worst decade-normalised and pointwise errors
void errors
(
    const deHoogInversion& inv,
    const testCase& c,
    real& decadeErr,
    real& pointErr,
    real& tWorst
)
{
    const std::vector<real> ts = logTimes(c.t0, c.t1);
    const std::vector<real> fi = inv.invert(c.F, ts);
    std::map<int, real> fMax;
    for (const real t : ts)
    {
        real& m = fMax[deHoogInversion::decade(t)];
        m = std::max(m, std::fabs(c.f(t)));
    }
    decadeErr = pointErr = tWorst = 0;
    for (size_t i = 0; i < ts.size(); ++i)
    {
        const real fe = c.f(ts[i]);
        const real err = std::fabs(fi[i] - fe);
        if (err/fMax[deHoogInversion::decade(ts[i])] > decadeErr)
        {
            decadeErr = err/fMax[deHoogInversion::decade(ts[i])];
            tWorst = ts[i];
        }
        pointErr = std::max(pointErr, err/std::fabs(fe));
    }
}

int main()
{
    const real pi = 3.141592653589793238462643383279502884L;
    const real a = 0.7L;
    const std::vector<testCase> cases =
    {
        {
            "1/(s+0.7) -> exp(-0.7 t)",
            [&](const complexReal& s) { return real(1)/(s + a); },
            [&](real t) { return std::exp(-a*t); },
            1e-3L, 30, false
        },
        {
            "1/s^2 -> t",
            [](const complexReal& s) { return real(1)/(s*s); },
            [](real t) { return t; },
            1e-3L, 1e4L, true
        },
        {
            "1/sqrt(s) -> 1/sqrt(pi t)",
            [](const complexReal& s) { return real(1)/std::sqrt(s); },
            [&](real t) { return 1/std::sqrt(pi*t); },
            1e-3L, 1e4L, true
        },
        {
            "exp(-sqrt s)/s -> erfc(1/(2 sqrt t))",
            [](const complexReal& s) { return std::exp(-std::sqrt(s))/s; },
            [](real t) { return std::erfc(1/(2*std::sqrt(t))); },
            0.05L, 1e4L, true
        },
        {
            "exp(-sqrt s) -> exp(-1/(4t))/(2 sqrt(pi) t^1.5)",
            [](const complexReal& s) { return std::exp(-std::sqrt(s)); },
            [&](real t)
            {
                return std::exp(-1/(4*t))/(2*std::sqrt(pi)*std::pow(t, 1.5L));
            },
            0.05L, 1e4L, true
        },
        {
            "1/(s^2+1) -> sin t",
            [](const complexReal& s) { return real(1)/(s*s + real(1)); },
            [](real t) { return std::sin(t); },
            1e-3L, 40, false
        }
    };

    const deHoogInversion inv;
    std::printf
    (
        "de Hoog inversion, M = %d, tolerance = %.3Lg, Tfactor = %.3Lg,"
        " alpha = %.3Lg\n",
        inv.parameters().M, inv.parameters().tolerance,
        inv.parameters().Tfactor, inv.parameters().alpha
    );

    for (const testCase& c : cases)
    {
        real decadeErr, pointErr, tWorst;
        errors(inv, c, decadeErr, pointErr, tWorst);
        std::printf
        (
            "%s, t in [%.3Lg, %.3Lg]: worst at t = %.4Lg;"
            " pointwise relative %.3Lg\n",
            c.name.c_str(), c.t0, c.t1, tWorst, pointErr
        );
        check("error / max|f| of the decade", decadeErr, 1e-8L);
        if (c.pointwise)
        {
            check("pointwise relative error", pointErr, 1e-8L);
        }
    }

    // Exactly at the decade boundaries
    {
        std::vector<real> ts;
        for (int n = -1; n <= 4; ++n)
        {
            ts.push_back(std::pow(real(10), n));
        }
        const std::vector<real> fi = inv.invert(cases[3].F, ts);
        real worst = 0;
        for (size_t i = 0; i < ts.size(); ++i)
        {
            worst = std::max
            (
                worst, std::fabs(fi[i]/cases[3].f(ts[i]) - 1)
            );
        }
        std::printf("erfc(1/(2 sqrt t)) at t = 0.1, 1, ..., 1e4:\n");
        check("pointwise relative error", worst, 1e-8L);
    }

    // For information: the parameters of Hollenbeck's invlap.m
    {
        deHoogParameters par;
        par.M = 20;
        par.Tfactor = 2;
        par.tolerance = 1e-9L;
        const deHoogInversion hollenbeck(par);
        std::printf("for information, M = 20, tolerance 1e-9, Tfactor 2:\n");
        for (const testCase& c : cases)
        {
            real decadeErr, pointErr, tWorst;
            errors(hollenbeck, c, decadeErr, pointErr, tWorst);
            std::printf
            (
                "  %-50s error / max|f| of the decade %.3Lg\n",
                c.name.c_str(), decadeErr
            );
        }
    }

    // For information: sin t over longer windows
    std::printf("for information, sin t on [10, t1], max |error|:\n");
    for (const real t1 : {40.0L, 50.0L, 60.0L, 70.0L, 80.0L, 99.0L})
    {
        std::vector<real> ts;
        for (int i = 0; i <= 200; ++i)
        {
            ts.push_back(10 + (t1 - 10)*i/200);
        }
        const std::vector<real> fi = inv.invert(cases[5].F, ts);
        real worst = 0;
        for (size_t i = 0; i < ts.size(); ++i)
        {
            worst = std::max(worst, std::fabs(fi[i] - std::sin(ts[i])));
        }
        std::printf("  t1 = %3.0Lf: %.3Lg\n", t1, worst);
    }

    std::printf("deHoogInversion: %s\n", failures ? "FAIL" : "PASS");
    return failures ? 1 : 0;
}
