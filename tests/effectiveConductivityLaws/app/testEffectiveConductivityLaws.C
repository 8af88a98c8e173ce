/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
-------------------------------------------------------------------------------
Application
    testEffectiveConductivityLaws

Description
    Unit tests of the johansen law of the effectiveConductivityModel family
    (tests/effectiveConductivityLaws; the other laws are checked by
    tests/porousModels): Johansen (1975) as given by Farouki (1981) and
    Lu et al. (2007) eqs. 1-6, evaluated by hand here:

    - k_dry = (0.135 rho_d + 64.7)/(2700 - 0.947 rho_d) at rho_d = 1600
      kg/m3 (phi = 1100/2700): 280.7/1184.8 = 0.236918 W/(m K);
    - k_sat = k_s^(1-phi) k_l^phi: 3^0.6 0.6^0.4 = 1.575917 W/(m K)
      (phi = 0.4);
    - Ke(S_r): coarse 0.7 log10 S_r + 1 (0.3 at 0.1, 0.789279 at 0.5),
      fine log10 S_r + 1 (0 at 0.1, 0.698970 at 0.5); Ke = 0 below the
      zero of the formula, k_e = k_dry there;
    - limits: S_r = 1 gives k_sat, S_r = 0 k_dry; k_e increasing in S_r;
      continuity at the zero of Ke; kappaDry given replaces the law;
    - bad input (caught).

    Usage: testEffectiveConductivityLaws [-fatal CASE]

\*---------------------------------------------------------------------------*/

#include "twoComponentConductivityModel.H"
#include "johansen.H"
#include "IStringStream.H"
#include "unitChecks.H"

#include <cfenv>
#include <cmath>

using namespace Foam;

namespace
{

dictionary dict(const std::string& text)
{
    IStringStream is(text);
    return dictionary(is);
}

autoPtr<effectiveConductivityModel> model(const std::string& text)
{
    return effectiveConductivityModel::New(dict(text));
}

void testJohansen()
{
    section("johansen");
    auto coarse = model
    (
        "conductivityModel johansen; johansenCoeffs { soilType coarse; }"
    );
    auto fine = model
    (
        "conductivityModel johansen; johansenCoeffs { soilType fine; }"
    );
    const auto& jc =
        refCast<const effectiveConductivityModels::johansen>(coarse());
    const auto& jf =
        refCast<const effectiveConductivityModels::johansen>(fine());

    // Hand values of the published formulae: 3e-6 relative for the
    // six-digit ones (half a unit of the sixth digit), 1e-12 where exact
    const scalar phiD = 1100.0/2700.0;
    checkRel("k_dry(rho_d = 1600 kg/m3) = 280.7/1184.8", jc.kappaDry(phiD),
        280.7/1184.8, 1e-12);
    checkRel("k_dry(rho_d = 1600 kg/m3) = 0.236918", jc.kappaDry(phiD),
        0.236918, 3e-6);
    checkRel("k_sat = 3^0.6 0.6^0.4 = 1.575917", jc.kappaSat(3, 0.6, 0.4),
        1.575917, 3e-6);
    checkRel("Ke coarse(0.1) = 0.3", jc.Ke(0.1), 0.3, 1e-12);
    checkRel("Ke coarse(0.5) = 0.789279", jc.Ke(0.5), 0.789279, 1e-6);
    checkAbs("Ke fine(0.1) = 0", jf.Ke(0.1), 0, 1e-15);
    checkRel("Ke fine(0.5) = 0.698970", jf.Ke(0.5), 0.698970, 1e-6);
    checkAbs("Ke coarse(0.03) = 0 (below 10^(-1/0.7) = 0.0373)",
        jc.Ke(0.03), 0, 0);
    checkAbs("Ke(0) = 0", jc.Ke(0), 0, 0);
    checkRel("Ke(1) = 1", jc.Ke(1), 1, 1e-15);

    // k_e = (k_sat - k_dry) Ke + k_dry, by hand at S_r = 0.5, coarse
    const scalar ks = 3, kl = 0.6, kg = 0.026, phi = 0.4;
    const scalar kDry = (0.135*1620 + 64.7)/(2700 - 0.947*1620);
    const scalar kSat = std::pow(ks, 0.6)*std::pow(kl, 0.4);
    checkRel("k_e(S_r = 0.5) coarse = (k_sat - k_dry) 0.789279 + k_dry",
        coarse->kappaPartiallySaturated(ks, kl, kg, 0.5, phi),
        (kSat - kDry)*0.789279 + kDry, 1e-6);
    checkRel("k_e(S_r = 1) = k_sat",
        coarse->kappaPartiallySaturated(ks, kl, kg, 1, phi), kSat, 1e-14);
    checkRel("k_e(S_r = 0) = k_dry",
        coarse->kappaPartiallySaturated(ks, kl, kg, 0, phi), kDry, 1e-14);
    checkRel("k_e does not depend on k_g (Johansen's empirical k_dry)",
        coarse->kappaPartiallySaturated(ks, kl, 1.0, 0.3, phi),
        coarse->kappaPartiallySaturated(ks, kl, kg, 0.3, phi), 1e-15);

    // Continuity at the zero of Ke and monotonicity in S_r
    const scalar Sr0 = std::pow(10.0, -1/0.7);
    checkRel("k_e continuous at Ke = 0 (S_r = 10^(-1/0.7))",
        coarse->kappaPartiallySaturated(ks, kl, kg, Sr0*(1 + 1e-9), phi),
        kDry, 1e-8);
    bool increasing = true;
    scalar prev = 0;
    for (label i = 0; i <= 1000; ++i)
    {
        const scalar k =
            fine->kappaPartiallySaturated(ks, kl, kg, i/1000.0, phi);
        increasing = increasing && k >= prev;
        prev = k;
    }
    checkTrue("k_e(S_r) non-decreasing on [0, 1] (fine, 1001 points)",
        increasing, prev, kSat, "monotone");

    auto given = model
    (
        "conductivityModel johansen;"
        "johansenCoeffs { soilType fine; kappaDry 0.3; rhoSolid 2650; }"
    );
    checkRel("kappaDry given: k_e(S_r = 0) = 0.3",
        given->kappaPartiallySaturated(ks, kl, kg, 0, phi), 0.3, 1e-15);
    checkRel("kappaDry given: k_e(S_r = 0.5) = (k_sat - 0.3) 0.698970 + 0.3",
        given->kappaPartiallySaturated(ks, kl, kg, 0.5, phi),
        (kSat - 0.3)*0.698970 + 0.3, 1e-6);
}


void testBadInput()
{
    section("bad input");
    checkThrows("soilType missing",
        [](){ model("conductivityModel johansen;"); },
        {"soilType", "coarse", "fine"}, true);
    checkThrows("soilType loam",
        [](){ model("conductivityModel johansen; soilType loam;"); },
        {"soilType", "loam", "coarse", "fine"}, true);
    checkThrows("rhoSolid -1",
        [](){ model("conductivityModel johansen; soilType fine;"
            " rhoSolid -1;"); },
        {"rhoSolid", "-1", "(0, "}, true);
    checkThrows("kappaDry 0",
        [](){ model("conductivityModel johansen; soilType fine;"
            " kappaDry 0;"); },
        {"kappaDry", "(0, "}, true);
    checkThrows("unknown keyword in johansenCoeffs",
        [](){ model("conductivityModel johansen;"
            " johansenCoeffs { soilType fine; quartz 0.5; }"); },
        {"'quartz'", "soilType", "rhoSolid", "kappaDry"}, true);
    checkThrows("unknown model lists johansen",
        [](){ model("conductivityModel johanssen;"); },
        {"johanssen", "johansen", "kuniiSmith"}, true);
    auto j = model("conductivityModel johansen; soilType fine;");
    checkTrue("johansen is a law of the saturation, not k_e(k_s, k_f, phi)",
        !isA<twoComponentConductivityModel>(*j)
     && isA<twoComponentConductivityModel>
        (*model("conductivityModel harmonic;")),
        0, 0, "type");
}

} // End anonymous namespace


int main(int argc, char* argv[])
{
    feenableexcept(FE_DIVBYZERO | FE_INVALID | FE_OVERFLOW);

    if (argc == 3 && std::string(argv[1]) == "-fatal")
    {
        const std::string what(argv[2]);
        if (what == "soilType")
        {
            model("conductivityModel johansen; soilType loam;");
        }
        Info<< "no error for -fatal " << what.c_str() << endl;
        return 0;
    }

    testJohansen();
    testBadInput();

    Info<< nl << nChecks << " checks, " << nFailed << " failed" << endl;
    return nFailed > 0;
}

// ************************************************************************* //
