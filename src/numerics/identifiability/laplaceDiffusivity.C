/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "laplaceDiffusivity.H"

#include <cmath>
#include <string>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

// (1 - exp(-x))/x and (1 - exp(-x)(1 + x))/x^2, x = p h >= 0: a segment's
// integral of exp(-p u) and of u exp(-p u) over [0, h], divided by h and
// h^2; series below 1e-3 (the closed forms cancel; next term x^5/5040)
double g1(const double x)
{
    return x < 1e-3 ? 1 - x/2 + x*x/6 - x*x*x/24 : -std::expm1(-x)/x;
}

double g2(const double x)
{
    return
        x < 1e-3
      ? 0.5 - x/3 + x*x/8 - x*x*x/30 + x*x*x*x/144
      : (1 - std::exp(-x)*(1 + x))/(x*x);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * //

double hearthFit::laplaceDiffusivity::transform
(
    const std::vector<double>& t,
    const std::vector<double>& T,
    const double p
)
{
    // T(t) = T_k + (T_k+1 - T_k) u/h on [t_k, t_k + h]:
    // int = exp(-p t_k) h [T_k g1(p h) + (T_k+1 - T_k) g2(p h)]
    double sum = 0;
    for (size_t k = 0; k + 1 < t.size(); ++k)
    {
        const double h = t[k + 1] - t[k];
        const double x = p*h;
        sum += std::exp(-p*t[k])*h*(T[k]*g1(x) + (T[k + 1] - T[k])*g2(x));
    }
    return sum;
}


hearthFit::laplaceDiffusivity::Result hearthFit::laplaceDiffusivity::estimate
(
    const std::vector<double>& t,
    const std::vector<double>& T1,
    const std::vector<double>& T2,
    const double z1,
    const double z2,
    double pMin,
    double pMax,
    const int nP,
    const double minRatio
)
{
    if (T1.size() != t.size() || T2.size() != t.size())
    {
        throw std::invalid_argument
        (
            "laplaceDiffusivity: histories of different lengths"
        );
    }
    if (t.size() < 3)
    {
        throw std::invalid_argument
        (
            "laplaceDiffusivity: fewer than 3 readings"
        );
    }
    for (size_t k = 0; k + 1 < t.size(); ++k)
    {
        if (!(t[k + 1] > t[k]))
        {
            throw std::invalid_argument
            (
                "laplaceDiffusivity: times not increasing at reading "
              + std::to_string(k + 1)
            );
        }
    }
    if (!(z2 > z1))
    {
        throw std::invalid_argument
        (
            "laplaceDiffusivity: the second sensor must be deeper (z2 > z1)"
        );
    }
    if (nP < 2)
    {
        throw std::invalid_argument("laplaceDiffusivity: nP < 2");
    }
    const double tEnd = t.back();
    if (!(tEnd > 0))
    {
        throw std::invalid_argument
        (
            "laplaceDiffusivity: the record ends before the origin"
        );
    }
    if (pMin <= 0) pMin = 10/tEnd;
    if (pMax <= 0) pMax = 100/tEnd;
    if (!(pMax > pMin))
    {
        throw std::invalid_argument("laplaceDiffusivity: pMax <= pMin");
    }

    // The readings before the origin (t < 0) are dropped: T = 0 there
    std::vector<double> ts, T1s, T2s;
    for (size_t k = 0; k < t.size(); ++k)
    {
        if (t[k] >= 0)
        {
            ts.push_back(t[k]);
            T1s.push_back(T1[k]);
            T2s.push_back(T2[k]);
        }
    }

    Result res;
    const double dz = z2 - z1;
    for (int i = 0; i < nP; ++i)
    {
        const double p = pMin*std::pow(pMax/pMin, double(i)/(nP - 1));
        const double b1 = transform(ts, T1s, p);
        const double b2 = transform(ts, T2s, p);
        if (!(b1 > 0 && b2 > 0) || b2/b1 < minRatio || b2/b1 >= 1) continue;
        const double l = std::log(b2/b1);
        res.p.push_back(p);
        res.x.push_back(l*l);
        res.y.push_back(dz*dz*p);
    }
    if (res.p.size() < 2) return res;

    double sxy = 0, sxx = 0;
    for (size_t i = 0; i < res.x.size(); ++i)
    {
        sxy += res.x[i]*res.y[i];
        sxx += res.x[i]*res.x[i];
    }
    res.a = sxy/sxx;
    double m = 0;
    for (size_t i = 0; i < res.x.size(); ++i)
    {
        const double e = (res.y[i] - res.a*res.x[i])/(res.a*res.x[i]);
        m += e*e;
    }
    res.misfit = std::sqrt(m/res.x.size());
    return res;
}


// ************************************************************************* //
