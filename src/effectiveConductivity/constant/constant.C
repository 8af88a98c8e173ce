/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "constant.H"
#include "addToRunTimeSelectionTable.H"
#include "checkedRead.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace effectiveConductivityModels
{
    defineTypeNameAndDebug(constant, 0);
    addToRunTimeSelectionTable
    (
        effectiveConductivityModel,
        constant,
        dictionary
    );
}
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::effectiveConductivityModels::constant::constant(const dictionary& coeffs)
:
    twoComponentConductivityModel(coeffs),
    kappa_
    (
        checkedRead::get
        (
            coeffs, "kappa", dimPower/dimLength/dimTemperature,
            checkedRead::positive()
        ).value()
    )
{}

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::effectiveConductivityModels::constant::kappa
(
    const scalar,
    const scalar,
    const scalar
) const
{
    return kappa_;
}

// ************************************************************************* //
