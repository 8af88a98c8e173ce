/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "brooksCoreyCapillaryPressure.H"
#include "addToRunTimeSelectionTable.H"
#include "checkedRead.H"

#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace capillaryPressureModels
{
    defineTypeNameAndDebug(brooksCorey, 0);
    addToRunTimeSelectionTable
    (
        capillaryPressureModel,
        brooksCorey,
        dictionary
    );
}
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::capillaryPressureModels::brooksCorey::brooksCorey
(
    const dictionary& dict,
    const dictionary& coeffs
)
:
    capillaryPressureModel(dict, coeffs),
    pd_
    (
        checkedRead::get
        (
            coeffs, "pd", dimPressure, checkedRead::positive()
        ).value()
    ),
    lambda_
    (
        checkedRead::get
        (
            coeffs, "lambda", dimless, checkedRead::positive()
        ).value()
    )
{}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::capillaryPressureModels::brooksCorey::pcEff
(
    const scalar Se,
    const scalar
) const
{
    return pd_*std::pow(Se, -1/lambda_);
}


Foam::scalar Foam::capillaryPressureModels::brooksCorey::dpcdSeEff
(
    const scalar Se,
    const scalar
) const
{
    return -pd_/lambda_*std::pow(Se, -1/lambda_ - 1);
}

// ************************************************************************* //
