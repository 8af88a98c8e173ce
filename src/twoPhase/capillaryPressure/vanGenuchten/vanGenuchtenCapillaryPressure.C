/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "vanGenuchtenCapillaryPressure.H"
#include "addToRunTimeSelectionTable.H"
#include "checkedRead.H"

#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace capillaryPressureModels
{
    defineTypeNameAndDebug(vanGenuchten, 0);
    addToRunTimeSelectionTable
    (
        capillaryPressureModel,
        vanGenuchten,
        dictionary
    );
}
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::capillaryPressureModels::vanGenuchten::vanGenuchten
(
    const dictionary& dict,
    const dictionary& coeffs
)
:
    capillaryPressureModel(dict, coeffs),
    alpha_
    (
        checkedRead::get
        (
            coeffs, "alpha", dimless/dimPressure, checkedRead::positive()
        ).value()
    ),
    n_
    (
        checkedRead::get
        (
            coeffs, "n", dimless, validRange{1, GREAT, true, true}
        ).value()
    ),
    m_(1 - 1/n_)
{}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::capillaryPressureModels::vanGenuchten::pcEff
(
    const scalar Se,
    const scalar
) const
{
    return std::pow(std::pow(Se, -1/m_) - 1, 1/n_)/alpha_;
}


bool Foam::capillaryPressureModels::vanGenuchten::finiteEff
(
    const scalar Se
) const
{
    if (Se >= 1)
    {
        return true;
    }
    // ln of x = S_e^(-1/m), of x/S_e (dpcdSeEff's first product), of p_c
    // <= x^(1/n)/alpha and of |dp_c/dS_e| <= x^(1/n)/(S_e alpha m n) (x >
    // 1: (x - 1)^(1/n - 1) <= x^(1/n - 1) when x - 1 >= 1; near S_e = 1,
    // where x - 1 is small, the terms are far below the bound)
    const scalar lnSe = std::log(Se);
    const scalar lnX = -lnSe/m_;
    const scalar lnMax = std::log(1e300);
    return
        lnX - lnSe < lnMax
     && lnX/n_ - std::log(alpha_) < lnMax
     && lnX/n_ - lnSe - std::log(alpha_*m_*n_) < lnMax;
}


Foam::scalar Foam::capillaryPressureModels::vanGenuchten::dpcdSeEff
(
    const scalar Se,
    const scalar
) const
{
    if (Se >= 1)
    {
        return 0;
    }
    const scalar x = std::pow(Se, -1/m_);
    return -x/Se*std::pow(x - 1, 1/n_ - 1)/(alpha_*m_*n_);
}

// ************************************************************************* //
