/*---------------------------------------------------------------------------*\
  hearthFoam: tests/nistRegression

  The hearthFit optimiser core (applications/utilities/hearthFit/
  leastSquares/levenbergMarquardt) against NIST StRD nonlinear regression
  problems, with finite-difference Jacobians only (the optimiser never
  sees a derivative), plus its other promises: failing evaluations are
  survived, bounds are respected (no evaluation outside them), log
  transforms, Gauss-Newton, concurrent batches, progress, stopping,
  input checks, statistics (the test computes one analytic Jacobian
  itself, Misra1a's, to check the covariance).  One line per check:
      ok|FAIL  <what>  value <v>  tol <t>    (pass: v <= t)
      ok|FAIL  <what>  value <v>  min <t>    (pass: v >= t)
      ok|FAIL  <what>  value <text>          (a condition)
  Lines starting with spaces are information.  Exit status 1 if any
  check failed.
\*---------------------------------------------------------------------------*/

#include "levenbergMarquardt.H"
#include "nistProblems.H"

#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <set>
#include <thread>

using namespace hearthFit;

static int nChecks = 0, nFailed = 0;

// Pass when value <= tol
static bool check(const std::string& what, double value, double tol)
{
    const bool ok = value <= tol;   // NaN fails
    ++nChecks;
    if (!ok) ++nFailed;
    std::printf
    (
        "%-4s  %-66s value %-11.4g tol %.3g\n",
        ok ? "ok" : "FAIL", what.c_str(), value, tol
    );
    std::fflush(stdout);
    return ok;
}

// Pass when value >= least
static bool checkAtLeast(const std::string& what, double value, double least)
{
    const bool ok = value >= least;
    ++nChecks;
    if (!ok) ++nFailed;
    std::printf
    (
        "%-4s  %-66s value %-11.4g min %.3g\n",
        ok ? "ok" : "FAIL", what.c_str(), value, least
    );
    std::fflush(stdout);
    return ok;
}

// Pass when cond is true
static bool checkTrue(const std::string& what, bool cond, const std::string& v)
{
    ++nChecks;
    if (!cond) ++nFailed;
    std::printf
    (
        "%-4s  %-66s value %s\n", cond ? "ok" : "FAIL", what.c_str(), v.c_str()
    );
    std::fflush(stdout);
    return cond;
}

static double relErr(double a, double b)
{
    return std::abs(a - b)/std::abs(b);
}

static std::string fmt(const char* f, double x)
{
    char buf[64];
    std::snprintf(buf, sizeof buf, f, x);
    return buf;
}


// Residuals of a NIST problem: model - y
static bool nistResiduals(const nistProblem& P, const Vector& b, Vector& r)
{
    const std::size_t m = P.y.size();
    r.resize(m);
    for (std::size_t i = 0; i < m; ++i)
    {
        r(i) = P.model(P.x[i], b.data()) - P.y[i];
    }
    return r.allFinite();
}


static std::vector<FitParameter> nistParameters
(
    const nistProblem& P,
    const std::vector<double>& start
)
{
    std::vector<FitParameter> pars(P.nPar);
    for (int j = 0; j < P.nPar; ++j)
    {
        pars[j].name = "b" + std::to_string(j + 1);
        pars[j].initial = start[j];
    }
    return pars;
}


// Options of the NIST runs: forward differences with the step of the rule
// for a closed-form model (noise = machine epsilon), tight tolerances
static FitOptions nistOptions()
{
    FitOptions o;
    o.difference = Difference::forward;
    o.hRel = levenbergMarquardt::recommendedRelativeStep
    (
        std::numeric_limits<double>::epsilon(), Difference::forward
    );
    o.tolStep = 1e-12;
    o.tolGradient = 1e-12;
    o.tolCost = 1e-15;
    o.maxIterations = 1000;
    return o;
}


static void checkCertified
(
    const std::string& tag,
    const nistProblem& P,
    const FitResult& R,
    bool checkSD = true
)
{
    checkTrue
    (
        tag + ": converged",
        R.converged,
        R.message + fmt(", %g iterations", R.iterations)
      + fmt(", %g evaluations", double(R.evaluations))
      + fmt(", scaled gradient %.1e", R.scaledGradient)
    );
    for (int j = 0; j < P.nPar; ++j)
    {
        check
        (
            tag + ": b" + std::to_string(j + 1) + " relative error",
            relErr(R.parameters(j), P.certified[j]), 1e-6
        );
    }
    if (checkSD)
    {
        for (int j = 0; j < P.nPar; ++j)
        {
            check
            (
                tag + ": sd(b" + std::to_string(j + 1) + ") relative error",
                relErr(R.standardErrors(j), P.certifiedSD[j]), 1e-3
            );
        }
    }
    check
    (
        tag + ": residual sum of squares relative error",
        relErr(R.cost, P.certifiedRSS), 1e-6
    );
}


// * * * * * * * * * * * * * * * NIST problems  * * * * * * * * * * * * * * //

static void testNist(const std::vector<nistProblem>& problems)
{
    for (const nistProblem& P : problems)
    {
        // The data as typed: RSS at the certified parameters
        Vector bc = Eigen::Map<const Vector>(P.certified.data(), P.nPar);
        Vector r;
        nistResiduals(P, bc, r);
        check
        (
            P.name + " (" + P.level + "): data, RSS at certified parameters",
            relErr(r.squaredNorm(), P.certifiedRSS), 1e-9
        );

        for (int s = 1; s <= 2; ++s)
        {
            const std::vector<double>& start = s == 1 ? P.start1 : P.start2;
            levenbergMarquardt lm(nistParameters(P, start), nistOptions());
            lm.setResidual
            (
                [&P](const Vector& b, Vector& r)
                {
                    return nistResiduals(P, b, r);
                }
            );
            const FitResult R = lm.solve();
            checkCertified(P.name + " start " + std::to_string(s), P, R);
        }
    }
}


// * * * * * * * * * * * * * * * Other checks * * * * * * * * * * * * * * * //

static const nistProblem& find
(
    const std::vector<nistProblem>& problems,
    const std::string& name
)
{
    for (const nistProblem& P : problems)
    {
        if (P.name == name) return P;
    }
    throw std::runtime_error("no problem " + name);
}


static Vector vec(const std::vector<double>& v)
{
    return Eigen::Map<const Vector>(v.data(), v.size());
}


static FitResult fitNist
(
    const nistProblem& P,
    const std::vector<FitParameter>& pars,
    const FitOptions& o
)
{
    levenbergMarquardt lm(pars, o);
    lm.setResidual
    (
        [&P](const Vector& b, Vector& r) { return nistResiduals(P, b, r); }
    );
    return lm.solve();
}


// Gauss-Newton, geodesic acceleration, log transforms
static void testVariants(const std::vector<nistProblem>& problems)
{
    const nistProblem& misra = find(problems, "Misra1a");
    const nistProblem& eck = find(problems, "Eckerle4");
    const nistProblem& mgh09 = find(problems, "MGH09");

    FitOptions gn = nistOptions();
    gn.method = Method::gaussNewton;
    checkCertified
    (
        "Gauss-Newton Misra1a start 1", misra,
        fitNist(misra, nistParameters(misra, misra.start1), gn)
    );
    checkCertified
    (
        "Gauss-Newton Misra1a start 2", misra,
        fitNist(misra, nistParameters(misra, misra.start2), gn)
    );
    checkCertified
    (
        "Gauss-Newton MGH09 start 2", mgh09,
        fitNist(mgh09, nistParameters(mgh09, mgh09.start2), gn)
    );

    FitOptions geo = nistOptions();
    geo.geodesicAcceleration = true;
    checkCertified
    (
        "geodesic acceleration Eckerle4 start 1", eck,
        fitNist(eck, nistParameters(eck, eck.start1), geo)
    );

    FitOptions central = nistOptions();
    central.difference = Difference::central;
    central.hRel = levenbergMarquardt::recommendedRelativeStep
    (
        std::numeric_limits<double>::epsilon(), Difference::central
    );
    checkCertified
    (
        "central differences Eckerle4 start 1", eck,
        fitNist(eck, nistParameters(eck, eck.start1), central)
    );

    // Log transforms (all parameters of both problems are positive)
    {
        std::vector<FitParameter> pars = nistParameters(misra, misra.start1);
        for (FitParameter& q : pars) q.transform = Transform::log;
        checkCertified
        (
            "log transform Misra1a start 1", misra,
            fitNist(misra, pars, nistOptions())
        );
    }
    // (Eckerle4 start 1 is not used here: in ln b its path runs to the
    // plateau b1, b2 -> infinity, a flat Gaussian, and stops there on
    // costTolerance, a valid local solution "at infinity")
    {
        std::vector<FitParameter> pars = nistParameters(eck, eck.start2);
        for (FitParameter& q : pars) q.transform = Transform::log;
        checkCertified
        (
            "log transform Eckerle4 start 2", eck,
            fitNist(eck, pars, nistOptions())
        );
    }
    {
        std::vector<FitParameter> pars = nistParameters(mgh09, mgh09.start1);
        for (FitParameter& q : pars) q.transform = Transform::log;
        checkCertified
        (
            "log transform MGH09 start 1", mgh09,
            fitNist(mgh09, pars, nistOptions())
        );
    }
}


// Evaluations that fail
static void testFailures(const std::vector<nistProblem>& problems)
{
    const nistProblem& misra = find(problems, "Misra1a");
    const nistProblem& eck = find(problems, "Eckerle4");

    // 1. A region where the model "diverges": Gaussians wider than
    //    b2 = 50 (Eckerle4 from start 1 goes to b2 ~ 1000 otherwise)
    for (const double wide : {50.0, 100.0})
    {
        levenbergMarquardt lm(nistParameters(eck, eck.start1), nistOptions());
        lm.setResidual
        (
            [&eck, wide](const Vector& b, Vector& r)
            {
                if (b(1) > wide) return false;
                return nistResiduals(eck, b, r);
            }
        );
        const FitResult R = lm.solve();
        const std::string tag =
            "failing region b2 > " + fmt("%g", wide) + ", Eckerle4 start 1";
        checkCertified(tag, eck, R);
        checkAtLeast
        (
            tag + ": failed evaluations", double(R.failedEvaluations), 1
        );
    }

    // 1b. A failing region across the descent path (Misra1a from start 1
    //     heads for b1 ~ 674 first and every descent direction points to
    //     b1 > 600): the fit ends on the region's edge and says so,
    //     instead of claiming convergence
    {
        levenbergMarquardt lm(nistParameters(misra, misra.start1), nistOptions());
        lm.setResidual
        (
            [&misra](const Vector& b, Vector& r)
            {
                if (b(0) > 600) return false;
                return nistResiduals(misra, b, r);
            }
        );
        const FitResult R = lm.solve();
        checkTrue
        (
            "failing region b1 > 600 across the path, Misra1a start 1:"
            " stalledAtFailures, not converged",
            R.status == FitStatus::stalledAtFailures && !R.converged
         && R.parameters(0) <= 600,
            R.message + fmt(", b1 %.6g", R.parameters(0))
          + fmt(", scaled gradient %.2g", R.scaledGradient)
        );
    }

    // 2. Every 4th call fails, whatever it evaluates (crashes): trial
    //    steps and Jacobian columns (retried on the other side)
    for (int s = 1; s <= 2; ++s)
    {
        const nistProblem& P = s == 1 ? misra : eck;
        long calls = 0;
        levenbergMarquardt lm(nistParameters(P, P.start1), nistOptions());
        lm.setResidual
        (
            [&P, &calls](const Vector& b, Vector& r)
            {
                if (++calls % 4 == 0) return false;
                return nistResiduals(P, b, r);
            }
        );
        const FitResult R = lm.solve();
        checkCertified("every 4th evaluation fails, " + P.name + " start 1", P, R);
        check
        (
            "every 4th evaluation fails: failed/evaluations - 1/4",
            std::abs(double(R.failedEvaluations)/R.evaluations - 0.25), 0.02
        );
    }

    // 3. Central differences, one side of every column fails
    {
        FitOptions o = nistOptions();
        o.difference = Difference::central;
        o.hRel = 1e-5;
        Vector current = vec(misra.start1);
        levenbergMarquardt lm(nistParameters(misra, misra.start1), o);
        lm.setBatchResidual
        (
            [&misra](std::vector<Evaluation>& batch)
            {
                // the centre is the first element's parameters except in
                // the perturbed component: fail the minus sides (detected
                // as the smaller of a central pair)
                for (std::size_t k = 0; k < batch.size(); ++k)
                {
                    Evaluation& e = batch[k];
                    bool minusSide = false;
                    if (batch.size() == 4)
                    {
                        const std::size_t partner = k ^ 1;
                        const int j = int(k/2);
                        minusSide =
                            e.parameters(j) < batch[partner].parameters(j);
                    }
                    e.ok = !minusSide && nistResiduals(misra, e.parameters, e.residuals);
                }
            }
        );
        const FitResult R = lm.solve();
        checkCertified("central, minus side always fails, Misra1a start 1", misra, R);
    }

    // 4. The initial point fails: a status, not an exception
    {
        levenbergMarquardt lm(nistParameters(misra, misra.start1), nistOptions());
        lm.setResidual([](const Vector&, Vector&) { return false; });
        const FitResult R = lm.solve();
        checkTrue
        (
            "initial evaluation fails: status initialEvaluationFailed",
            R.status == FitStatus::initialEvaluationFailed && !R.converged,
            statusName(R.status)
        );
    }

    // 5. Everything but the initial point fails: jacobianFailed, best
    //    parameters (the initial ones) returned
    {
        const Vector b0 = vec(misra.start1);
        levenbergMarquardt lm(nistParameters(misra, misra.start1), nistOptions());
        lm.setResidual
        (
            [&](const Vector& b, Vector& r)
            {
                if (b != b0) return false;
                return nistResiduals(misra, b, r);
            }
        );
        const FitResult R = lm.solve();
        checkTrue
        (
            "all but the initial point fail: status jacobianFailed, start kept",
            R.status == FitStatus::jacobianFailed && !R.converged
         && R.parameters == b0,
            statusName(R.status) + fmt(", %g evaluations", R.evaluations)
        );
    }

    // 6. Non-finite residuals count as failures
    {
        levenbergMarquardt lm(nistParameters(eck, eck.start1), nistOptions());
        lm.setResidual
        (
            [&eck](const Vector& b, Vector& r)
            {
                nistResiduals(eck, b, r);
                if (b(1) > 50) r(3) = std::numeric_limits<double>::quiet_NaN();
                return true;
            }
        );
        const FitResult R = lm.solve();
        checkCertified("NaN residuals for b2 > 50, Eckerle4 start 1", eck, R, false);
        checkAtLeast
        (
            "NaN residuals: counted as failed evaluations",
            double(R.failedEvaluations), 1
        );
    }
}


// Bounds: respected by every evaluation, active bounds, inactive bounds
static void testBounds(const std::vector<nistProblem>& problems)
{
    const nistProblem& misra = find(problems, "Misra1a");

    struct Case
    {
        std::string tag;
        std::vector<double> start;
        double lo1, hi1, lo2, hi2;
        Difference d;
        int active;   // index of the parameter on its bound, -1: none
        bool activeUpper;
    };
    const double inf = std::numeric_limits<double>::infinity();
    const std::vector<Case> cases =
    {
        {"b1 >= 245, start 1", misra.start1, 245, inf, -inf, inf,
         Difference::forward, 0, false},
        {"b1 >= 245, start 2", misra.start2, 245, inf, -inf, inf,
         Difference::forward, 0, false},
        {"b1 >= 245, start 2, central", misra.start2, 245, inf, -inf, inf,
         Difference::central, 0, false},
        {"b2 <= 5.3e-4, start 1", misra.start1, 0, 1000, 0, 5.3e-4,
         Difference::forward, 1, true},
        {"b2 <= 5.3e-4, start 1, central", misra.start1, 0, 1000, 0, 5.3e-4,
         Difference::central, 1, true},
        {"inactive [200,600]x[1e-4,1e-3], start 2", misra.start2, 200, 600,
         1e-4, 1e-3, Difference::forward, -1, false}
    };

    for (const Case& c : cases)
    {
        std::vector<FitParameter> pars = nistParameters(misra, c.start);
        pars[0].lower = c.lo1; pars[0].upper = c.hi1;
        pars[1].lower = c.lo2; pars[1].upper = c.hi2;
        FitOptions o = nistOptions();
        o.difference = c.d;
        if (c.d == Difference::central)
        {
            o.hRel = 1e-5;
        }

        long outside = 0, total = 0;
        levenbergMarquardt lm(pars, o);
        lm.setResidual
        (
            [&](const Vector& b, Vector& r)
            {
                ++total;
                if
                (
                    b(0) < c.lo1 || b(0) > c.hi1
                 || b(1) < c.lo2 || b(1) > c.hi2
                )
                {
                    ++outside;
                }
                return nistResiduals(misra, b, r);
            }
        );
        const FitResult R = lm.solve();
        const std::string tag = "bounds Misra1a " + c.tag;

        check
        (
            tag + ": evaluations outside the box (of "
          + std::to_string(total) + ")", double(outside), 0
        );

        if (c.active < 0)
        {
            checkCertified(tag, misra, R);
            continue;
        }

        checkTrue(tag + ": converged", R.converged, R.message);
        const int a = c.active, f = 1 - c.active;
        const double bound =
            c.activeUpper ? pars[a].upper : pars[a].lower;
        check
        (
            tag + ": b" + std::to_string(a + 1) + " - bound",
            std::abs(R.parameters(a) - bound), 0
        );
        checkTrue
        (
            tag + ": atBound flags",
            R.atBound[a] && !R.atBound[f],
            std::to_string(R.atBound[0]) + std::to_string(R.atBound[1])
        );

        // The free parameter must be the 1-D optimum with the other held
        // on its bound (independent fit of one parameter)
        std::vector<FitParameter> one(1);
        one[0].name = "free";
        one[0].initial = misra.certified[f];
        levenbergMarquardt lm1(one, nistOptions());
        lm1.setResidual
        (
            [&](const Vector& q, Vector& r)
            {
                Vector b(2);
                b(a) = bound;
                b(f) = q(0);
                return nistResiduals(misra, b, r);
            }
        );
        const FitResult R1 = lm1.solve();
        check
        (
            tag + ": b" + std::to_string(f + 1)
          + " vs 1-parameter fit on the bound, relative",
            relErr(R.parameters(f), R1.parameters(0)), 1e-6
        );
    }
}


// Batch interface: sizes, concurrency, progress, stopping, resuming
static void testInterface(const std::vector<nistProblem>& problems)
{
    const nistProblem& thurber = find(problems, "Thurber");
    const nistProblem& misra = find(problems, "Misra1a");

    for (int central = 0; central <= 1; ++central)
    {
        FitOptions o = nistOptions();
        if (central)
        {
            o.difference = Difference::central;
            o.hRel = 1e-5;
        }
        const std::vector<FitParameter> pars =
            nistParameters(thurber, thurber.start2);

        // Serial, one vector at a time
        levenbergMarquardt serial(pars, o);
        serial.setResidual
        (
            [&](const Vector& b, Vector& r) { return nistResiduals(thurber, b, r); }
        );
        const FitResult Rs = serial.solve();

        // One thread per element of the batch
        std::set<std::size_t> sizes;
        std::atomic<int> running(0), maxRunning(0);
        levenbergMarquardt concurrent(pars, o);
        concurrent.setBatchResidual
        (
            [&](std::vector<Evaluation>& batch)
            {
                sizes.insert(batch.size());
                std::vector<std::thread> threads;
                for (Evaluation& e : batch)
                {
                    threads.emplace_back
                    (
                        [&thurber, &e, &running, &maxRunning]()
                        {
                            const int now = ++running;
                            int seen = maxRunning.load();
                            while (now > seen && !maxRunning.compare_exchange_weak(seen, now)) {}
                            e.ok = nistResiduals(thurber, e.parameters, e.residuals);
                            std::this_thread::sleep_for(std::chrono::microseconds(200));
                            --running;
                        }
                    );
                }
                for (std::thread& t : threads) t.join();
            }
        );
        const FitResult Rc = concurrent.solve();
        const std::string tag =
            std::string("Thurber start 2 ") + (central ? "central" : "forward");

        std::string list;
        for (std::size_t z : sizes) list += std::to_string(z) + " ";
        checkTrue
        (
            tag + ": batch sizes: 1 (trials), " + (central ? "" : "7, ")
          + "14 (Jacobians, final central)",
            sizes == (central ? std::set<std::size_t>{1, 14}
                              : std::set<std::size_t>{1, 7, 14}),
            list
        );
        checkTrue
        (
            tag + ": concurrent batches ran at once (threads > 1)",
            maxRunning.load() > 1, std::to_string(maxRunning.load())
        );
        check
        (
            tag + ": concurrent vs serial, largest parameter difference",
            (Rc.parameters - Rs.parameters).cwiseAbs().maxCoeff(), 0
        );
        checkCertified(tag + " concurrent", thurber, Rc);
    }

    // Progress: one line per iteration, non-increasing cost
    {
        std::vector<FitProgress> lines;
        levenbergMarquardt lm(nistParameters(misra, misra.start1), nistOptions());
        lm.setResidual
        (
            [&](const Vector& b, Vector& r) { return nistResiduals(misra, b, r); }
        );
        lm.setProgress([&](const FitProgress& p) { lines.push_back(p); });
        const FitResult R = lm.solve();

        bool monotone = true, consecutive = true;
        for (std::size_t k = 0; k < lines.size(); ++k)
        {
            if (int(k) != lines[k].iteration) consecutive = false;
            if (k && lines[k].cost > lines[k - 1].cost) monotone = false;
        }
        checkTrue
        (
            "progress: lines = iterations + 1, numbered 0, 1, ...",
            consecutive && int(lines.size()) == R.iterations + 1,
            std::to_string(lines.size()) + " lines"
        );
        checkTrue("progress: cost non-increasing", monotone, "");
        checkTrue
        (
            "progress: last line = result (cost, evaluations, stop)",
            !lines.empty() && lines.back().cost == R.cost
         && lines.back().parameters == R.parameters
         && lines.back().event.find("stop") != std::string::npos,
            lines.empty() ? "" : lines.back().event
        );
        std::printf("      progress of Misra1a start 1 (iteration cost damping evaluations b1 b2):\n");
        for (const FitProgress& p : lines)
        {
            std::printf
            (
                "      %3d %.10e %9.3e %4ld %.8e %.8e %s\n",
                p.iteration, p.cost, p.damping, p.evaluations,
                p.parameters(0), p.parameters(1), p.event.c_str()
            );
        }
    }

    // Stopping: iteration and evaluation caps
    {
        FitOptions o = nistOptions();
        o.maxIterations = 3;
        const FitResult R =
            fitNist(misra, nistParameters(misra, misra.start1), o);
        checkTrue
        (
            "maxIterations 3: status maxIterations after 3 iterations",
            R.status == FitStatus::maxIterations && R.iterations == 3
         && !R.converged,
            statusName(R.status) + ", " + std::to_string(R.iterations)
        );

        o = nistOptions();
        o.maxEvaluations = 20;
        const FitResult R2 =
            fitNist(misra, nistParameters(misra, misra.start1), o);
        checkTrue
        (
            "maxEvaluations 20: status maxEvaluations",
            R2.status == FitStatus::maxEvaluations && R2.evaluations >= 20
         && R2.evaluations < 20 + 3 + 2,
            statusName(R2.status) + ", " + std::to_string(R2.evaluations)
        );

        // Loose tolerances stop earlier, on the named criterion
        o = nistOptions();
        o.tolGradient = 1e-3;
        const FitResult R3 =
            fitNist(misra, nistParameters(misra, misra.start1), o);
        checkTrue
        (
            "tolGradient 1e-3: status gradientTolerance",
            R3.status == FitStatus::gradientTolerance, statusName(R3.status)
        );
        o = nistOptions();
        o.tolCost = 1e-4;
        const FitResult R4 =
            fitNist(misra, nistParameters(misra, misra.start1), o);
        checkTrue
        (
            "tolCost 1e-4: status costTolerance",
            R4.status == FitStatus::costTolerance, statusName(R4.status)
        );
        o = nistOptions();
        o.tolStep = 1e-3;
        const FitResult R5 =
            fitNist(misra, nistParameters(misra, misra.start1), o);
        checkTrue
        (
            "tolStep 1e-3: status stepTolerance",
            R5.status == FitStatus::stepTolerance, statusName(R5.status)
        );
    }

    // Resume: 5 iterations, then a new fit from there with the reported
    // damping ends at the certified values
    {
        const nistProblem& mgh09 = find(problems, "MGH09");
        FitOptions o = nistOptions();
        o.maxIterations = 5;
        const FitResult R1 =
            fitNist(mgh09, nistParameters(mgh09, mgh09.start1), o);
        std::vector<double> from(R1.parameters.data(), R1.parameters.data() + 4);
        std::vector<FitParameter> pars = nistParameters(mgh09, from);
        for (int j = 0; j < 4; ++j) pars[j].typical = 1e-2*std::abs(mgh09.start1[j]);
        o = nistOptions();
        o.initialDamping = R1.damping;
        checkCertified
        (
            "resumed after 5 iterations MGH09 start 1", mgh09,
            fitNist(mgh09, pars, o)
        );
    }
}


// Input checks
static void testInput()
{
    auto throws = [](std::vector<FitParameter> pars, FitOptions o)
    {
        try
        {
            levenbergMarquardt lm(pars, o);
        }
        catch (const std::invalid_argument& e)
        {
            return std::string(e.what());
        }
        return std::string();
    };
    std::vector<FitParameter> good(1);
    good[0].name = "k";
    good[0].initial = 1;
    const FitOptions o;

    std::vector<FitParameter> p = good;
    p[0].lower = 2; p[0].upper = 1; p[0].initial = 1.5;
    std::string w = throws(p, o);
    checkTrue("input: inverted bounds throw", !w.empty(), w);

    p = good; p[0].lower = 2;
    w = throws(p, o);
    checkTrue("input: initial value outside bounds throws", !w.empty(), w);

    p = good; p[0].transform = Transform::log; p[0].initial = -1; p[0].lower = -2;
    w = throws(p, o);
    checkTrue("input: log transform of a negative value throws", !w.empty(), w);

    p = good; p[0].initial = 0;
    w = throws(p, o);
    checkTrue("input: linear parameter at 0 without typical throws", !w.empty(), w);
    p[0].typical = 1e-3;
    checkTrue("input: ... with typical accepted", throws(p, o).empty(), "");

    FitOptions bad; bad.hRel = 0;
    w = throws(good, bad);
    checkTrue("input: hRel = 0 throws", !w.empty(), w);

    w = throws(std::vector<FitParameter>(), o);
    checkTrue("input: no parameters throws", !w.empty(), w);
}


// Statistics: t quantile, intervals, correlation, singular values
static void testStatistics(const std::vector<nistProblem>& problems)
{
    const nistProblem& misra = find(problems, "Misra1a");
    const FitResult R =
        fitNist(misra, nistParameters(misra, misra.start2), nistOptions());

    // t_{0.975, 12} = 2.178812829663418 (tables: 2.179)
    check
    (
        "statistics Misra1a: dof = 12, t(0.975, 12) - 2.1788128297",
        std::abs(R.tQuantile - 2.1788128297) + std::abs(R.dof - 12), 1e-9
    );
    check
    (
        "statistics Misra1a: s^2 vs certified residual SD^2, relative",
        relErr(R.sigma2, 1.0187876330E-01*1.0187876330E-01), 1e-6
    );
    double e = 0;
    for (int j = 0; j < 2; ++j)
    {
        e = std::max(e, std::abs(R.lowerConfidence(j) - (R.parameters(j) - R.tQuantile*R.standardErrors(j))));
        e = std::max(e, std::abs(R.upperConfidence(j) - (R.parameters(j) + R.tQuantile*R.standardErrors(j))));
    }
    check("statistics Misra1a: intervals = b -/+ t se", e, 1e-12);
    check
    (
        "statistics Misra1a: 95 % interval of b1 contains the certified value",
        double(!(R.lowerConfidence(0) < misra.certified[0]
              && misra.certified[0] < R.upperConfidence(0))), 0
    );
    check
    (
        "statistics Misra1a: correlation: |diag - 1| + asymmetry",
        (R.correlation.diagonal().array() - 1).abs().maxCoeff()
      + (R.correlation - R.correlation.transpose()).cwiseAbs().maxCoeff(),
        1e-12
    );
    check
    (
        "statistics Misra1a: |corr(b1, b2)| < 1",
        std::abs(R.correlation(0, 1)), 1 - 1e-9
    );
    std::printf
    (
        "      Misra1a: corr(b1,b2) %.6f, scaled singular values %.6e %.6e,"
        " 95%% intervals [%.6g, %.6g] [%.6g, %.6g]\n",
        R.correlation(0, 1), R.singularValues(0), R.singularValues(1),
        R.lowerConfidence(0), R.upperConfidence(0),
        R.lowerConfidence(1), R.upperConfidence(1)
    );
    checkTrue
    (
        "statistics Misra1a: rank 2, singular values descending",
        R.rank == 2 && R.singularValues(0) >= R.singularValues(1)
     && R.singularValues(1) > 0, std::to_string(R.rank)
    );

    // Covariance = s^2 (J^T J)^-1 with the analytic Jacobian (the test's
    // own, not the optimiser's)
    {
        const double b1 = R.parameters(0), b2 = R.parameters(1);
        Matrix J(misra.x.size(), 2);
        for (std::size_t i = 0; i < misra.x.size(); ++i)
        {
            const double x = misra.x[i];
            J(i, 0) = 1 - std::exp(-b2*x);
            J(i, 1) = b1*x*std::exp(-b2*x);
        }
        const Matrix C = R.sigma2*(J.transpose()*J).inverse();
        check
        (
            "statistics Misra1a: covariance vs analytic s^2 (J^T J)^-1, relative",
            ((C - R.covariance).cwiseAbs().array()/C.cwiseAbs().array()).maxCoeff(),
            1e-6
        );
    }

    // Statistics alone at the certified parameters (Thurber)
    {
        const nistProblem& th = find(problems, "Thurber");
        levenbergMarquardt lm(nistParameters(th, th.start1), nistOptions());
        lm.setResidual
        (
            [&](const Vector& b, Vector& r) { return nistResiduals(th, b, r); }
        );
        FitResult S;
        const bool ok = lm.statistics(vec(th.certified), S);
        double worst = 0;
        for (int j = 0; j < th.nPar; ++j)
        {
            worst = std::max(worst, relErr(S.standardErrors(j), th.certifiedSD[j]));
        }
        check
        (
            "statistics() at certified Thurber: worst sd relative error",
            ok ? worst : 1.0, 1e-4
        );
        std::printf("      Thurber scaled singular values:");
        for (int j = 0; j < S.singularValues.size(); ++j)
        {
            std::printf(" %.3e", S.singularValues(j));
        }
        std::printf("\n");
    }

    // Rank-deficient: a parameter that does not act -> rank n-1, NaN se
    {
        std::vector<FitParameter> pars = nistParameters(misra, misra.start2);
        pars.push_back(FitParameter());
        pars.back().name = "idle";
        pars.back().initial = 1;
        levenbergMarquardt lm(pars, nistOptions());
        lm.setResidual
        (
            [&](const Vector& b, Vector& r) { return nistResiduals(misra, b.head(2), r); }
        );
        const FitResult Ri = lm.solve();
        checkTrue
        (
            "statistics: idle parameter: rank 2 of 3, its se NaN, fit converged",
            Ri.rank == 2 && std::isnan(Ri.standardErrors(2)) && Ri.converged
         && relErr(Ri.parameters(0), misra.certified[0]) < 1e-6,
            std::to_string(Ri.rank) + ", " + Ri.message
        );
    }
}


// The finite-difference step rule with a noisy model
static double noise(const Vector& b, std::size_t i)
{
    // Deterministic "solver noise" in [-1, 1] from the parameter bits
    std::uint64_t h = 0x9E3779B97F4A7C15ull*(i + 1);
    for (int j = 0; j < b.size(); ++j)
    {
        std::uint64_t bits;
        const double v = b(j);
        std::memcpy(&bits, &v, sizeof bits);
        h ^= bits + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2);
    }
    h ^= h >> 30; h *= 0xBF58476D1CE4E5B9ull;
    h ^= h >> 27; h *= 0x94D049BB133111EBull;
    h ^= h >> 31;
    return 2.0*(double(h >> 11)/double(1ull << 53)) - 1.0;
}


static void testStepRule(const std::vector<nistProblem>& problems)
{
    const nistProblem& misra = find(problems, "Misra1a");
    const double eps = 1e-6;        // relative noise of the model output

    auto residual = [&](const Vector& b, Vector& r)
    {
        r.resize(misra.y.size());
        for (std::size_t i = 0; i < misra.y.size(); ++i)
        {
            const double f = misra.model(misra.x[i], b.data());
            r(i) = f*(1 + eps*noise(b, i)) - misra.y[i];
        }
        return true;
    };

    auto run = [&](Difference d, double hRel, const std::string& name)
    {
        FitOptions o = nistOptions();
        o.difference = d;
        o.hRel = hRel;
        o.tolStep = 1e-8;
        o.finalDifference = Difference::central;
        o.finalHRel = levenbergMarquardt::recommendedRelativeStep(eps, Difference::central);
        levenbergMarquardt lm(nistParameters(misra, misra.start1), o);
        lm.setResidual(residual);
        const FitResult R = lm.solve();
        double err = 0;
        for (int j = 0; j < 2; ++j)
        {
            err = std::max(err, std::abs(R.parameters(j) - misra.certified[j])/misra.certifiedSD[j]);
        }
        std::printf
        (
            "      noise 1e-6, %s hRel %.1e: %s, %d iterations, "
            "largest |b - certified|/sd %.3e\n",
            name.c_str(), hRel, R.message.c_str(), R.iterations, err
        );
        return err;
    };

    const double hF = levenbergMarquardt::recommendedRelativeStep(eps, Difference::forward);
    const double hC = levenbergMarquardt::recommendedRelativeStep(eps, Difference::central);
    const double eF = run(Difference::forward, hF, "forward, rule");
    const double eC = run(Difference::central, hC, "central, rule");
    const double eTiny = run(Difference::forward, 1e-10, "forward, too small");

    // The noise makes the cost itself uncertain (relative 1e-6 of f ~ 50
    // on residuals ~ 0.1: ~3e-4 of S), which blurs the minimum by
    // ~ sqrt(3e-4 (m - n)) ~ 0.06 sd: no fit of this noisy model can do
    // better than a few hundredths of a standard deviation
    check("step rule, noise 1e-6: forward 2 sqrt(eps): |b - cert|/sd", eF, 0.1);
    check("step rule, noise 1e-6: central (3 eps)^(1/3): |b - cert|/sd", eC, 0.1);
    checkAtLeast
    (
        "step rule, noise 1e-6: error with hRel 1e-10 / error with the rule",
        eTiny/std::max(eF, 1e-300), 10
    );
}


// The stop at the model's precision (FitOptions::solverNoise): the noisy
// Misra1a of testStepRule (relative noise 1e-6 of f, uniform: eta ~
// 1e-6 f/sqrt(3) per residual, f up to ~ 240) fitted with the tolerances
// of the step-rule test alone, then with the noise stop (solverNoise =
// the noise declared, 1e-6): fewer evaluations, the estimates within 0.1
// standard error of the tolerance-stopped ones (the noise stop's own
// guarantee: the Gauss-Newton step left <= 0.1 standard error); and with
// a noise at machine precision (a closed-form model) every NIST problem
// still reaches its certified values (see below)
static void testNoiseStop(const std::vector<nistProblem>& problems)
{
    const nistProblem& misra = find(problems, "Misra1a");
    const double eps = 1e-6;
    auto residual = [&](const Vector& b, Vector& r)
    {
        r.resize(misra.y.size());
        for (std::size_t i = 0; i < misra.y.size(); ++i)
        {
            const double f = misra.model(misra.x[i], b.data());
            r(i) = f*(1 + eps*noise(b, i)) - misra.y[i];
        }
        return true;
    };
    auto run = [&](double solverNoise)
    {
        FitOptions o = nistOptions();
        o.hRel = levenbergMarquardt::recommendedRelativeStep(eps, Difference::forward);
        o.tolStep = 1e-8;
        o.finalHRel = levenbergMarquardt::recommendedRelativeStep(eps, Difference::central);
        o.solverNoise = solverNoise;
        levenbergMarquardt lm(nistParameters(misra, misra.start1), o);
        lm.setResidual(residual);
        return lm.solve();
    };
    const FitResult R0 = run(0);
    const FitResult R1 = run(eps);
    double dSE = 0;
    for (int j = 0; j < 2; ++j)
    {
        dSE = std::max
        (
            dSE, std::abs(R1.parameters(j) - R0.parameters(j))/R0.standardErrors(j)
        );
    }
    std::printf
    (
        "      noisy Misra1a (noise 1e-6): tolerances: %s, %d iterations, %ld"
        " evaluations; noise stop: %s, %d iterations, %ld evaluations\n"
        "      noise stop: model noise eta %.3e per residual, cost noise"
        " %.3e, Gauss-Newton decrease left %.3e\n",
        R0.message.c_str(), R0.iterations, R0.evaluations,
        R1.message.c_str(), R1.iterations, R1.evaluations,
        R1.modelNoise, R1.costNoise, R1.gaussNewtonDecrease
    );
    checkTrue
    (
        "noise stop, noisy Misra1a: status noiseLevel (converged)",
        R1.status == FitStatus::noiseLevel && R1.converged, R1.message
    );
    checkAtLeast
    (
        "noise stop, noisy Misra1a: evaluations saved",
        double(R0.evaluations - R1.evaluations), 1
    );
    check
    (
        "noise stop, noisy Misra1a: max |b - b(tolerances)|/sd", dSE, 0.1
    );
    // The declared noise against the true one: eta is eps times the
    // least sensitive column's largest value, the true standard deviation
    // of a residual eps |f|/sqrt(3) (f up to max|y|): same order
    double fMax = 0;
    for (double y : misra.y) fMax = std::max(fMax, std::abs(y));
    const double ratio = R1.modelNoise/(eps*fMax/std::sqrt(3.0));
    std::printf("      eta / (eps max|f|/sqrt(3)) = %.3f\n", ratio);
    checkTrue
    (
        "noise stop: eta within a factor 10 of the true noise",
        ratio > 0.1 && ratio < 10, fmt("%g", ratio)
    );

    // Machine-precision noise (a closed-form model, a "tight" noise): the
    // noise stop may come a few iterations earlier, where the decrease
    // left is at rounding level, and the fit ends where the tolerances
    // end it: the certified values (checkCertified: 1e-6 relative,
    // standard deviations 1e-3), the estimates within 0.1 standard error
    // of the tolerance-stopped fit's (the noise stop's guarantee; measured
    // 6.5e-7 at most, MGH17), no more evaluations
    for (const nistProblem& P : problems)
    {
        FitOptions o = nistOptions();
        const FitResult A = fitNist(P, nistParameters(P, P.start1), o);
        o.solverNoise = std::numeric_limits<double>::epsilon();
        const FitResult B = fitNist(P, nistParameters(P, P.start1), o);
        checkCertified(P.name + " start 1, solverNoise = machine epsilon", P, B);
        double d = 0;
        for (int j = 0; j < P.nPar; ++j)
        {
            d = std::max
            (
                d, std::abs(B.parameters(j) - A.parameters(j))/A.standardErrors(j)
            );
        }
        std::printf
        (
            "      %s: tolerances %ld evaluations (%s), noise stop %ld (%s)\n",
            P.name.c_str(), A.evaluations, statusName(A.status).c_str(),
            B.evaluations, statusName(B.status).c_str()
        );
        check
        (
            P.name + ", machine-precision noise: max |b - b(tolerances)|/sd",
            d, 0.1
        );
        check
        (
            P.name + ", machine-precision noise: evaluations - tolerances'",
            double(B.evaluations - A.evaluations), 0
        );
    }
}


int main()
{
    const std::vector<nistProblem> problems = nistProblems();

    testNist(problems);
    testVariants(problems);
    testFailures(problems);
    testBounds(problems);
    testInterface(problems);
    testInput();
    testStatistics(problems);
    testStepRule(problems);
    testNoiseStop(problems);

    std::printf("%d checks, %d failed\n", nChecks, nFailed);
    return nFailed ? 1 : 0;
}
