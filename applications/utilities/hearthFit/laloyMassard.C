/*---------------------------------------------------------------------------*\
  hearthFoam: Laloy-Massard first estimate (see laloyMassard.H)
\*---------------------------------------------------------------------------*/

#include "laloyMassard.H"

#include <algorithm>
#include <cmath>

namespace
{

const double fMin = 1e-6;

// x >= 0 with erfc(x) = f, f in (0, 1]: Newton on erfc from a bracket-safe
// start (bisection fallback)
double erfcInv(double f)
{
    double lo = 0, hi = 30;
    double x = 0.5;
    for (int it = 0; it < 200; ++it)
    {
        const double g = std::erfc(x) - f;          // decreasing in x
        if (g > 0) lo = x; else hi = x;
        const double dg = -2/std::sqrt(M_PI)*std::exp(-x*x);
        double xn = (dg != 0) ? x - g/dg : 0.5*(lo + hi);
        if (!(xn > lo && xn < hi)) xn = 0.5*(lo + hi);
        if (std::abs(xn - x) <= 1e-15*std::max(1.0, x)) { x = xn; break; }
        x = xn;
    }
    return x;
}

} // namespace


double hearthFit::laloyMassard::model
(
    double z, double t, double a, double T0, double Ti
)
{
    return Ti + (T0 - Ti)*std::erfc(z/(2*std::sqrt(a*t)));
}


double hearthFit::laloyMassard::median(std::vector<double> v)
{
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n/2] : 0.5*(v[n/2 - 1] + v[n/2]);
}


double hearthFit::laloyMassard::exactEstimate
(
    double z,
    const std::vector<double>& t,
    const std::vector<double>& T,
    double T0,
    double Ti,
    int& nUsed
)
{
    nUsed = 0;
    if (!(std::abs(z) > 0) || T0 == Ti) return -1;
    z = std::abs(z);
    std::vector<double> tk, Tk, ak;
    for (size_t k = 0; k < t.size() && k < T.size(); ++k)
    {
        const double f = (T[k] - Ti)/(T0 - Ti);
        if (!(t[k] > 0) || !(f >= fMin && f <= 1 - fMin)) continue;
        const double x = erfcInv(f);
        if (!(x > 0)) continue;
        tk.push_back(t[k]);
        Tk.push_back(T[k]);
        ak.push_back(z*z/(4*t[k]*x*x));
    }
    nUsed = int(tk.size());
    if (!nUsed) return -1;

    // Gauss-Newton in u = ln a on the temperature residuals
    double u = std::log(median(ak));
    auto cost = [&](double uu)
    {
        const double a = std::exp(uu);
        double c = 0;
        for (size_t k = 0; k < tk.size(); ++k)
        {
            const double r = model(z, tk[k], a, T0, Ti) - Tk[k];
            c += r*r;
        }
        return c;
    };
    double c = cost(u);
    for (int it = 0; it < 100; ++it)
    {
        const double a = std::exp(u);
        double jtj = 0, jtr = 0;
        for (size_t k = 0; k < tk.size(); ++k)
        {
            const double x = z/(2*std::sqrt(a*tk[k]));
            // dT/du = a dT/da = (T0 - Ti) (2/sqrt(pi)) exp(-x^2) x/2
            const double j = (T0 - Ti)/std::sqrt(M_PI)*std::exp(-x*x)*x;
            const double r = model(z, tk[k], a, T0, Ti) - Tk[k];
            jtj += j*j;
            jtr += j*r;
        }
        if (!(jtj > 0)) break;
        double du = -jtr/jtj;
        double cn = cost(u + du);
        int halvings = 0;
        while (cn > c && halvings < 40) { du *= 0.5; cn = cost(u + du); ++halvings; }
        if (cn > c) break;
        u += du;
        const double cOld = c;
        c = cn;
        if (std::abs(du) < 1e-14 || cOld - c <= 1e-30*std::max(1.0, cOld)) break;
    }
    return std::exp(u);
}


double hearthFit::laloyMassard::printedRecipe
(
    const std::vector<double>& z,
    const std::vector<double>& t,
    const std::vector<std::vector<double>>& T,
    double T0,
    double Ti
)
{
    if (T0 == Ti) return -1;
    double sst = 0, stt = 0;
    for (size_t k = 0; k < t.size(); ++k)
    {
        if (!(t[k] > 0)) continue;
        double szl = 0, sll = 0;
        for (size_t s = 0; s < z.size(); ++s)
        {
            const double f = (T[s][k] - Ti)/(T0 - Ti);
            if (!(f >= fMin && f <= 1 - fMin) || !(std::abs(z[s]) > 0)) continue;
            const double g = 1 - f;                 // (T0 - T)/(T0 - Ti)
            const double L = -std::log(1 - g*g);
            szl += z[s]*z[s]*L;
            sll += L*L;
        }
        if (!(sll > 0)) continue;
        const double slope = szl/sll;               // (8/3) a t
        sst += slope*t[k];
        stt += t[k]*t[k];
    }
    if (!(stt > 0)) return -1;
    return 3.0/8.0*sst/stt;
}


// ************************************************************************* //
