/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "kozenyCarmanPermeability.H"
#include "addToRunTimeSelectionTable.H"
#include "checkedRead.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace gasPermeabilityModels
{
    defineTypeNameAndDebug(kozenyCarman, 0);
    addToRunTimeSelectionTable(gasPermeabilityModel, kozenyCarman, dictionary);
}
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::gasPermeabilityModels::kozenyCarman::kozenyCarman
(
    const dictionary& coeffs
)
:
    gasPermeabilityModel(coeffs),
    Ckc_
    (
        checkedRead::getOrDefault
        (
            coeffs, "Ckc", dimArea, 3.11e-11, checkedRead::positive()
        ).value()
    )
{}

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::gasPermeabilityModels::kozenyCarman::Kg
(
    const scalar alphaL,
    const scalar porosity
) const
{
    const scalar g = max((1 - alphaL)*porosity, scalar(0));
    return Ckc_*g*g*g/sqr(1 - g);
}


Foam::scalar Foam::gasPermeabilityModels::kozenyCarman::dKgdAlphaL
(
    const scalar alphaL,
    const scalar porosity
) const
{
    const scalar g = max((1 - alphaL)*porosity, scalar(0));
    return -porosity*Ckc_*g*g*(3 - g)/pow3(1 - g);
}

// ************************************************************************* //
