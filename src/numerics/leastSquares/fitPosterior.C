/*---------------------------------------------------------------------------*\
  hearthFoam: hearthFit optimiser core (see fitPosterior.H)
\*---------------------------------------------------------------------------*/

#include "fitPosterior.H"

#include <cmath>
#include <stdexcept>

namespace hearthFit
{

namespace
{
const double nan = std::numeric_limits<double>::quiet_NaN();
}


// * * * * * * * * * * * * * * * * Constructor  * * * * * * * * * * * * * * //

fitPosterior::fitPosterior
(
    const std::vector<Prior>& priors,
    long nData,
    int nPredictions
)
:
    priors_(priors),
    nData_(nData),
    nPred_(nPredictions)
{
    for (std::size_t j = 0; j < priors_.size(); ++j)
    {
        const Prior& q = priors_[j];
        if (!std::isfinite(q.mean) || !std::isfinite(q.sd) || q.sd < 0)
        {
            throw std::invalid_argument
            (
                "fitPosterior: prior of parameter " + std::to_string(j + 1)
              + ": need a finite mean and a finite sd > 0 (0: no prior)"
            );
        }
    }
    if (nData_ < 1 || nPred_ < 0)
    {
        throw std::invalid_argument("fitPosterior: no data rows");
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

int fitPosterior::nPriors() const
{
    int n = 0;
    for (const Prior& q : priors_)
    {
        if (q.given()) ++n;
    }
    return n;
}


void fitPosterior::absorb(std::vector<Evaluation>& batch)
{
    const int np = nPriors();
    for (Evaluation& e : batch)
    {
        if (!e.ok)
        {
            continue;
        }
        if (e.residuals.size() != nData_ + nPred_)
        {
            e.ok = false;
            continue;
        }
        if (nPred_ > 0)
        {
            runParameters_.push_back(e.parameters);
            runPredictions_.push_back(e.residuals.tail(nPred_));
        }
        Vector r(nData_ + np);
        r.head(nData_) = e.residuals.head(nData_);
        long i = nData_;
        for (std::size_t j = 0; j < priors_.size(); ++j)
        {
            if (priors_[j].given())
            {
                r(i++) = (e.parameters(j) - priors_[j].mean)/priors_[j].sd;
            }
        }
        e.residuals.swap(r);
    }
}


Vector fitPosterior::taught(const FitResult& res) const
{
    const int n = int(priors_.size());
    Vector t = Vector::Constant(n, nan);
    for (int j = 0; j < n; ++j)
    {
        if (priors_[j].given() && res.standardErrors.size() == n)
        {
            t(j) = res.standardErrors(j)/priors_[j].sd;
        }
    }
    return t;
}


PredictionResult fitPosterior::predict(const FitResult& res) const
{
    PredictionResult pr;
    const Vector& p = res.parameters;
    const int n = int(p.size());
    if (nPred_ == 0)
    {
        pr.message = "no predictions";
        return pr;
    }

    // The runs at p and at p moved along one parameter only, the most
    // recent first (the final Jacobian's)
    int centre = -1;
    std::vector<int> plus(n, -1), minus(n, -1);
    for (int k = int(runParameters_.size()) - 1; k >= 0; --k)
    {
        const Vector& q = runParameters_[k];
        if (q.size() != n) continue;
        int moved = -1, nMoved = 0;
        for (int j = 0; j < n; ++j)
        {
            if (q(j) != p(j))
            {
                moved = j;
                ++nMoved;
            }
        }
        if (nMoved == 0 && centre < 0)
        {
            centre = k;
        }
        else if (nMoved == 1)
        {
            std::vector<int>& side = q(moved) > p(moved) ? plus : minus;
            if (side[moved] < 0) side[moved] = k;
        }
    }
    if (centre < 0)
    {
        pr.message = "no forward run at the final parameters";
        return pr;
    }
    pr.value = runPredictions_[centre];
    pr.sensitivity.resize(nPred_, n);
    for (int j = 0; j < n; ++j)
    {
        const int kp = plus[j], km = minus[j];
        if (kp >= 0 && km >= 0)
        {
            pr.sensitivity.col(j) =
                (runPredictions_[kp] - runPredictions_[km])
               /(runParameters_[kp](j) - runParameters_[km](j));
        }
        else if (kp >= 0 || km >= 0)
        {
            const int k = kp >= 0 ? kp : km;
            pr.sensitivity.col(j) =
                (runPredictions_[k] - pr.value)/(runParameters_[k](j) - p(j));
        }
        else
        {
            pr.message =
                "no finite-difference run around the final parameters"
                " along parameter " + std::to_string(j + 1);
            return pr;
        }
    }

    pr.standardError = Vector::Constant(nPred_, nan);
    pr.lower = Vector::Constant(nPred_, nan);
    pr.upper = Vector::Constant(nPred_, nan);
    if (res.covariance.rows() == n && res.covariance.cols() == n)
    {
        for (int k = 0; k < nPred_; ++k)
        {
            const Vector g = pr.sensitivity.row(k).transpose();
            const double v = g.dot(res.covariance*g);
            pr.standardError(k) = std::sqrt(std::max(v, 0.0));
            pr.lower(k) = pr.value(k) - res.tQuantile*pr.standardError(k);
            pr.upper(k) = pr.value(k) + res.tQuantile*pr.standardError(k);
        }
    }
    pr.ok = true;
    return pr;
}


} // End namespace hearthFit

// ************************************************************************* //
