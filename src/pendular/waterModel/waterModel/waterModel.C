/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "waterModel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(waterModel, 0);
    defineRunTimeSelectionTable(waterModel, dictionary);
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::waterModel::waterModel
(
    const pendularMedium& medium,
    const dictionary& coeffs
)
:
    medium_(medium),
    coeffs_(coeffs)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::waterModel::equilibriumState
(
    const scalar W,
    const pendularMedium::saturationState& sat,
    const scalar porosity,
    const scalar alphaGuess,
    scalar& alpha,
    scalar& rhoW
) const
{
    alpha = medium_.alphaL(W, sat, porosity, alphaGuess);
    rhoW = medium_.vapourDensity(W, alpha, sat, porosity);
}


// ************************************************************************* //
