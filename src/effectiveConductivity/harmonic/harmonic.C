/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "harmonic.H"
#include "addToRunTimeSelectionTable.H"
#include "checkedRead.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace effectiveConductivityModels
{
    defineTypeNameAndDebug(harmonic, 0);
    addToRunTimeSelectionTable
    (
        effectiveConductivityModel,
        harmonic,
        dictionary
    );
}
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::effectiveConductivityModels::harmonic::harmonic(const dictionary& coeffs)
:
    twoComponentConductivityModel(coeffs)
{}

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::effectiveConductivityModels::harmonic::kappa
(
    const scalar kappaSolid,
    const scalar kappaFluid,
    const scalar porosity
) const
{
    return 1.0/(porosity/kappaFluid + (1.0 - porosity)/kappaSolid);
}

// ************************************************************************* //
