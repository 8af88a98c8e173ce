/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "millingtonQuirkVapourDiffusion.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace vapourDiffusionModels
{
    defineTypeNameAndDebug(millingtonQuirk, 0);
    addToRunTimeSelectionTable
    (
        vapourDiffusionModel,
        millingtonQuirk,
        dictionary
    );
}
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::vapourDiffusionModels::millingtonQuirk::millingtonQuirk
(
    const dictionary&
)
:
    vapourDiffusionModel()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::vapourDiffusionModels::millingtonQuirk::factor
(
    const scalar alphaL,
    const scalar porosity
) const
{
    const scalar thetaG = max((1 - alphaL)*porosity, scalar(0));
    return std::pow(thetaG, 10.0/3.0)/sqr(porosity);
}


Foam::scalar Foam::vapourDiffusionModels::millingtonQuirk::dFactordAlphaL
(
    const scalar alphaL,
    const scalar porosity
) const
{
    const scalar thetaG = max((1 - alphaL)*porosity, scalar(0));
    return -(10.0/3.0)*std::pow(thetaG, 7.0/3.0)/porosity;
}

// ************************************************************************* //
