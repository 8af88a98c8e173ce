/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "arithmetic.H"
#include "addToRunTimeSelectionTable.H"
#include "checkedRead.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace effectiveConductivityModels
{
    defineTypeNameAndDebug(arithmetic, 0);
    addToRunTimeSelectionTable
    (
        effectiveConductivityModel,
        arithmetic,
        dictionary
    );
}
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::effectiveConductivityModels::arithmetic::arithmetic(const dictionary& coeffs)
:
    twoComponentConductivityModel(coeffs)
{}

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::effectiveConductivityModels::arithmetic::kappa
(
    const scalar kappaSolid,
    const scalar kappaFluid,
    const scalar porosity
) const
{
    return porosity*kappaFluid + (1.0 - porosity)*kappaSolid;
}

// ************************************************************************* //
