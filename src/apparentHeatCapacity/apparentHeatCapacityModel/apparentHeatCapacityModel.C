/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "apparentHeatCapacityModel.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(apparentHeatCapacityModel, 0);
    defineRunTimeSelectionTable(apparentHeatCapacityModel, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::apparentHeatCapacityModel::apparentHeatCapacityModel
(
    const dictionary& dict,
    const phaseProperties& liquid,
    const phaseProperties& vapour
)
:
    liquid_(liquid),
    vapour_(vapour),
    Tv_
    (
        checkedRead::get
        (
            dict, "Tv", dimTemperature, checkedRead::positive()
        ).value()
    ),
    dT_
    (
        checkedRead::get
        (
            dict, "dT", dimTemperature, checkedRead::positive()
        ).value()
    ),
    L_
    (
        checkedRead::get
        (
            dict, "latentHeat", dimEnergy/dimMass, checkedRead::nonNegative()
        ).value()
    ),
    irreversible_(dict.getOrDefault<bool>("irreversible", true)),
    linearBelowBand_(false)
{}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::apparentHeatCapacityModel::sigmaSqrIntegral
(
    const scalar T
) const
{
    // sigma^2 = (1 + 2 erf + erf^2)/4, with the antiderivatives
    //   int erf   = x erf + exp(-x^2)/sqrt(pi)
    //   int erf^2 = x erf^2 + 2/sqrt(pi) erf exp(-x^2) - sqrt(2/pi) erf(sqrt2 x)
    const scalar xi = x(T);
    scalar e, g, e2, g2;
    erfAndGauss(xi, e, g);
    erfAndGauss(sqrt(2.0)*xi, e2, g2);
    const scalar sqrtPi = sqrt(constant::mathematical::pi);

    const scalar intErf = xi*e + g/sqrtPi;
    const scalar intErfSqr =
        xi*sqr(e) + 2.0/sqrtPi*e*g
      - sqrt(2.0/constant::mathematical::pi)*e2;

    return 0.25*sqrt(2.0)*dT_*(xi + 2.0*intErf + intErfSqr);
}


// ************************************************************************* //
