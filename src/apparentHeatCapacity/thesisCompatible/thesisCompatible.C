/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "thesisCompatible.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace apparentHeatCapacityModels
{
    defineTypeNameAndDebug(thesisCompatible, 0);
    addToRunTimeSelectionTable
    (
        apparentHeatCapacityModel,
        thesisCompatible,
        dictionary
    );
}
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::apparentHeatCapacityModels::thesisCompatible::thesisCompatible
(
    const dictionary& dict,
    const phaseProperties& liquid,
    const phaseProperties& vapour
)
:
    apparentHeatCapacityModel(dict, liquid, vapour)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::apparentHeatCapacityModels::thesisCompatible::heatingEnthalpy
(
    const scalar T
) const
{
    const scalar dRho = vapour_.rho() - liquid_.rho();
    const scalar dCp = vapour_.Cp() - liquid_.Cp();
    const scalar s = sigma(T);

    return
        liquid_.rhoCp()*T
      + (liquid_.rho()*dCp + dRho*liquid_.Cp())*sigmaIntegral(T)
      + dRho*dCp*sigmaSqrIntegral(T)
      + latentEnthalpy(s);
}


Foam::scalar Foam::apparentHeatCapacityModels::thesisCompatible::sensibleCapacity
(
    const scalar sigma
) const
{
    return
        (liquid_.rho() + (vapour_.rho() - liquid_.rho())*sigma)
       *(liquid_.Cp() + (vapour_.Cp() - liquid_.Cp())*sigma);
}


Foam::scalar Foam::apparentHeatCapacityModels::thesisCompatible::latentCapacity
(
    const scalar T
) const
{
    return
        (liquid_.rho() + (vapour_.rho() - liquid_.rho())*sigma(T))
       *L_*dSigmaDT(T);
}


Foam::scalar Foam::apparentHeatCapacityModels::thesisCompatible::latentEnthalpy
(
    const scalar sigma
) const
{
    return L_*(liquid_.rho()*sigma + 0.5*(vapour_.rho() - liquid_.rho())*sqr(sigma));
}

// ************************************************************************* //
