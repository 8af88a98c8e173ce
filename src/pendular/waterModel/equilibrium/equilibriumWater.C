/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "equilibriumWater.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace waterModels
{
    defineTypeNameAndDebug(equilibrium, 0);
    addToRunTimeSelectionTable(waterModel, equilibrium, dictionary);
}
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::waterModels::equilibrium::equilibrium
(
    const pendularMedium& medium,
    const dictionary& coeffs
)
:
    waterModel(medium, coeffs)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::waterModels::equilibrium::liquidAndVapour
(
    const scalar W,
    const pendularMedium::saturationState& sat,
    const scalar porosity,
    const scalar,
    const scalar,
    const scalar,
    const scalar alphaGuess,
    scalar& alpha,
    scalar& rhoW
) const
{
    equilibriumState(W, sat, porosity, alphaGuess, alpha, rhoW);
}


// ************************************************************************* //
