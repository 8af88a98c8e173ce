/*---------------------------------------------------------------------------*\
  hearthFoam: hearthFit optimiser core (see tikhonov.H)
\*---------------------------------------------------------------------------*/

#include "tikhonov.H"

#include <cmath>
#include <stdexcept>

namespace hearthFit
{

// * * * * * * * * * * * * * * * * Constructor  * * * * * * * * * * * * * * //

tikhonov::tikhonov
(
    int nPar,
    int first,
    const std::vector<double>& knots,
    int order,
    double weight
)
:
    order_(order),
    weight_(0)
{
    const int n = int(knots.size());
    if (order != 1 && order != 2)
    {
        throw std::invalid_argument
        (
            "tikhonov: order " + std::to_string(order) + ": valid are 1"
            " (first differences), 2 (second differences)"
        );
    }
    if (first < 0 || n < order + 1 || first + n > nPar)
    {
        throw std::invalid_argument
        (
            "tikhonov: need at least " + std::to_string(order + 1)
          + " regularised parameters for differences of order "
          + std::to_string(order)
        );
    }
    for (int k = 1; k < n; ++k)
    {
        if (!(knots[k] > knots[k - 1]) || !std::isfinite(knots[k]))
        {
            throw std::invalid_argument
            (
                "tikhonov: knots must be finite and strictly increasing"
                " (knot " + std::to_string(k + 1) + ")"
            );
        }
    }
    // Divided differences weighted by the square root of the interval
    // (order 1) or of the dual cell (order 2): |L p|^2 ~ integral of the
    // squared derivative (header)
    L_ = Matrix::Zero(n - order, nPar);
    for (int i = 0; i < n - order; ++i)
    {
        if (order == 1)
        {
            const double h = knots[i + 1] - knots[i];
            L_(i, first + i) = -1/std::sqrt(h);
            L_(i, first + i + 1) = 1/std::sqrt(h);
        }
        else
        {
            const double h0 = knots[i + 1] - knots[i];
            const double h1 = knots[i + 2] - knots[i + 1];
            const double hbar = 0.5*(h0 + h1);
            // sqrt(hbar) T'' = sqrt(hbar)/hbar [(T2 - T1)/h1 - (T1 - T0)/h0]
            const double s = 1/std::sqrt(hbar);
            L_(i, first + i) = s/h0;
            L_(i, first + i + 1) = -s*(1/h0 + 1/h1);
            L_(i, first + i + 2) = s/h1;
        }
    }
    setWeight(weight);
}


tikhonov::tikhonov(int nPar, int first, int n, int order, double weight)
:
    tikhonov(nPar, first, unitKnots(n), order, weight)
{}


std::vector<double> tikhonov::unitKnots(int n)
{
    std::vector<double> t(std::max(n, 0));
    for (int k = 0; k < n; ++k) t[k] = k;
    return t;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void tikhonov::setWeight(double w)
{
    if (!std::isfinite(w) || w < 0)
    {
        throw std::invalid_argument
        (
            "tikhonov: weight " + std::to_string(w) + ": need a finite"
            " weight >= 0"
        );
    }
    weight_ = w;
}


bool tikhonov::dataMisfitInBand(double chi2, long nData)
{
    return std::abs(chi2 - double(nData)) <= dataMisfitBand(nData);
}


double tikhonov::dataMisfitBand(long nData)
{
    return 2*std::sqrt(2.0*double(nData));
}


void tikhonov::absorb(std::vector<Evaluation>& batch) const
{
    const double s = std::sqrt(weight_);
    for (Evaluation& e : batch)
    {
        if (!e.ok || e.parameters.size() != L_.cols())
        {
            continue;
        }
        const long m = e.residuals.size();
        Vector r(m + L_.rows());
        r.head(m) = e.residuals;
        r.tail(L_.rows()) = s*(L_*e.parameters);
        e.residuals.swap(r);
    }
}


Vector tikhonov::solve
(
    const Matrix& Jd,
    const Vector& r0,
    const Vector& p0,
    double w
) const
{
    // min |r0 + Jd dp|^2 + w |L (p0 + dp)|^2 as one stacked least-squares
    // problem (minimum-norm dp where it is rank deficient, w = 0)
    const long m = Jd.rows(), k = L_.rows(), n = Jd.cols();
    const double s = std::sqrt(w);
    Matrix A(m + k, n);
    A.topRows(m) = Jd;
    A.bottomRows(k) = s*L_;
    Vector b(m + k);
    b.head(m) = -r0;
    b.tail(k) = -s*(L_*p0);
    const Vector dp = A.completeOrthogonalDecomposition().solve(b);
    return p0 + dp;
}


tikhonov::Choice tikhonov::choose
(
    Rule rule,
    const Matrix& Jd,
    const Vector& r0,
    const Vector& p0,
    double wMin,
    double wMax
)
{
    auto chi2 = [&](const Vector& p)
    {
        return (r0 + Jd*(p - p0)).squaredNorm();
    };
    Choice c;
    c.chi2Unregularised = chi2(solve(Jd, r0, p0, 0));
    const double N = double(Jd.rows());

    if (rule == Rule::fixed)
    {
        c.weight = weight_;
    }
    else if (rule == Rule::discrepancy)
    {
        const double lo0 = chi2(solve(Jd, r0, p0, wMin));
        const double hi0 = chi2(solve(Jd, r0, p0, wMax));
        if (lo0 >= N)
        {
            c.weight = wMin;
            c.message =
                "chi^2 = " + std::to_string(lo0) + " > N = "
              + std::to_string(N) + " even at the smallest weight: the"
                " model does not fit the data to their noise";
        }
        else if (hi0 <= N)
        {
            c.weight = wMax;
            c.message =
                "chi^2 = " + std::to_string(hi0) + " < N even at the"
                " largest weight: the data allow the smoothest history";
        }
        else
        {
            // chi^2(w) increases with w: bisection in log w
            double a = std::log(wMin), b = std::log(wMax);
            for (int it = 0; it < 100 && b - a > 1e-6; ++it)
            {
                const double mid = 0.5*(a + b);
                if (chi2(solve(Jd, r0, p0, std::exp(mid))) < N) a = mid;
                else b = mid;
            }
            c.weight = std::exp(0.5*(a + b));
        }
    }
    else
    {
        // L-curve: (x, y) = (log sqrt(chi^2), log eta) against t = log w;
        // curvature kappa = (x' y'' - y' x'')/(x'^2 + y'^2)^(3/2) by
        // central differences in t; the corner is its largest value
        const int nw = 241;
        const double a = std::log(wMin), b = std::log(wMax);
        const double dt = (b - a)/(nw - 1);
        std::vector<double> x(nw), y(nw);
        for (int i = 0; i < nw; ++i)
        {
            const Vector p = solve(Jd, r0, p0, std::exp(a + i*dt));
            x[i] = 0.5*std::log(std::max(chi2(p), 1e-300));
            y[i] = std::log(std::max((L_*p).norm(), 1e-300));
        }
        // Where the curve hardly moves with w (its flat ends: w far below
        // or above the range where it matters) the curvature is round-off
        // over round-off: only points moving at >= 1 % of the fastest
        double vMax = 0;
        for (int i = 1; i < nw - 1; ++i)
        {
            vMax = std::max
            (
                vMax,
                std::hypot(x[i + 1] - x[i - 1], y[i + 1] - y[i - 1])/(2*dt)
            );
        }
        double best = -1e300;
        int ib = nw/2;
        for (int i = 1; i < nw - 1; ++i)
        {
            const double x1 = (x[i + 1] - x[i - 1])/(2*dt);
            const double y1 = (y[i + 1] - y[i - 1])/(2*dt);
            const double x2 = (x[i + 1] - 2*x[i] + x[i - 1])/(dt*dt);
            const double y2 = (y[i + 1] - 2*y[i] + y[i - 1])/(dt*dt);
            if (std::hypot(x1, y1) < 0.01*vMax) continue;
            const double d = std::pow(x1*x1 + y1*y1, 1.5);
            if (d <= 0) continue;
            const double kappa = (x1*y2 - y1*x2)/d;
            if (kappa > best)
            {
                best = kappa;
                ib = i;
            }
        }
        c.weight = std::exp(a + ib*dt);
    }
    const Vector p = solve(Jd, r0, p0, c.weight);
    c.chi2 = chi2(p);
    c.roughness = (L_*p).norm();
    setWeight(c.weight);
    return c;
}


} // End namespace hearthFit

// ************************************************************************* //
