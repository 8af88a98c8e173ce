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
