/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "geometric.H"
#include "addToRunTimeSelectionTable.H"
#include "checkedRead.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace effectiveConductivityModels
{
    defineTypeNameAndDebug(geometric, 0);
    addToRunTimeSelectionTable
    (
        effectiveConductivityModel,
        geometric,
        dictionary
    );
}
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::effectiveConductivityModels::geometric::geometric(const dictionary& coeffs)
:
    twoComponentConductivityModel(coeffs)
{}

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::effectiveConductivityModels::geometric::kappa
(
    const scalar kappaSolid,
    const scalar kappaFluid,
    const scalar porosity
) const
{
    return pow(kappaFluid, porosity)*pow(kappaSolid, 1.0 - porosity);
}

// ************************************************************************* //
