/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "nonEquilibriumWater.H"
#include "checkedRead.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace waterModels
{
    defineTypeNameAndDebug(nonEquilibrium, 0);
    addToRunTimeSelectionTable(waterModel, nonEquilibrium, dictionary);
}
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::waterModels::nonEquilibrium::nonEquilibrium
(
    const pendularMedium& medium,
    const dictionary& coeffs
)
:
    waterModel(medium, coeffs),
    relaxationFactor_
    (
        checkedRead::getOrDefault
        (
            coeffs_, "relaxationFactor", dimless, 1, checkedRead::positive()
        ).value()
    )
{
    // The meniscus model must know the rate law: fail before any step
    const meniscusCurvatureModel& meniscus = medium_.kelvin().meniscus();
    Info<< "Water model B (non-equilibrium): c_B "
        << meniscus.nonEquilibriumCoeff() << ", e_B "
        << meniscus.nonEquilibriumExponent() << ", R_0 "
        << meniscus.grainRadius() << " m, factor "
        << relaxationFactor_ << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::waterModels::nonEquilibrium::relaxedAlphaL
(
    const scalar W,
    const pendularMedium::saturationState& sat,
    const scalar porosity,
    const scalar pg,
    const scalar alphaOld,
    const scalar dt
) const
{
    if (alphaOld <= 0 || W <= 0 || sat.liquidFree)
    {
        return 0;
    }

    const meniscusCurvatureModel& meniscus = medium_.kelvin().meniscus();
    const scalar eB = meniscus.nonEquilibriumExponent();
    const scalar rateScale =
        medium_.binaryDiffusivity()
       /(
            relaxationFactor_*meniscus.nonEquilibriumCoeff()*medium_.rhoL()
           *porosity*sqr(meniscus.grainRadius())*max(pg, SMALL)
        );
    const scalar RT = medium_.R()*sat.T;
    const scalar Mw = medium_.Mw();
    const scalar Ma = medium_.Ma();

    // g(alpha) = alpha - alphaOld - dt d(alpha)/dt, increasing in alpha
    auto g = [&](const scalar alpha)
    {
        const scalar rhoW = medium_.freeVapourDensity(W, alpha, porosity);
        const scalar pw = rhoW*RT/Mw;
        const scalar pwl =
            sat.pSat*std::exp(sat.kelvinLength*meniscus.K(alpha));
        const scalar rhoG = max(Ma*(pg - pw)/RT, scalar(0)) + rhoW;
        return
            alpha - alphaOld
          - dt*(pw - pwl)*std::pow(alpha, -eB)*rhoG*rateScale;
    };

    // All the water as liquid (no vapour) bounds alpha above
    const scalar alphaMax = min(W/(porosity*medium_.rhoL()), 1 - SMALL);
    scalar hi = std::log(alphaMax);
    scalar gHi = g(alphaMax);
    if (gHi <= 0)
    {
        return alphaMax;
    }
    scalar lo = std::log(max(1e-300, 1e-30*alphaMax));
    scalar gLo = g(std::exp(lo));
    if (gLo >= 0)
    {
        return std::exp(lo);
    }

    // Regula falsi (Illinois) in s = ln(alpha) across the decades, then,
    // once the bracket is within 1e-3 of alpha, in alpha itself, to the
    // rounding of alpha: rho_w = (W/phi - alpha rho_l)/(1 - alpha) is a
    // difference of nearly equal terms in a wet cell (W/phi ~ 1000 rho_w),
    // so the vapour is as smooth in (T, p_g, W) as alpha's root is exact:
    // stopped at 1e-13 in ln(alpha), the root's noise made the vapour's
    // fluxes' derivatives by finite differences wrong by up to 2e-4 of the
    // Jacobian's entries (the Newton engine's; tests/pendularResidual 1m)
    const scalar eps = std::numeric_limits<scalar>::epsilon();
    bool linear = false;
    label side = 0;
    for (label iter = 0; iter < 200; ++iter)
    {
        if (!linear && hi - lo < 1e-3)
        {
            // The same bracket in alpha (signs of g kept)
            lo = std::exp(lo);
            hi = std::exp(hi);
            linear = true;
            side = 0;
        }
        const scalar s = (lo*gHi - hi*gLo)/(gHi - gLo);
        const scalar alpha = linear ? s : std::exp(s);
        if (linear && !(s > lo && s < hi))
        {
            // The bracket is down to adjacent values of alpha
            return mag(gLo) < mag(gHi) ? lo : hi;
        }
        const scalar gs = g(alpha);
        if (gs == 0 || (linear && hi - lo <= 4*eps*hi))
        {
            return alpha;
        }
        if (gs > 0)
        {
            hi = s;
            gHi = gs;
            if (side == 1)
            {
                gLo *= 0.5;
            }
            side = 1;
        }
        else
        {
            lo = s;
            gLo = gs;
            if (side == -1)
            {
                gHi *= 0.5;
            }
            side = -1;
        }
    }
    return linear ? 0.5*(lo + hi) : std::exp(0.5*(lo + hi));
}


void Foam::waterModels::nonEquilibrium::liquidAndVapour
(
    const scalar W,
    const pendularMedium::saturationState& sat,
    const scalar porosity,
    const scalar pg,
    const scalar alphaOld,
    const scalar dt,
    const scalar alphaGuess,
    scalar& alpha,
    scalar& rhoW
) const
{
    if (dt > 0)
    {
        // alpha relaxes towards equilibrium over the step
        alpha = relaxedAlphaL(W, sat, porosity, pg, alphaOld, dt);
        rhoW = medium_.freeVapourDensity(W, alpha, porosity);
    }
    else
    {
        equilibriumState(W, sat, porosity, alphaGuess, alpha, rhoW);
    }
}


// ************************************************************************* //
