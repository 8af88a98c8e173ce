/*---------------------------------------------------------------------------*\
  hearthFoam: hearthFit optimiser core (see levenbergMarquardt.H)
\*---------------------------------------------------------------------------*/

#include "levenbergMarquardt.H"

#include <gsl/gsl_cdf.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace hearthFit
{

namespace
{

const double inf = std::numeric_limits<double>::infinity();
const double nan = std::numeric_limits<double>::quiet_NaN();

std::string str(double x)
{
    std::ostringstream os;
    os.precision(10);
    os << x;
    return os.str();
}

} // End anonymous namespace


std::string statusName(FitStatus s)
{
    switch (s)
    {
        case FitStatus::gradientTolerance: return "gradientTolerance";
        case FitStatus::stepTolerance: return "stepTolerance";
        case FitStatus::costTolerance: return "costTolerance";
        case FitStatus::zeroResidual: return "zeroResidual";
        case FitStatus::maxIterations: return "maxIterations";
        case FitStatus::maxEvaluations: return "maxEvaluations";
        case FitStatus::dampingLimit: return "dampingLimit";
        case FitStatus::initialEvaluationFailed:
            return "initialEvaluationFailed";
        case FitStatus::jacobianFailed: return "jacobianFailed";
        case FitStatus::noiseLevel: return "noiseLevel";
        case FitStatus::stalledAtFailures: return "stalledAtFailures";
    }
    return "unknown";
}


std::string chiSquareBandVerdict
(
    const FitResult& res,
    double confidence,
    bool* inside
)
{
    const bool in =
        res.sigma2 >= res.sigma2Lower && res.sigma2 <= res.sigma2Upper;
    if (inside)
    {
        *inside = in;
    }
    std::ostringstream os;
    os  << std::setprecision(4) << "s^2 = " << res.sigma2 << " is "
        << (in ? "inside" : "outside") << " its " << 100*confidence
        << " % chi-square band [" << res.sigma2Lower << ", "
        << res.sigma2Upper << "]";
    if (!in)
    {
        os  << ": "
            << (
                   res.sigma2 > res.sigma2Upper
                 ? "model error (the model cannot reproduce the data:"
                   " discretisation, physics, fixed parameters) or a sigma"
                   " too small"
                 : "a sigma too large (or data fitted by the model itself)"
               );
    }
    return os.str();
}


bool statusConverged(FitStatus s)
{
    return
        s == FitStatus::gradientTolerance
     || s == FitStatus::stepTolerance
     || s == FitStatus::costTolerance
     || s == FitStatus::noiseLevel
     || s == FitStatus::zeroResidual;
}


double levenbergMarquardt::recommendedRelativeStep(double eps, Difference d)
{
    eps = std::max(eps, std::numeric_limits<double>::epsilon());
    return
        d == Difference::forward
      ? 2*std::sqrt(eps)
      : std::cbrt(3*eps);
}


// * * * * * * * * * * * * * * * * Constructor  * * * * * * * * * * * * * * //

levenbergMarquardt::levenbergMarquardt
(
    const std::vector<FitParameter>& parameters,
    const FitOptions& options
)
:
    params_(parameters),
    opts_(options),
    n_(int(parameters.size())),
    m_(-1),
    typical_(parameters.size()),
    uLower_(parameters.size()),
    uUpper_(parameters.size()),
    evaluations_(0),
    failed_(0),
    batches_(0)
{
    if (n_ == 0)
    {
        throw std::invalid_argument("levenbergMarquardt: no parameters");
    }

    for (int j = 0; j < n_; ++j)
    {
        const FitParameter& q = params_[j];
        const std::string who =
            "levenbergMarquardt: parameter " + std::to_string(j + 1)
          + (q.name.empty() ? "" : " (" + q.name + ")") + ": ";

        if (!std::isfinite(q.initial))
        {
            throw std::invalid_argument(who + "initial value not finite");
        }
        if (std::isnan(q.lower) || std::isnan(q.upper))
        {
            throw std::invalid_argument(who + "bound is NaN");
        }
        if (!(q.lower < q.upper))
        {
            throw std::invalid_argument
            (
                who + "inverted or empty bounds: lower " + str(q.lower)
              + " >= upper " + str(q.upper)
            );
        }
        if (q.initial < q.lower || q.initial > q.upper)
        {
            throw std::invalid_argument
            (
                who + "initial value " + str(q.initial) + " outside ["
              + str(q.lower) + ", " + str(q.upper) + "]"
            );
        }
        if (!(q.typical >= 0) || !std::isfinite(q.typical))
        {
            throw std::invalid_argument(who + "typical must be >= 0");
        }

        if (q.typical == 0 && q.initial == 0)
        {
            if (q.transform == Transform::linear)
            {
                throw std::invalid_argument
                (
                    who + "starts at 0: give its typical magnitude"
                    " (finite-difference step floor)"
                );
            }
        }
        if (!(q.sensitivityScale >= 0) || !std::isfinite(q.sensitivityScale))
        {
            throw std::invalid_argument(who + "sensitivityScale must be >= 0");
        }
        typical_(j) = q.typical > 0 ? q.typical : 1e-2*std::abs(q.initial);

        if (q.transform == Transform::log)
        {
            if (!(q.initial > 0))
            {
                throw std::invalid_argument
                (
                    who + "log transform needs a positive initial value, not "
                  + str(q.initial)
                );
            }
            uLower_(j) = q.lower > 0 ? std::log(q.lower) : -inf;
            uUpper_(j) = std::log(q.upper);     // upper > initial > 0
        }
        else
        {
            uLower_(j) = q.lower/typical_(j);
            uUpper_(j) = q.upper/typical_(j);
        }
    }

    const FitOptions& o = opts_;
    if (!(o.hRel > 0 && o.hRel < 0.5))
    {
        throw std::invalid_argument("levenbergMarquardt: hRel not in (0, 0.5)");
    }
    if (!(o.finalHRel >= 0 && o.finalHRel < 0.5))
    {
        throw std::invalid_argument
        (
            "levenbergMarquardt: finalHRel not in [0, 0.5)"
        );
    }
    if (!(o.tolStep >= 0 && o.tolGradient >= 0 && o.tolCost >= 0))
    {
        throw std::invalid_argument
        (
            "levenbergMarquardt: negative tolerance"
        );
    }
    if (o.maxIterations < 1 || o.maxEvaluations < 0)
    {
        throw std::invalid_argument
        (
            "levenbergMarquardt: maxIterations must be >= 1,"
            " maxEvaluations >= 0"
        );
    }
    if (!(o.initialDamping > 0) || !(o.maxDamping > o.initialDamping))
    {
        throw std::invalid_argument
        (
            "levenbergMarquardt: need 0 < initialDamping < maxDamping"
        );
    }
    if (!(o.confidence > 0 && o.confidence < 1))
    {
        throw std::invalid_argument
        (
            "levenbergMarquardt: confidence not in (0, 1)"
        );
    }
    if
    (
        !(o.solverNoise >= 0 && o.solverNoise < 1)
     || !(o.noiseStopStdError > 0)
    )
    {
        throw std::invalid_argument
        (
            "levenbergMarquardt: need 0 <= solverNoise < 1 and"
            " noiseStopStdError > 0"
        );
    }
    if (!(o.geodesicAlpha > 0 && o.geodesicStep > 0))
    {
        throw std::invalid_argument
        (
            "levenbergMarquardt: geodesicAlpha and geodesicStep must be > 0"
        );
    }
}


void levenbergMarquardt::setBatchResidual(const BatchResidual& f)
{
    batch_ = f;
}


void levenbergMarquardt::setResidual(const Residual& f)
{
    batch_ = [f](std::vector<Evaluation>& batch)
    {
        for (Evaluation& e : batch)
        {
            e.ok = f(e.parameters, e.residuals);
        }
    };
}


void levenbergMarquardt::setProgress(const ProgressCallback& f)
{
    progress_ = f;
}


// * * * * * * * * * * * * * * * Transforms * * * * * * * * * * * * * * * * //

Vector levenbergMarquardt::toInternal(const Vector& p) const
{
    Vector u(n_);
    for (int j = 0; j < n_; ++j)
    {
        u(j) =
            params_[j].transform == Transform::log
          ? std::log(p(j))
          : p(j)/typical_(j);
    }
    return u;
}


Vector levenbergMarquardt::toPhysical(const Vector& u) const
{
    Vector p(n_);
    for (int j = 0; j < n_; ++j)
    {
        p(j) =
            params_[j].transform == Transform::log
          ? std::exp(u(j))
          : u(j)*typical_(j);
    }
    return clampPhysical(p);
}


Vector levenbergMarquardt::dpdu(const Vector& u) const
{
    Vector d(n_);
    for (int j = 0; j < n_; ++j)
    {
        d(j) =
            params_[j].transform == Transform::log
          ? std::exp(u(j))
          : typical_(j);
    }
    return d;
}


Vector levenbergMarquardt::clampInternal(const Vector& u) const
{
    return u.cwiseMax(uLower_).cwiseMin(uUpper_);
}


Vector levenbergMarquardt::clampPhysical(const Vector& p) const
{
    Vector q(p);
    for (int j = 0; j < n_; ++j)
    {
        q(j) = std::min(std::max(q(j), params_[j].lower), params_[j].upper);
        if (params_[j].transform == Transform::log && !(q(j) > 0))
        {
            q(j) = std::numeric_limits<double>::min();
        }
    }
    return q;
}


double levenbergMarquardt::relativeStep
(
    const Vector& p0,
    const Vector& p1
) const
{
    double s = 0;
    for (int j = 0; j < n_; ++j)
    {
        const double d =
            params_[j].transform == Transform::log
          ? std::abs(std::log(p1(j)/p0(j)))
          : std::abs(p1(j) - p0(j))/std::max(std::abs(p1(j)), typical_(j));
        s = std::max(s, d);
    }
    return s;
}


// * * * * * * * * * * * * * * * Evaluations  * * * * * * * * * * * * * * * //

void levenbergMarquardt::evaluate(std::vector<Evaluation>& batch)
{
    if (batch.empty())
    {
        return;
    }
    for (Evaluation& e : batch)
    {
        e.ok = false;
        e.residuals.resize(0);
    }

    batch_(batch);

    ++batches_;
    evaluations_ += long(batch.size());

    for (Evaluation& e : batch)
    {
        if (e.ok)
        {
            if (e.residuals.size() == 0 || !e.residuals.allFinite())
            {
                e.ok = false;
            }
            else if (m_ < 0)
            {
                m_ = e.residuals.size();
            }
            else if (e.residuals.size() != m_)
            {
                e.ok = false;
            }
        }
        if (!e.ok)
        {
            ++failed_;
        }
    }
}


bool levenbergMarquardt::evaluateOne(const Vector& p, Vector& r)
{
    std::vector<Evaluation> b(1);
    b[0].parameters = p;
    evaluate(b);
    if (b[0].ok)
    {
        r.swap(b[0].residuals);
    }
    return b[0].ok;
}


bool levenbergMarquardt::jacobian
(
    const Vector& p,
    const Vector& r0,
    Difference d,
    double hRel,
    Matrix& J
)
{
    const long m = r0.size();
    J.resize(m, n_);

    // Nominal steps (rule in the header)
    Vector h(n_);
    for (int j = 0; j < n_; ++j)
    {
        const double base =
            params_[j].transform == Transform::log
          ? std::abs(p(j))
          : std::max(std::abs(p(j)), typical_(j));
        h(j) = hRel*base;
    }

    // Perturbed parameter vector along j by signed step s (clamped to the
    // box for safety; the step actually taken is returned in hActual)
    auto perturbed = [&](int j, double s, double& hActual)
    {
        Vector q(p);
        q(j) = std::min
        (
            std::max(p(j) + s, params_[j].lower), params_[j].upper
        );
        hActual = q(j) - p(j);
        return q;
    };

    auto fits = [&](int j, double s)
    {
        const double x = p(j) + s;
        return
            x >= params_[j].lower && x <= params_[j].upper
         && (params_[j].transform != Transform::log || x > 0);
    };

    // Round 0: the scheme asked for; one-sided near a bound
    struct Attempt { int j; double s; };
    std::vector<Attempt> attempts;
    std::vector<int> nDone(n_, 0);      // 0: unresolved, 1: resolved

    for (int j = 0; j < n_; ++j)
    {
        const bool plus = fits(j, h(j)), minus = fits(j, -h(j));
        if (d == Difference::central && plus && minus)
        {
            attempts.push_back({j, h(j)});
            attempts.push_back({j, -h(j)});
        }
        else if (plus)
        {
            attempts.push_back({j, h(j)});
        }
        else if (minus)
        {
            attempts.push_back({j, -h(j)});
        }
        else
        {
            // Box narrower than the step: use the larger room
            const double up = params_[j].upper - p(j);
            const double down = p(j) - params_[j].lower;
            attempts.push_back({j, up >= down ? up : -down});
        }
    }

    for (int round = 0; round < 3; ++round)
    {
        if (attempts.empty())
        {
            break;
        }

        std::vector<Evaluation> batch(attempts.size());
        std::vector<double> hAct(attempts.size());
        for (std::size_t k = 0; k < attempts.size(); ++k)
        {
            batch[k].parameters =
                perturbed(attempts[k].j, attempts[k].s, hAct[k]);
        }
        evaluate(batch);

        // Collect per column
        std::vector<int> okPlus(n_, -1), okMinus(n_, -1);
        for (std::size_t k = 0; k < attempts.size(); ++k)
        {
            const int j = attempts[k].j;
            if (hAct[k] == 0)
            {
                batch[k].ok = false;
            }
            if (hAct[k] > 0 || (hAct[k] == 0 && attempts[k].s > 0))
            {
                okPlus[j] = int(k);
            }
            else
            {
                okMinus[j] = int(k);
            }
        }

        std::vector<Attempt> retry;
        for (int j = 0; j < n_; ++j)
        {
            const int kp = okPlus[j], km = okMinus[j];
            if (kp < 0 && km < 0)
            {
                continue;   // column not in this round
            }
            const bool gp = kp >= 0 && batch[kp].ok;
            const bool gm = km >= 0 && batch[km].ok;

            if (gp && gm)
            {
                J.col(j) =
                    (batch[kp].residuals - batch[km].residuals)
                   /(hAct[kp] - hAct[km]);
                nDone[j] = 1;
            }
            else if (gp || gm)
            {
                const int k = gp ? kp : km;
                J.col(j) = (batch[k].residuals - r0)/hAct[k];
                nDone[j] = 1;
            }
            else
            {
                // Failed: round 0 -> other side (same step) when it fits
                // and was not tried; round 1 -> a ten times smaller step
                const double sTried =
                    kp >= 0 ? attempts[kp].s : attempts[km].s;
                if (round == 0 && km < 0 && fits(j, -std::abs(sTried)))
                {
                    retry.push_back({j, -std::abs(sTried)});
                }
                else if (round == 0 && kp < 0 && fits(j, std::abs(sTried)))
                {
                    retry.push_back({j, std::abs(sTried)});
                }
                else if (round <= 1)
                {
                    const double s = 0.1*std::abs(sTried);
                    retry.push_back({j, fits(j, s) ? s : -s});
                }
            }
        }
        attempts.swap(retry);
    }

    for (int j = 0; j < n_; ++j)
    {
        if (!nDone[j])
        {
            return false;
        }
    }
    return true;
}


// * * * * * * * * * * * * * * * * Statistics * * * * * * * * * * * * * * * //

void levenbergMarquardt::computeStatistics
(
    const Vector& p,
    const Vector& r,
    const Matrix& J,
    FitResult& res
) const
{
    const long m = r.size();
    res.jacobian = J;
    res.dof = int(m) - n_;
    res.sigma2 = res.dof > 0 ? r.squaredNorm()/res.dof : nan;
    // Known noise (residuals divided by the true sigma): the covariance is
    // (J^T J)^-1 and the quantile normal; s^2 should lie in its
    // chi-square band (chi^2_dof/dof). Unknown: s^2 (J^T J)^-1 and t
    res.knownSigma = opts_.knownSigma;
    // (with a known sigma the covariance needs no residual degree of
    // freedom: m = n is enough, e.g. one observation of one parameter)
    res.tQuantile =
        opts_.knownSigma && res.dof >= 0
      ? gsl_cdf_ugaussian_Pinv(0.5*(1 + opts_.confidence))
      : res.dof > 0
      ? gsl_cdf_tdist_Pinv(0.5*(1 + opts_.confidence), res.dof)
      : nan;
    res.sigma2Lower =
        res.dof > 0
      ? gsl_cdf_chisq_Pinv(0.5*(1 - opts_.confidence), res.dof)/res.dof
      : nan;
    res.sigma2Upper =
        res.dof > 0
      ? gsl_cdf_chisq_Pinv(0.5*(1 + opts_.confidence), res.dof)/res.dof
      : nan;

    // Scaled Jacobian: sensitivity to a relative change of each parameter
    Vector scale(n_);
    for (int j = 0; j < n_; ++j)
    {
        scale(j) =
            params_[j].sensitivityScale > 0 ? params_[j].sensitivityScale
          : p(j) != 0 ? std::abs(p(j))
          : typical_(j);
    }
    res.sensitivityScale = scale;
    const Matrix Js = J*scale.asDiagonal();

    Eigen::JacobiSVD<Matrix> svd(Js, Eigen::ComputeThinV);
    res.singularValues = svd.singularValues();
    res.singularVectors = svd.matrixV();

    const double smax =
        res.singularValues.size() ? res.singularValues(0) : 0.0;
    res.rank = 0;
    for (int i = 0; i < res.singularValues.size(); ++i)
    {
        if (res.singularValues(i) > 1e-12*smax && res.singularValues(i) > 0)
        {
            ++res.rank;
        }
    }

    res.covariance = Matrix::Constant(n_, n_, nan);
    res.correlation = Matrix::Constant(n_, n_, nan);
    res.standardErrors = Vector::Constant(n_, nan);
    res.lowerConfidence = Vector::Constant(n_, nan);
    res.upperConfidence = Vector::Constant(n_, nan);

    if (res.rank == n_ && (res.dof > 0 || (opts_.knownSigma && res.dof == 0)))
    {
        const Matrix& V = res.singularVectors;
        const Vector inv2 = res.singularValues.array().square().inverse();
        const Matrix covS = V*inv2.asDiagonal()*V.transpose();
        res.covariance =
            (opts_.knownSigma ? 1.0 : res.sigma2)
           *(scale.asDiagonal()*covS*scale.asDiagonal());

        for (int j = 0; j < n_; ++j)
        {
            res.standardErrors(j) = std::sqrt(res.covariance(j, j));
            res.lowerConfidence(j) = p(j) - res.tQuantile*res.standardErrors(j);
            res.upperConfidence(j) = p(j) + res.tQuantile*res.standardErrors(j);
        }
        // The correlation of the estimates is that of (J^T J)^-1 whatever
        // s^2 is: from covS when s^2 = 0 (a zero-residual fit: zero
        // covariance, zero-width intervals, and 0/0 here would trap)
        // (knownSigma first: with m = n, s^2 is NaN, and comparing a NaN
        // traps under OpenFOAM's FP exceptions)
        const bool zeroS2 = !opts_.knownSigma && !(res.sigma2 > 0);
        const Matrix& C = zeroS2 ? covS : res.covariance;
        for (int i = 0; i < n_; ++i)
        {
            for (int j = 0; j < n_; ++j)
            {
                const double d = std::sqrt(C(i, i)*C(j, j));
                res.correlation(i, j) = d > 0 ? C(i, j)/d : nan;
            }
        }
    }

    res.atBound.assign(n_, false);
    const Vector g = J.transpose()*r;
    const double rn = r.norm();
    res.scaledGradient = 0;
    for (int j = 0; j < n_; ++j)
    {
        const bool atLower = p(j) <= params_[j].lower;
        const bool atUpper = p(j) >= params_[j].upper;
        res.atBound[j] = atLower || atUpper;
        const double cn = J.col(j).norm();
        if ((atLower && g(j) > 0) || (atUpper && g(j) < 0) || cn == 0 || rn == 0)
        {
            continue;
        }
        res.scaledGradient =
            std::max(res.scaledGradient, std::abs(g(j))/(cn*rn));
    }
}


bool levenbergMarquardt::statistics(const Vector& p0, FitResult& res)
{
    if (!batch_)
    {
        throw std::logic_error("levenbergMarquardt: no residual function");
    }
    if (p0.size() != n_)
    {
        throw std::invalid_argument("levenbergMarquardt: wrong parameter count");
    }
    const Vector p = clampPhysical(p0);
    Vector r;
    if (!evaluateOne(p, r))
    {
        return false;
    }
    const double hF =
        opts_.finalHRel > 0 ? opts_.finalHRel
      : opts_.finalDifference == opts_.difference ? opts_.hRel
      : opts_.finalDifference == Difference::central
      ? std::pow(opts_.hRel, 2.0/3.0)
      : std::pow(opts_.hRel, 1.5);

    Matrix J;
    if (!jacobian(p, r, opts_.finalDifference, hF, J))
    {
        return false;
    }
    res.parameters = p;
    res.residuals = r;
    res.cost = r.squaredNorm();
    computeStatistics(p, r, J, res);
    return true;
}


bool levenbergMarquardt::initialLinearisation(Vector& p, Vector& r, Matrix& J)
{
    if (!batch_)
    {
        throw std::logic_error("levenbergMarquardt: no residual function");
    }
    // The point and steps of solve()'s first iteration
    p.resize(n_);
    for (int j = 0; j < n_; ++j)
    {
        p(j) = params_[j].initial;
    }
    p = clampPhysical(p);
    m_ = -1;
    return evaluateOne(p, r) && jacobian(p, r, opts_.difference, opts_.hRel, J);
}


// * * * * * * * * * * * * * * * * * * Fit  * * * * * * * * * * * * * * * * //

FitResult levenbergMarquardt::solve()
{
    if (!batch_)
    {
        throw std::logic_error("levenbergMarquardt: no residual function");
    }

    evaluations_ = 0;
    failed_ = 0;
    batches_ = 0;
    m_ = -1;

    const bool gn = opts_.method == Method::gaussNewton;

    FitResult res;
    Vector p(n_);
    for (int j = 0; j < n_; ++j)
    {
        p(j) = params_[j].initial;
    }
    p = clampPhysical(p);

    auto fillCounters = [&](FitResult& x)
    {
        x.evaluations = evaluations_;
        x.failedEvaluations = failed_;
        x.batches = batches_;
    };

    Vector r;
    if (!evaluateOne(p, r))
    {
        res.status = FitStatus::initialEvaluationFailed;
        res.converged = false;
        res.message = "the residuals at the initial parameters failed";
        res.parameters = p;
        res.cost = nan;
        fillCounters(res);
        return res;
    }

    double S = r.squaredNorm();
    Vector u = toInternal(p);
    double lambda = gn ? 0.0 : opts_.initialDamping;
    double nu = 2;
    Vector D2 = Vector::Zero(n_);
    int iter = 0;
    FitStatus status = FitStatus::maxIterations;
    std::string detail;

    Matrix Jp;
    bool JAtP = false;       // Jp was evaluated at the current p

    // Broyden updates between finite-difference Jacobians (FitOptions::
    // jacobianUpdates): JuB, the Jacobian in the internal variables
    // updated with every trial evaluated, is used for up to that many
    // iterations after each finite-difference one
    Matrix Ju, JuB;
    int broydenLeft = 0;
    int fdJacobians = 0, broydenJacobians = 0;

    {
        FitProgress pr;
        pr.iteration = 0;
        pr.cost = S;
        pr.parameters = p;
        pr.damping = lambda;
        pr.evaluations = evaluations_;
        pr.failedEvaluations = failed_;
        pr.batches = batches_;
        pr.event = "initial";
        report(pr);
    }

    bool done = false;
    while (!done)
    {
        if (S == 0)
        {
            status = FitStatus::zeroResidual;
            break;
        }
        if (iter >= opts_.maxIterations)
        {
            status = FitStatus::maxIterations;
            break;
        }
        if (opts_.maxEvaluations > 0 && evaluations_ >= opts_.maxEvaluations)
        {
            status = FitStatus::maxEvaluations;
            break;
        }

        const bool broyden = broydenLeft > 0;
        if (broyden)
        {
            Ju = JuB;
            --broydenLeft;
            ++broydenJacobians;
        }
        else
        {
            if (!jacobian(p, r, opts_.difference, opts_.hRel, Jp))
            {
                status = FitStatus::jacobianFailed;
                detail = "a Jacobian column failed on both sides and with"
                    " a ten times smaller step";
                JAtP = false;
                break;
            }
            JAtP = true;
            Ju = Jp*dpdu(u).asDiagonal();
            broydenLeft = opts_.jacobianUpdates;
            ++fdJacobians;
        }
        JuB = Ju;
        ++iter;

        const Vector g = Ju.transpose()*r;

        // Active set: on a bound with the gradient pointing out of the box
        std::vector<int> freeIdx;
        double gScaled = 0;
        for (int j = 0; j < n_; ++j)
        {
            const bool fixed =
                (u(j) <= uLower_(j) && g(j) > 0)
             || (u(j) >= uUpper_(j) && g(j) < 0);
            const double cn = Ju.col(j).norm();
            D2(j) = std::max(D2(j), cn*cn);
            if (!fixed)
            {
                freeIdx.push_back(j);
                if (cn > 0)
                {
                    gScaled =
                        std::max(gScaled, std::abs(g(j))/(cn*std::sqrt(S)));
                }
            }
        }
        for (int j = 0; j < n_; ++j)
        {
            if (D2(j) == 0) D2(j) = 1;
        }

        if (gScaled <= opts_.tolGradient)
        {
            if (broyden)
            {
                // Converged on an updated Jacobian: check with a
                // finite-difference one at the same point
                broydenLeft = 0;
                --iter;
                continue;
            }
            status = FitStatus::gradientTolerance;
            break;
        }

        const int nf = int(freeIdx.size());
        const long m = r.size();
        Matrix Jf(m, nf);
        Vector Df(nf);
        for (int k = 0; k < nf; ++k)
        {
            Jf.col(k) = Ju.col(freeIdx[k]);
            Df(k) = std::sqrt(D2(freeIdx[k]));
        }

        // Solve min |[Jf; sqrt(lambda) Df] x - [rhs; 0]|
        auto dampedSolve = [&](const Vector& rhs, double lam)
        {
            if (lam > 0)
            {
                Matrix A(m + nf, nf);
                A.topRows(m) = Jf;
                A.bottomRows(nf) = (std::sqrt(lam)*Df).asDiagonal();
                Vector b = Vector::Zero(m + nf);
                b.head(m) = rhs;
                return Vector(A.colPivHouseholderQr().solve(b));
            }
            return Vector(Jf.colPivHouseholderQr().solve(rhs));
        };

        // Stop at the model's precision (see the header): the undamped
        // Gauss-Newton decrease left, against the cost's noise 2 eta |r|
        // and a fraction of a standard error; on finite differences only
        if (opts_.solverNoise > 0 && !broyden && nf > 0)
        {
            double eta = inf;
            for (int j = 0; j < n_; ++j)
            {
                const double scale =
                    params_[j].transform == Transform::log
                  ? std::abs(p(j))
                  : std::max(std::abs(p(j)), typical_(j));
                eta = std::min
                (
                    eta, opts_.solverNoise*scale*Jp.col(j).cwiseAbs().maxCoeff()
                );
            }
            const Vector xgn = dampedSolve(-r, 0);
            const double dGN = std::max(0.0, S - (r + Jf*xgn).squaredNorm());
            const double s2 =
                opts_.knownSigma ? 1.0
              : m > n_ ? S/double(m - n_) : 0.0;
            const double sdTol = opts_.noiseStopStdError;
            res.modelNoise = eta;
            res.costNoise = 2*eta*std::sqrt(S);
            res.gaussNewtonDecrease = dGN;
            if (dGN <= res.costNoise && dGN <= sdTol*sdTol*s2)
            {
                status = FitStatus::noiseLevel;
                detail = "the Gauss-Newton step left would lower the cost by "
                    + str(dGN) + ", below its noise 2 eta |r| = "
                    + str(res.costNoise) + " (model noise eta = "
                    + str(eta) + " per residual from solverNoise "
                    + str(opts_.solverNoise) + "), a step of "
                    + str(s2 > 0 ? std::sqrt(dGN/s2) : 0.0)
                    + " standard errors (at most " + str(sdTol) + ")";
                FitProgress pr;
                pr.iteration = iter;
                pr.cost = S;
                pr.parameters = p;
                pr.damping = lambda;
                pr.evaluations = evaluations_;
                pr.failedEvaluations = failed_;
                pr.batches = batches_;
                pr.event = "stop: " + statusName(status);
                report(pr);
                break;
            }
        }

        int rejected = 0;
        const long failedBefore = failed_;
        const Vector r0 = r;          // at the iteration's start
        const double S0 = S;
        const double lambda0 = lambda, nu0 = nu;
        double alphaGN = 1;
        std::string event;

        while (true)
        {
            if
            (
                opts_.maxEvaluations > 0
             && evaluations_ >= opts_.maxEvaluations
            )
            {
                status = FitStatus::maxEvaluations;
                done = true;
                break;
            }

            Vector xf = dampedSolve(-r, lambda);
            if (gn)
            {
                xf *= alphaGN;
            }

            Vector du = Vector::Zero(n_);
            for (int k = 0; k < nf; ++k)
            {
                du(freeIdx[k]) = xf(k);
            }

            // Geodesic acceleration (Levenberg-Marquardt only)
            bool geodesicReject = false;
            if (!gn && opts_.geodesicAcceleration)
            {
                const double hg = opts_.geodesicStep;
                const Vector uh = u + hg*du;
                if (clampInternal(uh) == uh)
                {
                    Vector rh;
                    if (evaluateOne(toPhysical(uh), rh))
                    {
                        const Vector rvv =
                            (2.0/hg)*((rh - r)/hg - Ju*du);
                        const Vector af = dampedSolve(-rvv, lambda);
                        double na = 0, nv = 0;
                        for (int k = 0; k < nf; ++k)
                        {
                            na += D2(freeIdx[k])*af(k)*af(k);
                            nv += D2(freeIdx[k])*xf(k)*xf(k);
                        }
                        if (2*std::sqrt(na) > opts_.geodesicAlpha*std::sqrt(nv))
                        {
                            geodesicReject = true;
                        }
                        else
                        {
                            for (int k = 0; k < nf; ++k)
                            {
                                du(freeIdx[k]) += 0.5*af(k);
                            }
                        }
                    }
                }
            }

            const Vector ut = clampInternal(u + du);
            const Vector pt = toPhysical(ut);
            const Vector step = ut - u;
            const double relStep = relativeStep(p, pt);
            const double predicted = S - (r + Ju*step).squaredNorm();

            bool evaluated = false, accepted = false;
            double St = nan, rho = 0;
            Vector rt;
            if (!geodesicReject && relStep > 0)
            {
                evaluated = evaluateOne(pt, rt);
                if (evaluated)
                {
                    St = rt.squaredNorm();
                    rho = predicted > 0 ? (S - St)/predicted : -1;
                    accepted = gn ? St < S : (St < S && rho > 1e-4);

                    // Broyden's rank-one secant update (Broyden 1965;
                    // Madsen, Nielsen & Tingleff 2004, section 3.4):
                    // JuB += (r(u + s) - r(u) - JuB s) s^T/(s^T s), with
                    // every evaluated trial, accepted or not; after an
                    // accepted one JuB stands at the new point
                    if (opts_.jacobianUpdates > 0)
                    {
                        const double ss = step.squaredNorm();
                        if (ss > 0)
                        {
                            JuB.noalias() +=
                                ((rt - r - JuB*step)/ss)*step.transpose();
                        }
                    }
                }
            }

            if (accepted)
            {
                const double actualRel = (S - St)/S;
                const double predictedRel = predicted/S;
                // Little progress: near the minimum finite differences
                // take over (an updated Jacobian would only cost rejected
                // trials there)
                if (actualRel < opts_.broydenMinReduction)
                {
                    broydenLeft = 0;
                }
                p = pt;
                u = toInternal(p);
                r.swap(rt);
                S = St;
                JAtP = false;
                if (!gn)
                {
                    const double t = 2*rho - 1;
                    lambda *= std::max(1.0/3.0, 1 - t*t*t);
                    lambda = std::max(lambda, 1e-300);
                    nu = 2;
                }
                event = "accepted";

                if (S == 0)
                {
                    status = FitStatus::zeroResidual;
                    done = true;
                }
                else if (relStep <= opts_.tolStep)
                {
                    status = FitStatus::stepTolerance;
                    done = true;
                }
                else if
                (
                    actualRel <= opts_.tolCost
                 && predictedRel <= opts_.tolCost
                 && rho <= 2
                )
                {
                    status = FitStatus::costTolerance;
                    done = true;
                }
                break;
            }

            // Rejected (cost not decreased, evaluation failed, or the
            // geodesic acceleration too large)
            ++rejected;
            if (evaluated && relStep <= opts_.tolStep)
            {
                status = FitStatus::stepTolerance;
                detail = "the last trial step, below tolStep, did not"
                    " decrease the cost";
                event = "rejected";
                done = true;
                break;
            }
            if (relStep == 0 && !geodesicReject)
            {
                // Nothing to try: the step vanished (all variables held
                // at bounds or underflow)
                status = FitStatus::stepTolerance;
                detail = "the step vanished";
                event = "rejected";
                done = true;
                break;
            }
            if (gn)
            {
                alphaGN *= 0.5;
                if (rejected > 30)
                {
                    status = FitStatus::dampingLimit;
                    detail = "Gauss-Newton step halved 30 times without a"
                        " decrease of the cost";
                    done = true;
                    break;
                }
            }
            else
            {
                lambda *= nu;
                nu *= 2;
                if (lambda > opts_.maxDamping)
                {
                    status = FitStatus::dampingLimit;
                    detail = "damping above maxDamping without an"
                        " acceptable step";
                    done = true;
                    break;
                }
            }
        }

        // A stop on small or failed steps of an updated Jacobian is not
        // trusted: a finite-difference Jacobian at the point found decides
        // (the damping of the iteration's start restored if the steps
        // failed)
        if
        (
            broyden && done
         && (
                status == FitStatus::stepTolerance
             || status == FitStatus::costTolerance
             || status == FitStatus::dampingLimit
            )
        )
        {
            done = false;
            status = FitStatus::maxIterations;
            detail.clear();
            broydenLeft = 0;
            if (event != "accepted")
            {
                lambda = lambda0;
                nu = nu0;
            }
            event += event.empty() ? "" : ", ";
            event += "updated Jacobian stopped: finite differences next";
        }

        // Stopped on a short step while longer trials failed: at a
        // minimum the undamped (Gauss-Newton) model predicts no decrease
        // (r orthogonal to the columns of J); at the edge of a failing
        // region it still predicts a large one
        if
        (
            done
         && failed_ > failedBefore
         && (
                status == FitStatus::stepTolerance
             || status == FitStatus::costTolerance
            )
        )
        {
            const Vector xgn = dampedSolve(-r0, 0);
            const double gnFraction = 1 - (r0 + Jf*xgn).squaredNorm()/S0;
            if (gnFraction > 1e-2)
            {
                status = FitStatus::stalledAtFailures;
                detail = std::to_string(failed_ - failedBefore)
                  + " trial evaluations failed in the last iteration and"
                    " the Gauss-Newton model still predicts a cost decrease"
                    " of " + std::to_string(int(std::round(100*gnFraction)))
                  + " %: stopped at the edge"
                    " of a region where the model fails";
            }
        }

        FitProgress pr;
        pr.iteration = iter;
        pr.cost = S;
        pr.parameters = p;
        pr.damping = lambda;
        pr.evaluations = evaluations_;
        pr.failedEvaluations = failed_;
        pr.batches = batches_;
        pr.rejected = rejected;
        pr.broyden = broyden;
        pr.event = done ? event + (event.empty() ? "" : ", ")
            + "stop: " + statusName(status) : event;
        report(pr);
    }

    res.status = status;
    res.converged = statusConverged(status);
    res.parameters = p;
    res.residuals = r;
    res.cost = S;
    res.iterations = iter;
    res.finiteDifferenceJacobians = fdJacobians;
    res.broydenJacobians = broydenJacobians;
    res.damping = lambda;
    res.message = statusName(status) + (detail.empty() ? "" : ": " + detail);

    // Statistics at the final parameters
    const double hF =
        opts_.finalHRel > 0 ? opts_.finalHRel
      : opts_.finalDifference == opts_.difference ? opts_.hRel
      : opts_.finalDifference == Difference::central
      ? std::pow(opts_.hRel, 2.0/3.0)
      : std::pow(opts_.hRel, 1.5);

    Matrix Jf;
    if (jacobian(p, r, opts_.finalDifference, hF, Jf))
    {
        computeStatistics(p, r, Jf, res);
    }
    else if (JAtP)
    {
        computeStatistics(p, r, Jp, res);
        res.message += "; final Jacobian failed, statistics from the"
            " last iteration's Jacobian";
    }
    else
    {
        res.message += "; final Jacobian failed, no statistics";
        res.dof = int(r.size()) - n_;
        res.standardErrors = Vector::Constant(n_, nan);
        res.lowerConfidence = Vector::Constant(n_, nan);
        res.upperConfidence = Vector::Constant(n_, nan);
        res.covariance = Matrix::Constant(n_, n_, nan);
        res.correlation = Matrix::Constant(n_, n_, nan);
    }

    fillCounters(res);
    return res;
}


} // End namespace hearthFit

// ************************************************************************* //
