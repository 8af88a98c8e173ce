/*---------------------------------------------------------------------------*\
  hearthFoam: tests/fitPosterior

  Priors and predictive intervals of the hearthFit core (fitPosterior with
  levenbergMarquardt) on the linear Gaussian model
      y = A p + e,  e ~ N(0, sigma^2 I),  A: 40 x 3, its third column 0
  (a parameter the data cannot see), predictions z = G p. For this model
  the first-order posterior is exact (Tarantola 2005 §3.2):
      C = (A^T A/sigma^2 + C_prior^-1)^-1,
      mean = C (A^T y/sigma^2 + C_prior^-1 mu),
  computed here in closed form, independently of the optimiser (which only
  sees residuals and finite differences). One line per check:
      ok|FAIL  <what>  value <v>  tol <t>    (pass: v <= t)
  Exit status 1 if any check failed.
\*---------------------------------------------------------------------------*/

#include "levenbergMarquardt.H"
#include "fitPosterior.H"

#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>

using namespace hearthFit;

static int nChecks = 0, nFailed = 0;

static bool check(const std::string& what, double value, double tol)
{
    const bool ok = value <= tol;   // NaN fails
    ++nChecks;
    if (!ok) ++nFailed;
    std::printf
    (
        "%-4s  %-70s value %-11.4g tol %.3g\n",
        ok ? "ok" : "FAIL", what.c_str(), value, tol
    );
    std::fflush(stdout);
    return ok;
}

static bool checkIn(const std::string& what, double v, double lo, double hi)
{
    const bool ok = v >= lo && v <= hi;
    ++nChecks;
    if (!ok) ++nFailed;
    std::printf
    (
        "%-4s  %-70s value %-11.6g in [%g, %g]\n",
        ok ? "ok" : "FAIL", what.c_str(), v, lo, hi
    );
    std::fflush(stdout);
    return ok;
}

static const int m = 40, n = 3;
static const double sigma = 0.5;

static Matrix designA()
{
    Matrix A = Matrix::Zero(m, n);
    for (int i = 0; i < m; ++i)
    {
        const double t = i/double(m - 1);
        A(i, 0) = 1 + std::cos(3*t);
        A(i, 1) = t;
        // A(i, 2) = 0: p3 does not act on the data
    }
    return A;
}

static Matrix designG()
{
    Matrix G(2, n);
    G << 1, 2, 0,
         0.5, -1, 3;
    return G;
}

struct Fit
{
    FitResult res;
    PredictionResult pred;
    Vector taught;
};

//- Fit y with the priors through levenbergMarquardt + fitPosterior
static Fit fit(const Vector& y, const std::vector<Prior>& priors)
{
    const Matrix A = designA(), G = designG();
    std::vector<FitParameter> pars(n);
    const char* names[] = {"p1", "p2", "p3"};
    for (int j = 0; j < n; ++j)
    {
        pars[j].name = names[j];
        pars[j].initial = 1;
        pars[j].lower = -100;
        pars[j].upper = 100;
    }
    FitOptions o;
    o.knownSigma = true;
    o.tolStep = 1e-12;
    o.tolGradient = 1e-12;
    o.tolCost = 1e-14;
    levenbergMarquardt lm(pars, o);
    fitPosterior post(priors, m, int(G.rows()));
    lm.setBatchResidual
    (
        [&](std::vector<Evaluation>& batch)
        {
            // The forward model: data residuals, then the predictions
            for (Evaluation& e : batch)
            {
                e.residuals.resize(m + G.rows());
                e.residuals.head(m) = (A*e.parameters - y)/sigma;
                e.residuals.tail(G.rows()) = G*e.parameters;
                e.ok = true;
            }
            post.absorb(batch);
        }
    );
    Fit f;
    f.res = lm.solve();
    f.pred = post.predict(f.res);
    f.taught = post.taught(f.res);
    return f;
}

//- The closed-form posterior: mean and covariance
static void closedForm
(
    const Vector& y,
    const std::vector<Prior>& priors,
    Vector& mean,
    Matrix& C
)
{
    const Matrix A = designA();
    Matrix P = A.transpose()*A/(sigma*sigma);
    Vector b = A.transpose()*y/(sigma*sigma);
    for (int j = 0; j < n; ++j)
    {
        if (priors[j].given())
        {
            P(j, j) += 1/(priors[j].sd*priors[j].sd);
            b(j) += priors[j].mean/(priors[j].sd*priors[j].sd);
        }
    }
    C = P.inverse();
    mean = C*b;
}


int main()
{
    const Matrix A = designA(), G = designG();
    std::mt19937 rng(20261201);
    std::normal_distribution<double> N01(0, 1);

    // ---- 1. Closed form: a prior comparable to the data (p1), none
    //         (p2), a parameter the data cannot see (p3)
    std::vector<Prior> priors(n);
    priors[0].mean = 1.3;  priors[0].sd = 0.05;
    priors[2].mean = 2.0;  priors[2].sd = 0.5;
    Vector pTrue(n);
    pTrue << 1.25, 0.7, 2.4;
    Vector y(m);
    for (int i = 0; i < m; ++i) y(i) = (A*pTrue)(i) + sigma*N01(rng);

    Fit f = fit(y, priors);
    Vector mean;
    Matrix C;
    closedForm(y, priors, mean, C);
    std::printf("    status %s, estimates %g %g %g\n",
        statusName(f.res.status).c_str(), f.res.parameters(0),
        f.res.parameters(1), f.res.parameters(2));
    check("fit converged (1 = no)", f.res.converged ? 0 : 1, 0);
    for (int j = 0; j < n; ++j)
    {
        // The optimiser stops within tolStep 1e-12 of the minimum, the
        // finite differences of a linear model are exact to ~1e-9
        check("posterior mean p" + std::to_string(j + 1)
            + " vs closed form, in posterior sd",
            std::abs(f.res.parameters(j) - mean(j))/std::sqrt(C(j, j)), 1e-6);
        for (int k = 0; k < n; ++k)
        {
            check("posterior covariance (" + std::to_string(j + 1) + ","
                + std::to_string(k + 1) + ") vs closed form, / sqrt(C_jj C_kk)",
                std::abs(f.res.covariance(j, k) - C(j, k))
               /std::sqrt(C(j, j)*C(k, k)), 1e-6);
        }
    }
    check("p3 unseen: keeps its prior value, relative",
        std::abs(f.res.parameters(2) - 2.0)/2.0, 1e-3);
    check("p3 unseen: posterior sd / prior sd - 1",
        std::abs(f.taught(2) - 1), 1e-3);
    // p1: the data taught something (post/prior well below 1)
    std::printf("    p1: posterior sd / prior sd %.4f\n", f.taught(0));
    checkIn("p1 (prior sd comparable to the data's): post/prior sd",
        f.taught(0), 0.2, 0.95);
    check("p2 (no prior): taught is NaN (1 = not)",
        std::isnan(f.taught(1)) ? 0 : 1, 0);

    // Predictions: value G p, sd sqrt(g^T C g), sensitivities G
    check("predictions available (1 = no)", f.pred.ok ? 0 : 1, 0);
    for (int k = 0; k < 2; ++k)
    {
        const Vector g = G.row(k).transpose();
        const double sd = std::sqrt(g.dot(C*g));
        check("prediction " + std::to_string(k + 1)
            + ": value vs G p at the estimates, in its sd",
            std::abs(f.pred.value(k) - g.dot(f.res.parameters))/sd, 1e-6);
        check("prediction " + std::to_string(k + 1)
            + ": std error vs sqrt(g^T C g), relative",
            std::abs(f.pred.standardError(k) - sd)/sd, 1e-6);
        check("prediction " + std::to_string(k + 1)
            + ": sensitivities vs G, max abs",
            (f.pred.sensitivity.row(k) - G.row(k)).cwiseAbs().maxCoeff(),
            1e-6);
        check("prediction " + std::to_string(k + 1)
            + ": interval half-width / (1.959964 sd) - 1",
            std::abs((f.pred.upper(k) - f.pred.value(k))/(1.959964*sd) - 1),
            1e-6);
    }

    // ---- 2. A weak prior on a parameter the data see well (p2): the
    //         estimate and its sd are the data's
    std::vector<Prior> none(n);
    none[2] = priors[2];                // keeps p3 identifiable
    const Fit f0 = fit(y, none);
    const double se2 = f0.res.standardErrors(1);
    std::vector<Prior> weak(none);
    weak[1].mean = f0.res.parameters(1) + 3*se2;    // 3 data sd off
    weak[1].sd = 1e3*se2;
    const Fit fw = fit(y, weak);
    std::printf("    p2: data-only %g (se %g), with weak prior %g (se %g)\n",
        f0.res.parameters(1), se2, fw.res.parameters(1),
        fw.res.standardErrors(1));
    // theory: shift 3 se (se/sd)^2 = 3e-6 se, sd ratio 1 - 5e-7
    check("p2 weak prior (sd 1000 x data se): estimate shift / data se",
        std::abs(fw.res.parameters(1) - f0.res.parameters(1))/se2, 1e-3);
    check("p2 weak prior: posterior sd / data-only sd - 1",
        std::abs(fw.res.standardErrors(1)/se2 - 1), 1e-3);
    check("p2 weak prior: posterior sd / prior sd (data taught much)",
        fw.taught(1), 2e-3);
    // And a strong one (sd 0.1 x data se) takes over: the test can fail
    std::vector<Prior> strong(none);
    strong[1].mean = weak[1].mean;
    strong[1].sd = 0.1*se2;
    const Fit fs = fit(y, strong);
    std::printf("    p2 with a strong prior (sd 0.1 se): estimate %g,"
        " shift %.3f data se (a prior that were ignored: 0)\n",
        fs.res.parameters(1),
        (fs.res.parameters(1) - f0.res.parameters(1))/se2);
    checkIn("p2 strong prior: shift towards its value, in data se",
        (fs.res.parameters(1) - f0.res.parameters(1))/se2, 2.5, 3.0);

    // ---- 3. Coverage of the predictions' 95 % intervals over repeated
    //         draws: truth from the prior where there is one (p1, p3),
    //         fixed where not (p2), noise N(0, sigma^2). The Bayesian
    //         interval of a linear Gaussian model covers exactly 95 % of
    //         such draws: over 2000, the count is binomial(2000, 0.95):
    //         mean 1900, sd 9.75; 99.9 % two-sided bounds 1900 -/+ 3.29 sd
    //         = [1868, 1932]
    const int nDraws = 2000;
    int covered[2] = {0, 0}, coveredNoPrior3 = 0, failed = 0;
    for (int d = 0; d < nDraws; ++d)
    {
        Vector pt(n);
        pt << priors[0].mean + priors[0].sd*N01(rng), 0.7,
              priors[2].mean + priors[2].sd*N01(rng);
        Vector yd(m);
        for (int i = 0; i < m; ++i) yd(i) = (A*pt)(i) + sigma*N01(rng);
        const Fit fd = fit(yd, priors);
        if (!fd.res.converged || !fd.pred.ok)
        {
            ++failed;
            continue;
        }
        for (int k = 0; k < 2; ++k)
        {
            const double z = G.row(k).dot(pt);
            if (fd.pred.lower(k) <= z && z <= fd.pred.upper(k)) ++covered[k];
        }
        // A propagation that dropped p3's (prior) variance: prediction 2
        const Vector g = G.row(1).transpose();
        Matrix Cd = fd.res.covariance;
        Cd.row(2).setZero();
        Cd.col(2).setZero();
        const double sdd = std::sqrt(g.dot(Cd*g));
        const double z = g.dot(pt);
        if (std::abs(z - fd.pred.value(1)) <= 1.959964*sdd) ++coveredNoPrior3;
    }
    check("coverage draws: fits failed", failed, 0);
    checkIn("prediction 1 (p1 + 2 p2): draws inside the 95 % interval",
        covered[0], 1868, 1932);
    checkIn("prediction 2 (p1/2 - p2 + 3 p3): draws inside the 95 % interval",
        covered[1], 1868, 1932);
    std::printf("    prediction 2 with p3's prior variance dropped: %d of %d"
        " covered (would fail)\n", coveredNoPrior3, nDraws);

    // ---- 4. Bad priors throw
    int threw = 0;
    for (double sd : {-1.0, std::nan("")})
    {
        std::vector<Prior> bad(n);
        bad[0].sd = sd;
        try { fitPosterior p(bad, m, 0); } catch (const std::invalid_argument&) { ++threw; }
    }
    check("negative or NaN sd: throws (count missing)", 2 - threw, 0);

    std::printf("%d checks, %d failed\n", nChecks, nFailed);
    return nFailed ? 1 : 0;
}
