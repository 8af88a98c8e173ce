/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "relativePermeabilityModel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(relativePermeabilityModel, 0);
    defineRunTimeSelectionTable(relativePermeabilityModel, dictionary);
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::relativePermeabilityModel::relativePermeabilityModel
(
    const dictionary& dict,
    const dictionary& coeffs
)
:
    coeffs_(coeffs),
    saturation_(dict)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::relativePermeabilityModel::krl(const scalar S) const
{
    return krlEff(saturation_.Se(S, "relativePermeabilityModel " + type()));
}


Foam::scalar Foam::relativePermeabilityModel::krg(const scalar S) const
{
    return krgEff(saturation_.Se(S, "relativePermeabilityModel " + type()));
}


Foam::scalar Foam::relativePermeabilityModel::dkrldS(const scalar S) const
{
    const string who("relativePermeabilityModel " + type());
    const scalar dSedS = saturation_.dSedS(S, who);
    return dSedS > 0 ? dkrldSeEff(saturation_.Se(S, who))*dSedS : scalar(0);
}


Foam::scalar Foam::relativePermeabilityModel::dkrgdS(const scalar S) const
{
    const string who("relativePermeabilityModel " + type());
    const scalar dSedS = saturation_.dSedS(S, who);
    return dSedS > 0 ? dkrgdSeEff(saturation_.Se(S, who))*dSedS : scalar(0);
}

// ************************************************************************* //
