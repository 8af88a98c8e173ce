/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "exponentialCapillaryPressure.H"
#include "addToRunTimeSelectionTable.H"
#include "checkedRead.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace capillaryPressureModels
{
    defineTypeNameAndDebug(exponential, 0);
    addToRunTimeSelectionTable
    (
        capillaryPressureModel,
        exponential,
        dictionary
    );
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::capillaryPressureModels::exponential::exponential
(
    const dictionary& dict,
    const dictionary& coeffs
)
:
    capillaryPressureModel(dict, coeffs),
    p0_
    (
        checkedRead::get
        (
            coeffs, "p0", dimPressure, checkedRead::positive()
        ).value()
    )
{}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::capillaryPressureModels::exponential::pcEff
(
    const scalar Se,
    const scalar
) const
{
    return -p0_*Foam::log(Se);
}


Foam::scalar Foam::capillaryPressureModels::exponential::dpcdSeEff
(
    const scalar Se,
    const scalar
) const
{
    return -p0_/Se;
}


// ************************************************************************* //
