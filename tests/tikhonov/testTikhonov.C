/*---------------------------------------------------------------------------*\
  hearthFoam: tests/tikhonov

  Tikhonov regularisation of the hearthFit core (src/numerics/leastSquares/
  tikhonov with levenbergMarquardt) on a linear ill-posed model: a Gaussian
  blur y = A p + e, A 60 x 20 (the smoothing a buried sensor does to the
  surface history), e ~ N(0, sigma^2), rows divided by sigma. Independent
  closed form (normal equations, computed here with Eigen's LDLT):
      p(w) = (A^T A/sigma^2 + w L^T L)^-1 A^T y/sigma^2.
  Checks: the optimiser with the rows sqrt(w) L p (absorb) converges to
  p(w) at a fixed w (1e-6 relative); the discrepancy rule's weight gives
  chi^2 = N (1e-4 relative) and its p(w) equals the closed form; the L-curve
  corner is a local maximum of the curvature; regularisation reduces the
  error against the truth (the unregularised one is much larger: x3);
  the divided-difference operator on stretched knots against the integrals
  of T'^2 and T''^2 of sin t, converging at second order (plain
  differences are off); on uniform knots the weight h^3 x the plain one,
  same estimate; the data-only chi^2 at the estimate flagged outside its
  band for a nonlinear model, back in it with the weight re-chosen at the
  estimate; bad order, knots, too few parameters and negative weight
  throw.
\*---------------------------------------------------------------------------*/

#include "levenbergMarquardt.H"
#include "tikhonov.H"

#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>

using namespace hearthFit;

static int nFailed = 0;

static bool check(const std::string& what, double value, double tol)
{
    const bool ok = value <= tol;   // NaN fails
    if (!ok) ++nFailed;
    std::printf
    (
        "%-4s  %-66s value %-11.4g tol %.3g\n",
        ok ? "ok" : "FAIL", what.c_str(), value, tol
    );
    return ok;
}

template<class F>
static void checkThrows(const std::string& what, F f)
{
    bool thrown = false;
    try { f(); } catch (const std::invalid_argument& e)
    {
        thrown = true;
        std::printf("      (%s)\n", e.what());
    }
    check(what + " throws", thrown ? 0 : 1, 0);
}

int main()
{
    const int m = 60, n = 20;
    const double sigma = 0.5;
    Matrix A(m, n);
    for (int i = 0; i < m; ++i)
    {
        const double ti = (i + 0.5)*n/double(m);
        for (int j = 0; j < n; ++j)
        {
            A(i, j) = 0.4*std::exp(-0.5*std::pow((ti - j)/2.0, 2));
        }
    }
    Vector ptrue(n);
    for (int j = 0; j < n; ++j)
    {
        ptrue(j) = 20 + 680*std::sin(M_PI*j/(n - 1));
    }
    std::mt19937 gen(2026);
    std::normal_distribution<double> noise(0, sigma);
    Vector y = A*ptrue;
    for (int i = 0; i < m; ++i) y(i) += noise(gen);

    auto closed = [&](const tikhonov& reg, double w)
    {
        const Matrix H = A.transpose()*A/(sigma*sigma) + w*reg.L().transpose()*reg.L();
        return Vector(H.ldlt().solve(A.transpose()*y/(sigma*sigma)));
    };
    auto chi2 = [&](const Vector& p)
    {
        return ((A*p - y)/sigma).squaredNorm();
    };

    // The optimiser with the rows, fixed weight
    tikhonov reg(n, 0, n, 2, 1e-4);
    std::vector<FitParameter> pars(n);
    for (int j = 0; j < n; ++j)
    {
        pars[j].name = "p" + std::to_string(j);
        pars[j].initial = 300;
        pars[j].lower = -1e4;
        pars[j].upper = 1e4;
        pars[j].typical = 100;
    }
    FitOptions opts;
    opts.knownSigma = true;
    levenbergMarquardt lm(pars, opts);
    lm.setBatchResidual
    (
        [&](std::vector<Evaluation>& batch)
        {
            for (Evaluation& e : batch)
            {
                e.residuals = (A*e.parameters - y)/sigma;
                e.ok = true;
            }
            reg.absorb(batch);
        }
    );
    const FitResult res = lm.solve();
    const Vector pw = closed(reg, 1e-4);
    check
    (
        "fixed w = 1e-4: optimiser = closed form (max rel. diff)",
        ((res.parameters - pw).cwiseAbs().maxCoeff())/pw.cwiseAbs().maxCoeff(),
        1e-6
    );

    // Discrepancy principle on the linearisation at p0 (exact: linear)
    const Vector p0 = Vector::Constant(n, 300);
    const Matrix J = A/sigma;
    const Vector r0 = (A*p0 - y)/sigma;
    const tikhonov::Choice c =
        reg.choose(tikhonov::Rule::discrepancy, J, r0, p0);
    const Vector pd = closed(reg, c.weight);
    std::printf("      discrepancy: w = %.6g, chi^2 = %.6g (N = %d), unregularised %.6g\n",
        c.weight, c.chi2, m, c.chi2Unregularised);
    check("discrepancy: |chi^2(w)/N - 1| (closed form)", std::abs(chi2(pd)/m - 1), 1e-4);
    check("discrepancy: weight set", std::abs(reg.weight() - c.weight), 0);
    const Vector p00 = reg.solve(J, r0, p0, 0);
    const double eReg = (pd - ptrue).norm(), eNone = (p00 - ptrue).norm();
    std::printf("      error |p - p_true|: regularised %.4g, unregularised %.4g\n",
        eReg, eNone);
    check("unregularised error / regularised error >= 3 (1/ratio)", eReg/eNone, 1.0/3);

    // L-curve: the corner is a local maximum of the curvature
    const tikhonov::Choice cl = reg.choose(tikhonov::Rule::lCurve, J, r0, p0);
    auto kappa = [&](double w)
    {
        // curvature of (log |r|, log |L p|) against log w, independent
        // central differences with step 0.05 in log w
        const double h = 0.05, t = std::log(w);
        double x[3], yv[3];
        for (int k = 0; k < 3; ++k)
        {
            const Vector p = closed(reg, std::exp(t + (k - 1)*h));
            x[k] = 0.5*std::log(chi2(p));
            yv[k] = std::log((reg.L()*p).norm());
        }
        const double x1 = (x[2] - x[0])/(2*h), y1 = (yv[2] - yv[0])/(2*h);
        const double x2 = (x[2] - 2*x[1] + x[0])/(h*h);
        const double y2 = (yv[2] - 2*yv[1] + yv[0])/(h*h);
        return (x1*y2 - y1*x2)/std::pow(x1*x1 + y1*y1, 1.5);
    };
    std::printf("      L-curve: w = %.6g, chi^2 = %.6g; curvature %.4g (x 0.5: %.4g, x 2: %.4g)\n",
        cl.weight, cl.chi2, kappa(cl.weight), kappa(0.5*cl.weight), kappa(2*cl.weight));
    check("L-curve: curvature at w/2 <= at w (difference)", kappa(0.5*cl.weight) - kappa(cl.weight), 0);
    check("L-curve: curvature at 2w <= at w (difference)", kappa(2*cl.weight) - kappa(cl.weight), 0);

    // Knot spacing: |L T|^2 against the integral of T'^2 (order 1) and
    // T''^2 (order 2) of T(t) = sin(t) on stretched knots t_k =
    // pi (k/(K-1))^2 (spacings from 2e-3 to 0.2 at K = 41): exact
    // integrals of cos^2 and sin^2. Order 1 is the midpoint rule of
    // (T')^2 (second order in h), order 2 a midpoint sum over the dual
    // cells of the interior knots, [(t_0 + t_1)/2, (t_{K-2} + t_{K-1})/2],
    // on these smoothly stretched knots second order too (measured errors
    // 1.03e-3 and 1.95e-3 at K = 41, ratios 4.0 and 3.9 when K - 1
    // doubles): within 2e-3 and 4e-3, ratios >= 3. Plain differences (the
    // old operator), made a smoothness measure of uniform knots of the
    // mean spacing (x h^-1, x h^-3), are off: measured x1.28 and x3.7,
    // checked > 20 % off.
    {
        auto intCos2 = [](double a, double b)
        { return 0.5*(b - a) + 0.25*(std::sin(2*b) - std::sin(2*a)); };
        auto intSin2 = [](double a, double b)
        { return 0.5*(b - a) - 0.25*(std::sin(2*b) - std::sin(2*a)); };
        double err1[2], err2[2];
        for (int level = 0; level < 2; ++level)
        {
            const int K = 40*(level + 1) + 1;
            std::vector<double> t(K);
            Vector T(K);
            for (int k = 0; k < K; ++k)
            {
                t[k] = M_PI*std::pow(k/double(K - 1), 2);
                T(k) = std::sin(t[k]);
            }
            const double hMean = (t[K - 1] - t[0])/(K - 1);
            const tikhonov r1(K, 0, t, 1, 0), r2(K, 0, t, 2, 0);
            const tikhonov q1(K, 0, K, 1, 0), q2(K, 0, K, 2, 0);
            const double I1 = intCos2(t[0], t[K - 1]);
            const double I2 =
                intSin2(0.5*(t[0] + t[1]), 0.5*(t[K - 2] + t[K - 1]));
            const double s1 = (r1.L()*T).squaredNorm();
            const double s2 = (r2.L()*T).squaredNorm();
            err1[level] = std::abs(s1/I1 - 1);
            err2[level] = std::abs(s2/I2 - 1);
            const double plain1 = (q1.L()*T).squaredNorm()/hMean;
            const double plain2 = (q2.L()*T).squaredNorm()/std::pow(hMean, 3);
            std::printf("      %d stretched knots: |L1 T|^2 = %.6g, integral T'^2 = %.6g"
                " (plain differences / h: %.4g); |L2 T|^2 = %.6g,"
                " integral T''^2 = %.6g (plain / h^3: %.4g)\n",
                K, s1, I1, plain1, s2, I2, plain2);
            if (level == 0)
            {
                check("41 knots: |L1 T|^2 / integral T'^2 - 1 (rel.)", err1[0], 2e-3);
                check("41 knots: |L2 T|^2 / integral T''^2 - 1 (rel.)", err2[0], 4e-3);
                check("plain first differences / h: off by > 20 % (1/|rel. error|)",
                    1/std::abs(plain1/I1 - 1), 1/0.2);
                check("plain second differences / h^3: off by > 20 % (1/|rel. error|)",
                    1/std::abs(plain2/I2 - 1), 1/0.2);
            }
        }
        std::printf("      errors 41 -> 81 knots: order 1 %.3g -> %.3g, order 2 %.3g -> %.3g\n",
            err1[0], err1[1], err2[0], err2[1]);
        check("order 1: error ratio under refinement >= 3 (1/ratio)", err1[1]/err1[0], 1/3.0);
        check("order 2: error ratio under refinement >= 3 (1/ratio)", err2[1]/err2[0], 1/3.0);
    }

    // Uniform knots of spacing h: L = h^-3/2 x plain second differences,
    // the discrepancy weight h^3 x the plain one, the same estimate
    {
        const double h = 300;
        std::vector<double> t(n);
        for (int k = 0; k < n; ++k) t[k] = 1000 + h*k;
        tikhonov regH(n, 0, t, 2, 0), regU(n, 0, n, 2, 0);
        const double dL = (regH.L() - regU.L()/std::pow(h, 1.5)).cwiseAbs().maxCoeff()
           /(regH.L().cwiseAbs().maxCoeff());
        check("uniform h = 300: L = h^-1.5 x plain (max rel. diff)", dL, 1e-14);
        const tikhonov::Choice cH = regH.choose(tikhonov::Rule::discrepancy, J, r0, p0);
        const tikhonov::Choice cU = regU.choose(tikhonov::Rule::discrepancy, J, r0, p0);
        std::printf("      uniform h = 300: discrepancy w = %.6g (plain differences %.6g, x h^3 = %.6g)\n",
            cH.weight, cU.weight, cU.weight*h*h*h);
        check("uniform: weight = h^3 x plain weight (rel.)",
            std::abs(cH.weight/(cU.weight*h*h*h) - 1), 1e-5);
        const Vector pH = regH.solve(J, r0, p0, cH.weight);
        const Vector pU = regU.solve(J, r0, p0, cU.weight);
        check("uniform: same estimate (max rel. diff)",
            (pH - pU).cwiseAbs().maxCoeff()/pU.cwiseAbs().maxCoeff(), 1e-5);
    }

    // The data-only chi^2 at the estimate (dataMisfitInBand): a weight
    // chosen by the discrepancy principle on the linearisation at p0 of a
    // linear model gives chi^2 = N at the estimate (in band); of a
    // nonlinear one (y = A g(p), g(p) = p^2/700, started at 2000: its
    // sensitivities there 3 to 100 times those at the truth, 20..700) it
    // need not: measured chi^2 92.6 at the optimiser's estimate, outside
    // N -/+ 2 sqrt(2N) = 60 -/+ 21.9 (flagged; from 300 or 100 it stays
    // inside, 55 and 48); the weight chosen again on the linearisation at
    // that estimate (one outer iteration) brings it back (measured 60.7).
    {
        check("linear: discrepancy weight, chi^2 at the estimate in band (0: yes)",
            tikhonov::dataMisfitInBand(chi2(pd), m) ? 0 : 1, 0);
        auto g = [](const Vector& p) { return Vector(p.array().square()/700); };
        auto dg = [](const Vector& p) { return Vector(2*p/700); };
        Vector yn = A*g(ptrue);
        std::mt19937 gen2(7);
        for (int i = 0; i < m; ++i) yn(i) += noise(gen2);
        tikhonov regN(n, 0, n, 2, 0);
        auto fit = [&](const Vector& pStart)
        {
            std::vector<FitParameter> pn(pars);
            for (int j = 0; j < n; ++j)
            {
                pn[j].initial = pStart(j);
                pn[j].lower = 1;
            }
            levenbergMarquardt lmN(pn, opts);
            lmN.setBatchResidual
            (
                [&](std::vector<Evaluation>& batch)
                {
                    for (Evaluation& e : batch)
                    {
                        e.residuals = (A*g(e.parameters) - yn)/sigma;
                        e.ok = true;
                    }
                    regN.absorb(batch);
                }
            );
            return lmN.solve();
        };
        auto chooseAt = [&](const Vector& p)
        {
            const Matrix Jn = (A*dg(p).asDiagonal())/sigma;
            const Vector rn = (A*g(p) - yn)/sigma;
            return regN.choose(tikhonov::Rule::discrepancy, Jn, rn, p);
        };
        const Vector p0n = Vector::Constant(n, 2000);
        const tikhonov::Choice c0 = chooseAt(p0n);
        const FitResult f0 = fit(p0n);
        const double chi0 = f0.residuals.head(m).squaredNorm();
        const tikhonov::Choice c1 = chooseAt(f0.parameters);
        const FitResult f1 = fit(f0.parameters);
        const double chi1 = f1.residuals.head(m).squaredNorm();
        std::printf("      nonlinear: w at p0 = %.4g: chi^2 at the estimate %.2f"
            " (N = %d, band +- %.2f); w at the estimate = %.4g: chi^2 %.2f\n",
            c0.weight, chi0, m, tikhonov::dataMisfitBand(m), c1.weight, chi1);
        check("nonlinear: weight of p0, chi^2 at the estimate outside the band (0: flagged)",
            tikhonov::dataMisfitInBand(chi0, m) ? 1 : 0, 0);
        check("nonlinear: weight re-chosen at the estimate, chi^2 in band (0: yes)",
            tikhonov::dataMisfitInBand(chi1, m) ? 0 : 1, 0);
    }

    // Bad input
    checkThrows("knots not increasing",
        [&]{ tikhonov(n, 0, std::vector<double>{0, 2, 1}, 1, 0); });
    checkThrows("order 3", [&]{ tikhonov(n, 0, n, 3, 0); });
    checkThrows("2 parameters, order 2", [&]{ tikhonov(n, 0, 2, 2, 0); });
    checkThrows("negative weight", [&]{ tikhonov(n, 0, n, 1, -1); });

    std::printf("%s\n", nFailed ? "tikhonov: FAIL" : "tikhonov: PASS");
    return nFailed ? 1 : 0;
}
