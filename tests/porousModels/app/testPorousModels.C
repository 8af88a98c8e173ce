/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
-------------------------------------------------------------------------------
Application
    testPorousModels

Description
    Unit tests of the point-wise porous-medium models of libhearthFoam, with
    no mesh or case:

    1. effective conductivity laws (harmonic, arithmetic, geometric,
       kuniiSmith): limits phi = 0 and 1, values computed from the theses'
       published parameters (Muhieddine 2009 Table 5.1, Mansour 2015 §4.1), and the bounds arithmetic >= geometric >= harmonic;
    2. apparent heat capacity (energyConsistent, thesisCompatible): the
       capacity integrated by composite Simpson equals the difference of
       heatingEnthalpy, and its latent part is rho_l L (energyConsistent) or
       (rho_l + rho_v)/2 L (thesisCompatible);
    3. the phase indicator sigma: sigma(Tv) = 1/2, dT is the standard
       deviation, dsigma/dT integrates to 1 and erf(sqrt 2) of the latent
       heat is absorbed within Tv -+ 2 dT;
    4. irreversible drying: after heating to TMax = Tv + 3 dT, cooling
       follows the frozen-composition capacity sensibleCapacity(sigma(TMax))
       and the enthalpy is continuous at TMax;
    5. enthalpyAndCapacity (porousMedium's evaluation, with its shortcut
       below the band) gives enthalpy() and capacity() to the bit.

    The porousMedium-level formulas need a mesh and are not tested here.

    Prints one line per check (ok/FAIL, value, expected, tolerance) and
    returns 1 if any check fails.

Usage
    testPorousModels

\*---------------------------------------------------------------------------*/

#include "dictionary.H"
#include "unitChecks.H"
#include "twoComponentConductivityModel.H"
#include "apparentHeatCapacityModel.H"
#include "phaseProperties.H"

#include <cstdarg>
#include <cstdio>
#include <cmath>
#include <cstdint>
#include <random>

using namespace Foam;

// * * * * * * * * * * * * * * * * Checks  * * * * * * * * * * * * * * * * //

namespace
{

//- Composite Simpson rule of f over [a, b] (b < a allowed) with an even
//  number of intervals of width at most hMax
template<class Function>
scalar simpson(const Function& f, const scalar a, const scalar b, scalar hMax)
{
    label n = label(std::ceil(std::fabs(b - a)/hMax));
    n = max(n + (n % 2), label(2));
    const scalar h = (b - a)/n;

    scalar sumOdd = 0, sumEven = 0;
    for (label i = 1; i < n; ++i)
    {
        (i % 2 ? sumOdd : sumEven) += f(a + i*h);
    }
    return h/3.0*(f(a) + 4.0*sumOdd + 2.0*sumEven + f(b));
}


// Data: clay and water (Muhieddine 2009 ch. 3, porousMedium.H)

const scalar kSolid = 0.756;        // W/(m K)
const scalar kLiquid = 0.6;
const scalar kVapour = 0.025;

const phaseProperties liquid("liquid", 1000, 4000, kLiquid);
const phaseProperties vapour("vapour", 0.8, 2000, kVapour);

const scalar Tv = 373.15;           // K
const scalar latentHeat = 2.4e6;    // J/kg
const scalar T0 = 273.15;           // integration range [T0, T1], K
const scalar T1 = 673.15;

// erf(sqrt 2) and (1 + erf(1/sqrt 2))/2 = Phi(1), as literals so as not to
// depend on the erf the models use
const scalar erfSqrt2 = 0.9544997361036416;
const scalar normalCdf1 = 0.8413447460685429;


//- The two-component law k_e(k_s, k_f, phi) of a selected model
const twoComponentConductivityModel& twoComponent
(
    const autoPtr<effectiveConductivityModel>& k
)
{
    return refCast<const twoComponentConductivityModel>(*k);
}


autoPtr<effectiveConductivityModel> conductivity(const word& law)
{
    dictionary dict;
    dict.add("conductivityModel", law);
    if (law == "kuniiSmith")
    {
        dictionary coeffs;
        coeffs.add("beta", 0.895);
        coeffs.add("Phi", 0.058);
        dict.add("kuniiSmithCoeffs", coeffs);
    }
    return effectiveConductivityModel::New(dict);
}


autoPtr<apparentHeatCapacityModel> ahc
(
    const word& type,
    const scalar dT,
    const bool irreversible
)
{
    dictionary dict;
    dict.add("type", type);
    dict.add("Tv", Tv);
    dict.add("dT", dT);
    dict.add("latentHeat", latentHeat);
    dict.add("irreversible", irreversible);

    autoPtr<apparentHeatCapacityModel> model
    (
        apparentHeatCapacityModel::New(dict, liquid, vapour)
    );
    if (model->Tv() != Tv || model->dT() != dT
     || model->latentHeat() != latentHeat
     || model->irreversible() != irreversible)
    {
        FatalErrorInFunction
            << "model " << type << " did not read its dictionary " << dict
            << exit(FatalError);
    }
    return model;
}


//- The sensible capacity at frozen composition sigma, written out here
//  independently of the library [J/m3/K]
scalar expectedSensible(const word& type, const scalar s)
{
    if (type == "energyConsistent")
    {
        return liquid.rho()*liquid.Cp()*(1 - s) + vapour.rho()*vapour.Cp()*s;
    }
    return
        (liquid.rho()*(1 - s) + vapour.rho()*s)
       *(liquid.Cp()*(1 - s) + vapour.Cp()*s);
}


//- Latent heat absorbed through the whole change per unit volume of
//  initial water [J/m3]
scalar expectedLatent(const word& type)
{
    return
        type == "energyConsistent"
      ? liquid.rho()*latentHeat
      : 0.5*(liquid.rho() + vapour.rho())*latentHeat;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * Main  * * * * * * * * * * * * * * * * //

// No argList: in v1912 its destructor (ParRunControl) ends the process with
// Pstream::exit(0), which would hide the exit status of failed checks.
int main()
{
    const wordList laws{"harmonic", "arithmetic", "geometric"};
    const wordList ahcTypes{"energyConsistent", "thesisCompatible"};
    const scalar dTs[] = {0.5, 2, 5};

    // ---------------------------------------------------------------------
    section("1. effective conductivity laws");

    // Limits: the solid at phi = 0, the fluid at phi = 1 (phi = 1 is outside
    // the valid porosity range, a check of the formula only); tol 1e-12 rel
    for (const word& law : laws)
    {
        autoPtr<effectiveConductivityModel> k(conductivity(law));
        for (const scalar kf : {kLiquid, kVapour})
        {
            checkRel
            (
                fmt("%s k(ks=%g, kf=%g, phi=0) = ks", law.c_str(), kSolid, kf),
                twoComponent(k).kappa(kSolid, kf, 0), kSolid, 1e-12
            );
            checkRel
            (
                fmt("%s k(ks=%g, kf=%g, phi=1) = kf", law.c_str(), kSolid, kf),
                twoComponent(k).kappa(kSolid, kf, 1), kf, 1e-12
            );
        }
    }

    // Harmonic (Muhieddine 2009 eq. 3.3), values certified to 3 significant
    // digits: tol 5e-4 abs
    {
        autoPtr<effectiveConductivityModel> k(conductivity("harmonic"));
        const scalar certified[3][3] =
        {
            // phi,  saturated (kf = 0.6), dry (kf = 0.025)
            {0.10, 0.737, 0.193},
            {0.15, 0.728, 0.140},
            {0.20, 0.719, 0.110}
        };
        for (const auto& c : certified)
        {
            checkAbs
            (
                fmt("harmonic phi=%.2f saturated (kf=%g)", c[0], kLiquid),
                twoComponent(k).kappa(kSolid, kLiquid, c[0]), c[1], 5e-4
            );
            checkAbs
            (
                fmt("harmonic phi=%.2f dry (kf=%g)", c[0], kVapour),
                twoComponent(k).kappa(kSolid, kVapour, c[0]), c[2], 5e-4
            );
        }
    }

    // Kunii-Smith (Mansour 2015 eq. 4.3, beta 0.895, Phi 0.058), certified
    // to 4 digits: tol 5e-5 abs
    {
        autoPtr<effectiveConductivityModel> k(conductivity("kuniiSmith"));
        checkAbs
        (
            "kuniiSmith phi=0.2 kf=0.6",
            twoComponent(k).kappa(kSolid, kLiquid, 0.2), 0.6244, 5e-5
        );
        checkAbs
        (
            "kuniiSmith phi=0.2 kf=0.025",
            twoComponent(k).kappa(kSolid, kVapour, 0.2), 0.2016, 5e-5
        );

        // Without kuniiSmithCoeffs the defaults are the same: tol 1e-14 rel
        dictionary dict;
        dict.add("conductivityModel", word("kuniiSmith"));
        autoPtr<effectiveConductivityModel> kDefault
        (
            effectiveConductivityModel::New(dict)
        );
        checkRel
        (
            "kuniiSmith default coefficients = (0.895, 0.058)",
            twoComponent(kDefault).kappa(kSolid, kLiquid, 0.2),
            twoComponent(k).kappa(kSolid, kLiquid, 0.2), 1e-14
        );
    }

    // Bounds: arithmetic >= geometric >= harmonic (weighted AM-GM-HM) for
    // random ks in [0.1, 5], kf in [0.01, 1], phi in [0, 1]; tol 1e-12 rel
    // (the means coincide only when ks = kf)
    {
        autoPtr<effectiveConductivityModel> kA(conductivity("arithmetic"));
        autoPtr<effectiveConductivityModel> kG(conductivity("geometric"));
        autoPtr<effectiveConductivityModel> kH(conductivity("harmonic"));

        std::mt19937_64 gen(20191201);
        auto uniform = [&gen](const scalar a, const scalar b)
        {
            return a + (b - a)*scalar(gen() >> 11)/9007199254740992.0;
        };

        for (int i = 0; i < 5; ++i)
        {
            const scalar ks = uniform(0.1, 5);
            const scalar kf = uniform(0.01, 1);
            const scalar phi = uniform(0, 1);
            const scalar a = twoComponent(kA).kappa(ks, kf, phi);
            const scalar g = twoComponent(kG).kappa(ks, kf, phi);
            const scalar h = twoComponent(kH).kappa(ks, kf, phi);
            checkAtLeast
            (
                fmt("arithmetic >= geometric (ks=%.3f kf=%.3f phi=%.3f)",
                    ks, kf, phi),
                a, g, 1e-12
            );
            checkAtLeast
            (
                fmt("geometric >= harmonic  (ks=%.3f kf=%.3f phi=%.3f)",
                    ks, kf, phi),
                g, h, 1e-12
            );
        }
    }


    // ---------------------------------------------------------------------
    section("2. apparent heat capacity: integral of the capacity");

    // Reversible models (irreversible false), heated from T0 to T1;
    // composite Simpson with step <= dT/50 (the integrands are smooth and
    // flat at both ends, so the rule is far more accurate than the tolerances)
    for (const word& type : ahcTypes)
    {
        // The model's sensible capacity is the formula written here:
        // tol 1e-12 rel
        autoPtr<apparentHeatCapacityModel> m(ahc(type, 2, false));
        for (const scalar s : {0.0, 0.3, 1.0})
        {
            checkRel
            (
                fmt("%s sensibleCapacity(sigma=%g)", type.c_str(), s),
                m->sensibleCapacity(s), expectedSensible(type, s), 1e-12
            );
        }

        for (const scalar dT : dTs)
        {
            autoPtr<apparentHeatCapacityModel> m(ahc(type, dT, false));
            const scalar hMax = dT/50;

            // heatingEnthalpy is the exact antiderivative of the capacity:
            // tol 1e-9 rel
            const scalar total = simpson
            (
                [&](const scalar T) { return m->capacity(T, T0); },
                T0, T1, hMax
            );
            checkRel
            (
                fmt("%s dT=%g int c dT = h(T1) - h(T0)", type.c_str(), dT),
                total, m->heatingEnthalpy(T1) - m->heatingEnthalpy(T0), 1e-9
            );

            // Latent part = total - sensible part, the latter integrated
            // from the formula of this file: tol 1e-6 rel
            const scalar sensible = simpson
            (
                [&](const scalar T)
                {
                    return expectedSensible(type, m->sigma(T));
                },
                T0, T1, hMax
            );
            checkRel
            (
                fmt
                (
                    "%s dT=%g latent heat absorbed = %s",
                    type.c_str(), dT,
                    type == "energyConsistent" ? "rho_l L" : "(rho_l+rho_v)/2 L"
                ),
                total - sensible, expectedLatent(type), 1e-6
            );

            // latentEnthalpy(1): tol 1e-12 rel
            checkRel
            (
                fmt("%s dT=%g latentEnthalpy(1)", type.c_str(), dT),
                m->latentEnthalpy(1), expectedLatent(type), 1e-12
            );
        }
    }


    // ---------------------------------------------------------------------
    section("3. phase indicator sigma");

    for (const scalar dT : dTs)
    {
        autoPtr<apparentHeatCapacityModel> m
        (
            ahc("energyConsistent", dT, false)
        );

        // sigma(Tv) = 1/2: tol 1e-12 abs
        checkAbs(fmt("dT=%g sigma(Tv)", dT), m->sigma(Tv), 0.5, 1e-12);

        // dT is the standard deviation: sigma(Tv + dT) = Phi(1),
        // sigma(Tv - dT) = 1 - Phi(1): tol 1e-12 abs
        checkAbs
        (
            fmt("dT=%g sigma(Tv + dT) = Phi(1)", dT),
            m->sigma(Tv + dT), normalCdf1, 1e-12
        );
        checkAbs
        (
            fmt("dT=%g sigma(Tv - dT) = 1 - Phi(1)", dT),
            m->sigma(Tv - dT), 1 - normalCdf1, 1e-12
        );

        // Simpson integral of dsigma/dT over [T0, T1] = 1: tol 1e-9 abs
        checkAbs
        (
            fmt("dT=%g int dsigma/dT dT", dT),
            simpson
            (
                [&](const scalar T) { return m->dSigmaDT(T); },
                T0, T1, dT/50
            ),
            1, 1e-9
        );

        // Fraction of the latent heat absorbed within Tv -+ 2 dT is
        // erf(sqrt 2) for both models (for thesisCompatible by the symmetry
        // sigma(Tv + x) = 1 - sigma(Tv - x)): tol 1e-6 abs
        for (const word& type : ahcTypes)
        {
            autoPtr<apparentHeatCapacityModel> m(ahc(type, dT, false));
            const scalar latentInBand = simpson
            (
                [&](const scalar T) { return m->latentCapacity(T); },
                Tv - 2*dT, Tv + 2*dT, dT/50
            );
            checkAbs
            (
                fmt("%s dT=%g int_{Tv-2dT}^{Tv+2dT} c_lat / L_tot",
                    type.c_str(), dT),
                latentInBand/expectedLatent(type), erfSqrt2, 1e-6
            );
            checkAbs
            (
                fmt("%s dT=%g latentEnthalpy over Tv-+2dT / L_tot",
                    type.c_str(), dT),
                (
                    m->latentEnthalpy(m->sigma(Tv + 2*dT))
                  - m->latentEnthalpy(m->sigma(Tv - 2*dT))
                )/expectedLatent(type),
                erfSqrt2, 1e-6
            );
        }
    }


    // ---------------------------------------------------------------------
    section("4. irreversible drying: heat to TMax = Tv + 3 dT, then cool");

    for (const word& type : ahcTypes)
    {
        const scalar dT = 2;
        const scalar TMax = Tv + 3*dT;
        const scalar TCool = 300;
        autoPtr<apparentHeatCapacityModel> m(ahc(type, dT, true));
        const scalar sMax = m->sigma(TMax);
        const scalar cFrozen = expectedSensible(type, sMax);
        const scalar hMax = m->enthalpy(TMax, TMax);

        // Heating (T >= TMax) follows the first-heating enthalpy:
        // tol 1e-12 rel
        checkRel
        (
            fmt("%s enthalpy(TMax, TMax) = heatingEnthalpy(TMax)",
                type.c_str()),
            hMax, m->heatingEnthalpy(TMax), 1e-12
        );

        // Below TMax: no latent term, the capacity of the frozen composition
        // sigma(TMax), also where the latent term of a first heating is
        // largest (T = Tv); the evaporated fraction stays sigma(TMax):
        // tol 1e-12 rel
        for (const scalar T : {TCool, Tv - 3*dT, Tv, TMax - 0.01*dT})
        {
            checkRel
            (
                fmt("%s capacity(T=%.2f, TMax) = c_sens(sigma(TMax))",
                    type.c_str(), T),
                m->capacity(T, TMax), cFrozen, 1e-12
            );
        }
        checkRel
        (
            fmt("%s evaporatedFraction(Tv, TMax) = sigma(TMax)",
                type.c_str()),
            m->evaporatedFraction(Tv, TMax), sMax, 1e-12
        );

        // Enthalpy continuous at T = TMax from below and above: tol 1e-9
        // rel, about 4 J/m3; a step of 1e-9 dT changes a continuous h by
        // at most c*2e-9 K ~ 1e-2 J/m3 (c <= 5.3e6 J/m3/K at TMax)
        const scalar delta = 1e-9*dT;
        checkRel
        (
            fmt("%s enthalpy(TMax - %g, TMax) -> enthalpy(TMax, TMax)",
                type.c_str(), delta),
            m->enthalpy(TMax - delta, TMax), hMax, 1e-9
        );
        checkRel
        (
            fmt("%s enthalpy(TMax + %g, TMax) -> enthalpy(TMax, TMax)",
                type.c_str(), delta),
            m->enthalpy(TMax + delta, TMax), hMax, 1e-9
        );

        // Cooling line: h*(T; TMax) = h(TMax) - c_sens(sigma(TMax)) (TMax - T)
        // with c_sens written in this file: tol 1e-12 rel
        for (const scalar T : {TCool, Tv, TMax - 0.01*dT})
        {
            checkRel
            (
                fmt("%s enthalpy(T=%.2f, TMax) on the cooling line",
                    type.c_str(), T),
                m->enthalpy(T, TMax), hMax - cFrozen*(TMax - T), 1e-12
            );
        }

        // Contrast: a reversible model cools back along the heating curve,
        // releasing the latent heat: tol 1e-12 rel
        autoPtr<apparentHeatCapacityModel> mRev(ahc(type, dT, false));
        checkRel
        (
            fmt("%s reversible enthalpy(300, TMax) = heatingEnthalpy(300)",
                type.c_str()),
            mRev->enthalpy(TCool, TMax), mRev->heatingEnthalpy(TCool), 1e-12
        );
    }


    // ---------------------------------------------------------------------
    section
    (
        "5. enthalpyAndCapacity = (enthalpy, capacity) to the bit"
    );

    // porousMedium evaluates H and C by enthalpyAndCapacity, which skips
    // the virtual calls below the band for energyConsistent
    // (linearBelowBand_): it must give the very values of enthalpy() and
    // capacity(), which always take them, so that the iterates of ahcFoam
    // do not change. T from 250 K to 700 K in steps of 0.37 K (through the
    // band's edge x = -6, T = Tv - 6 sqrt(2) dT, at dT 1, 2, 5 K), TMax at
    // T (heating), below the band, at its edge, in it and above it
    // (cooling when T < TMax); both models, irreversible or not: the
    // largest difference must be exactly 0 (one check per model and
    // setting; any rounding difference fails)
    for (const word& type : ahcTypes)
    {
        for (const bool irreversible : {true, false})
        {
            for (const scalar dT : {1.0, 2.0, 5.0})
            {
                autoPtr<apparentHeatCapacityModel> m
                (
                    ahc(type, dT, irreversible)
                );
                const scalar edge = Tv - 6*std::sqrt(2.0)*dT;
                scalar maxDiff = 0;
                label nDiff = 0, nPoints = 0;
                for (scalar T = 250; T < 700; T += 0.37)
                {
                    for
                    (
                        const scalar TMax
                      : {T, 300.0, edge, std::nextafter(edge, 0.0),
                         std::nextafter(edge, 1e3), Tv, Tv + 3*dT, 650.0}
                    )
                    {
                        scalar h, c;
                        m->enthalpyAndCapacity(T, TMax, h, c);
                        const scalar dh = h - m->enthalpy(T, TMax);
                        const scalar dc = c - m->capacity(T, TMax);
                        maxDiff = max(maxDiff, max(mag(dh), mag(dc)));
                        nDiff += (dh != 0 || dc != 0);
                        ++nPoints;
                    }
                }
                checkTrue
                (
                    fmt("%s%s dT %g: %d points, %d differ",
                        type.c_str(), irreversible ? "" : " reversible",
                        dT, int(nPoints), int(nDiff)),
                    nDiff == 0, maxDiff, 0, "max |diff|, exact"
                );
            }
        }
    }


    // ---------------------------------------------------------------------
    Info<< nl << "testPorousModels: " << nChecks << " checks, "
        << nFailed << " failed" << endl;

    return nFailed ? 1 : 0;
}


// ************************************************************************* //
