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
  bad order, too few parameters and negative weight throw.
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

    // Bad input
    checkThrows("order 3", [&]{ tikhonov(n, 0, n, 3, 0); });
    checkThrows("2 parameters, order 2", [&]{ tikhonov(n, 0, 2, 2, 0); });
    checkThrows("negative weight", [&]{ tikhonov(n, 0, n, 1, -1); });

    std::printf("%s\n", nFailed ? "tikhonov: FAIL" : "tikhonov: PASS");
    return nFailed ? 1 : 0;
}
