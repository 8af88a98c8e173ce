/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
-------------------------------------------------------------------------------
Application
    testRelativePermeabilityLaws

Description
    Unit tests of the relativePermeabilityModel family (tests/
    relativePermeabilityLaws):

    - vanGenuchtenMualem against Mualem's (1976) integral evaluated
      numerically with the vanGenuchten capillary pressure of
      capillaryPressureModel (an independent path: the closed forms of van
      Genuchten 1980 eq. 8 and of Parker et al. 1987 are its integrals):
          k_rl = S_e^l [I(S_e)/I(1)]^2,  k_rg = (1 - S_e)^l_g [1 - I(S_e)/I(1)]^2
          I(S_e) = int_0^S_e dS/p_c(S)
    - brooksCoreyBurdine against Burdine's (1953) integral with the
      brooksCorey capillary pressure:
          k_rl = S_e^2 J(S_e)/J(1),  k_rg = (1 - S_e)^2 [1 - J(S_e)/J(1)]
          J(S_e) = int_0^S_e dS/p_c(S)^2
    - corey: the Udell & Fitch (1985) cubes, hand values;
    - the end points k_rl(S_wr) = 0, k_rl(1 - S_gr) = 1, k_rg the reverse;
    - derivatives against central differences; bad input.

    Usage: testRelativePermeabilityLaws [-fatal CASE]

\*---------------------------------------------------------------------------*/

#include "relativePermeabilityModel.H"
#include "capillaryPressureModel.H"
#include "IStringStream.H"
#include "unitChecks.H"

#include <cfenv>
#include <cmath>
#include <functional>

using namespace Foam;

namespace
{

dictionary dict(const std::string& text)
{
    IStringStream is(text);
    return dictionary(is);
}

autoPtr<relativePermeabilityModel> model(const std::string& text)
{
    return relativePermeabilityModel::New(dict(text));
}

//- Composite Simpson rule of f on [a, b], N (even) intervals
scalar simpson
(
    const std::function<scalar(scalar)>& f,
    const scalar a,
    const scalar b,
    const label N
)
{
    const scalar h = (b - a)/N;
    scalar sum = f(a) + f(b);
    for (label i = 1; i < N; ++i)
    {
        sum += (i % 2 ? 4 : 2)*f(a + i*h);
    }
    return sum*h/3;
}


//- Derivatives against central differences at S
void checkDerivatives
(
    const std::string& name,
    const relativePermeabilityModel& kr,
    const scalar S
)
{
    // Truncation h^2 k'''/6 and rounding eps k/h: below 1e-7 relative
    // (or 1e-10 absolute where a derivative is near 0) with this h
    const scalar h = 1e-5*std::min(S, 1 - S);
    const scalar fdl = (kr.krl(S + h) - kr.krl(S - h))/(2*h);
    const scalar fdg = (kr.krg(S + h) - kr.krg(S - h))/(2*h);
    checkAbs(fmt("%s dkrl/dS vs central difference, S = %g", name.c_str(), S),
        kr.dkrldS(S), fdl, 1e-6*std::abs(fdl) + 1e-10);
    checkAbs(fmt("%s dkrg/dS vs central difference, S = %g", name.c_str(), S),
        kr.dkrgdS(S), fdg, 1e-6*std::abs(fdg) + 1e-10);
}


void checkEnds(const std::string& name, const relativePermeabilityModel& kr)
{
    const scalar Swr = kr.saturation().Swr(), Sgr = kr.saturation().Sgr();
    checkAbs(name + " krl(Swr) = 0", kr.krl(Swr), 0, 1e-15);
    checkAbs(name + " krg(Swr) = 1", kr.krg(Swr), 1, 1e-15);
    checkAbs(name + " krl(1 - Sgr) = 1", kr.krl(1 - Sgr), 1, 1e-15);
    checkAbs(name + " krg(1 - Sgr) = 0", kr.krg(1 - Sgr), 0, 1e-15);
    checkAbs(name + " krl(0) = 0 (below Swr)", kr.krl(0), 0, 1e-15);
    checkAbs(name + " krg(1) = 0", kr.krg(1), 0, 1e-15);
    checkAbs(name + " dkrl/dS(0) = 0 (clamped)", kr.dkrldS(0), 0, 0);
    checkAbs(name + " dkrg/dS(1) = 0 (clamped)", kr.dkrgdS(1), 0, 0);
}


void testVanGenuchtenMualem()
{
    for (const scalar n : {2.0, 3.0})
    {
        section(fmt("vanGenuchtenMualem, n = %g", n).c_str());
        const std::string coeffs =
            fmt("Swr 0.1; Sgr 0.05; n %g; alpha 1e-4;", n);
        auto kr = model
        (
            "relativePermeabilityModel vanGenuchtenMualem;" + coeffs
        );
        auto pc = capillaryPressureModel::New
        (
            dict("capillaryPressureModel vanGenuchten;" + coeffs)
        );
        // I(S_e) = int_0^S_e dS/p_c: with 1 - S = s^n the integrand
        // n s^(n-1)/p_c(1 - s^n) is regular at s = 0 (p_c ~ s there);
        // at s = 1 (S_e = 0) it goes like S_e^(1/(m n)), a square root
        // for n = 3: Simpson's error there falls as h^1.5 only (4e-6
        // relative with 4000 intervals, measured), hence 200000 intervals
        const scalar Swr = 0.1, Sgr = 0.05, r = 1 - Swr - Sgr;
        const auto I = [&](const scalar Se)
        {
            const auto f = [&](const scalar s)
            {
                if (s <= 0)
                {
                    // limit: p_c ~ (1/alpha) (s^n/m)^(1/n)
                    const scalar m = 1 - 1/n;
                    return n*1e-4*std::pow(m, 1/n)*(n == 2 ? 1.0 : 0.0);
                }
                if (s >= 1)
                {
                    return 0.0;     // S_e = 0: 1/p_c = 0
                }
                const scalar S = Swr + r*(1 - std::pow(s, n));
                return n*std::pow(s, n - 1)/pc->pc(S, 300);
            };
            return simpson(f, std::pow(1 - Se, 1/n), 1, 200000);
        };
        const scalar I1 = I(1);
        const scalar m = 1 - 1/n;
        for (const scalar Se : {0.1, 0.3, 0.5, 0.8, 0.95})
        {
            const scalar S = Swr + Se*r;
            const scalar ratio = I(Se)/I1;
            // Simpson's error: below 1e-8 for n = 2 (smooth integrand),
            // about 1e-8 for n = 3 (h^1.5); 1e-6 allowed
            checkRel(fmt("VGM krl(S_e = %g) = Mualem's integral", Se),
                kr->krl(S), std::sqrt(Se)*sqr(ratio), 1e-6);
            checkRel(fmt("VGM krg(S_e = %g) = Parker's integral", Se),
                kr->krg(S), std::cbrt(1 - Se)*sqr(1 - ratio), 1e-6);
            // The closed form, by hand (van Genuchten 1980 eq. 8)
            checkRel(fmt("VGM krl(S_e = %g) = vG eq. 8", Se), kr->krl(S),
                std::sqrt(Se)*sqr(1 - std::pow(1 - std::pow(Se, 1/m), m)),
                1e-14);
            checkDerivatives("vanGenuchtenMualem", *kr, S);
        }
        checkEnds("vanGenuchtenMualem", *kr);
    }
}


void testBrooksCoreyBurdine()
{
    section("brooksCoreyBurdine, lambda = 1.5");
    const std::string coeffs = "Swr 0.2; lambda 1.5; pd 1000;";
    auto kr = model("relativePermeabilityModel brooksCoreyBurdine;" + coeffs);
    auto pc = capillaryPressureModel::New
    (
        dict("capillaryPressureModel brooksCorey;" + coeffs)
    );
    const scalar Swr = 0.2, r = 1 - Swr;
    // J(S_e) = int_0^S_e dS/p_c^2 (p_c^-2 = S_e^(2/lambda)/p_d^2: smooth)
    const auto J = [&](const scalar Se)
    {
        return simpson
        (
            [&](const scalar s)
            {
                return s <= 0 ? 0 : 1/sqr(pc->pc(Swr + r*s, 300));
            },
            0, Se, 4000
        );
    };
    const scalar J1 = J(1);
    for (const scalar Se : {0.1, 0.3, 0.5, 0.8, 0.95})
    {
        const scalar S = Swr + Se*r;
        const scalar ratio = J(Se)/J1;
        checkRel(fmt("BCB krl(S_e = %g) = Burdine's integral", Se),
            kr->krl(S), sqr(Se)*ratio, 1e-6);
        checkRel(fmt("BCB krg(S_e = %g) = Burdine's integral", Se),
            kr->krg(S), sqr(1 - Se)*(1 - ratio), 1e-6);
        checkDerivatives("brooksCoreyBurdine", *kr, S);
    }
    checkEnds("brooksCoreyBurdine", *kr);
}


void testCorey()
{
    section("corey (Udell & Fitch 1985: cubes, S_wr = 0.15)");
    auto kr = model
    (
        "relativePermeabilityModel corey; Swr 0.15;"
        "coreyCoeffs { nl 3; ng 3; }"
    );
    // S = 0.575: S_e = 0.5, k_rl = k_rg = 1/8
    checkRel("corey krl(S_e = 0.5) = 0.125", kr->krl(0.575), 0.125, 1e-14);
    checkRel("corey krg(S_e = 0.5) = 0.125", kr->krg(0.575), 0.125, 1e-14);
    // S = 0.83: S_e = 0.8, k_rl = 0.512, k_rg = 0.008
    checkRel("corey krl(S_e = 0.8) = 0.512", kr->krl(0.83), 0.512, 1e-14);
    checkRel("corey krg(S_e = 0.8) = 0.008", kr->krg(0.83), 0.008, 1e-12);
    checkRel("corey dkrl/dS(S_e = 0.5) = 3 0.25/0.85", kr->dkrldS(0.575),
        0.75/0.85, 1e-14);
    for (const scalar S : {0.2, 0.5, 0.9})
    {
        checkDerivatives("corey", *kr, S);
    }
    checkEnds("corey", *kr);
}


void testBadInput()
{
    section("bad input");
    auto kr = model("relativePermeabilityModel corey; nl 3; ng 2;");
    checkThrows("S = 1.1", [&](){ kr->krl(1.1); },
        {"corey", "S = 1.1", "[0, 1]"});
    checkThrows("S = -1e-3 (dkrg/dS)", [&](){ kr->dkrgdS(-1e-3); },
        {"corey", "-0.001", "[0, 1]"});
    checkThrows("unknown model",
        [](){ model("relativePermeabilityModel mualem;"); },
        {"mualem", "brooksCoreyBurdine", "corey", "vanGenuchtenMualem"},
        true);
    checkThrows("inconsistent residual saturations",
        [](){ model("relativePermeabilityModel corey; nl 3; ng 3;"
            "Swr 0.5; Sgr 0.5;"); },
        {"Swr", "Sgr", "[0, 1)"}, true);
    checkThrows("corey missing ng",
        [](){ model("relativePermeabilityModel corey; nl 3;"); }, {"ng"},
        true);
    checkThrows("corey nl = 0.5",
        [](){ model("relativePermeabilityModel corey; nl 0.5; ng 3;"); },
        {"'nl'", "0.5", "[1, "}, true);
    checkThrows("VGM n = 1",
        [](){ model("relativePermeabilityModel vanGenuchtenMualem; n 1;"); },
        {"'n'", "(1, "}, true);
    checkThrows("BCB lambda = -1",
        [](){ model("relativePermeabilityModel brooksCoreyBurdine;"
            " lambda -1;"); },
        {"'lambda'", "-1", "(0, "}, true);
    checkThrows("unknown keyword in coreyCoeffs",
        [](){ model("relativePermeabilityModel corey;"
            "coreyCoeffs { nl 3; ng 3; nw 2; }"); },
        {"'nw'", "nl", "ng"}, true);
}

} // End anonymous namespace


int main(int argc, char* argv[])
{
    feenableexcept(FE_DIVBYZERO | FE_INVALID | FE_OVERFLOW);

    if (argc == 3 && std::string(argv[1]) == "-fatal")
    {
        const std::string what(argv[2]);
        if (what == "model")
        {
            model("relativePermeabilityModel foo;");
        }
        else if (what == "residual")
        {
            model("relativePermeabilityModel corey; nl 3; ng 3; Sgr 1;");
        }
        Info<< "no error for -fatal " << what.c_str() << endl;
        return 0;
    }

    testVanGenuchtenMualem();
    testBrooksCoreyBurdine();
    testCorey();
    testBadInput();

    Info<< nl << nChecks << " checks, " << nFailed << " failed" << endl;
    return nFailed > 0;
}

// ************************************************************************* //
