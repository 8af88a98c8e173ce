/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "brooksCoreyBurdineRelativePermeability.H"
#include "addToRunTimeSelectionTable.H"
#include "checkedRead.H"

#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace relativePermeabilityModels
{
    defineTypeNameAndDebug(brooksCoreyBurdine, 0);
    addToRunTimeSelectionTable
    (
        relativePermeabilityModel,
        brooksCoreyBurdine,
        dictionary
    );
}
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::relativePermeabilityModels::brooksCoreyBurdine::brooksCoreyBurdine
(
    const dictionary& dict,
    const dictionary& coeffs
)
:
    relativePermeabilityModel(dict, coeffs),
    lambda_
    (
        checkedRead::get
        (
            coeffs, "lambda", dimless, checkedRead::positive()
        ).value()
    )
{}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::relativePermeabilityModels::brooksCoreyBurdine::krlEff
(
    const scalar Se
) const
{
    return std::pow(Se, (2 + 3*lambda_)/lambda_);
}


Foam::scalar Foam::relativePermeabilityModels::brooksCoreyBurdine::krgEff
(
    const scalar Se
) const
{
    return sqr(1 - Se)*(1 - std::pow(Se, (2 + lambda_)/lambda_));
}


Foam::scalar
Foam::relativePermeabilityModels::brooksCoreyBurdine::dkrldSeEff
(
    const scalar Se
) const
{
    const scalar e = (2 + 3*lambda_)/lambda_;
    return e*std::pow(Se, e - 1);
}


Foam::scalar
Foam::relativePermeabilityModels::brooksCoreyBurdine::dkrgdSeEff
(
    const scalar Se
) const
{
    const scalar p = (2 + lambda_)/lambda_;
    return
       -2*(1 - Se)*(1 - std::pow(Se, p))
      - sqr(1 - Se)*p*std::pow(Se, p - 1);
}

// ************************************************************************* //
