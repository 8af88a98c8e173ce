/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "energyConsistent.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace apparentHeatCapacityModels
{
    defineTypeNameAndDebug(energyConsistent, 0);
    addToRunTimeSelectionTable
    (
        apparentHeatCapacityModel,
        energyConsistent,
        dictionary
    );
}
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::apparentHeatCapacityModels::energyConsistent::energyConsistent
(
    const dictionary& dict,
    const phaseProperties& liquid,
    const phaseProperties& vapour
)
:
    apparentHeatCapacityModel(dict, liquid, vapour)
{
    // Below the band sigma = 0.5 (1 + e) = 0 and the antiderivative
    // S = sqrt(2) dT/2 (x + x e + g/sqrt(pi)) = 0 exactly (e = -1, g = 0):
    // heatingEnthalpy = (rho C)_l T, sensibleCapacity(0) = (rho C)_l and
    // latentCapacity = 0, to the bit
    linearBelowBand_ = true;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::apparentHeatCapacityModels::energyConsistent::heatingEnthalpy
(
    const scalar T
) const
{
    const scalar sigmaInt = sigmaIntegral(T);
    return
        liquid_.rhoCp()*T
      + (vapour_.rhoCp() - liquid_.rhoCp())*sigmaInt
      + liquid_.rho()*L_*sigma(T);
}


void Foam::apparentHeatCapacityModels::energyConsistent::
heatingEnthalpyAndCapacity
(
    const scalar T,
    scalar& h,
    scalar& c
) const
{
    // heatingEnthalpy(T), sensibleCapacity(sigma(T)) and latentCapacity(T)
    // written out with their operations in the same order (the same values
    // to the bit: tests/porousModels section 5), erf and exp taken once
    // instead of four times
    const scalar xi = x(T);
    scalar e, g;
    erfAndGauss(xi, e, g);
    const scalar sigmaInt =
        0.5*sqrt(2.0)*dT_
       *(xi + xi*e + g/sqrt(constant::mathematical::pi));
    const scalar s = 0.5*(1.0 + e);
    const scalar dSigma = g/(sqrt(2.0*constant::mathematical::pi)*dT_);

    h =
        liquid_.rhoCp()*T
      + (vapour_.rhoCp() - liquid_.rhoCp())*sigmaInt
      + liquid_.rho()*L_*s;
    c =
        energyConsistent::sensibleCapacity(s)
      + liquid_.rho()*L_*dSigma;
}


Foam::scalar Foam::apparentHeatCapacityModels::energyConsistent::sensibleCapacity
(
    const scalar sigma
) const
{
    return liquid_.rhoCp()*(1.0 - sigma) + vapour_.rhoCp()*sigma;
}


Foam::scalar Foam::apparentHeatCapacityModels::energyConsistent::latentCapacity
(
    const scalar T
) const
{
    return liquid_.rho()*L_*dSigmaDT(T);
}


Foam::scalar Foam::apparentHeatCapacityModels::energyConsistent::latentEnthalpy
(
    const scalar sigma
) const
{
    return liquid_.rho()*L_*sigma;
}

// ************************************************************************* //
