/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "effectiveConductivityModel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(effectiveConductivityModel, 0);
    defineRunTimeSelectionTable(effectiveConductivityModel, dictionary);
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::effectiveConductivityModel::effectiveConductivityModel
(
    const dictionary& coeffs
)
:
    coeffs_(coeffs)
{}

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::effectiveConductivityModel::kappaPartiallySaturated
(
    const scalar kappaSolid,
    const scalar kappaLiquid,
    const scalar kappaGas,
    const scalar alphaL,
    const scalar porosity
) const
{
    return kappa
    (
        kappaSolid, alphaL*kappaLiquid + (1 - alphaL)*kappaGas, porosity
    );
}


// ************************************************************************* //
