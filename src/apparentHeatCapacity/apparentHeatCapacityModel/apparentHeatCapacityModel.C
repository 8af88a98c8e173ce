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


namespace
{
    // erf(x) and exp(-x^2). Beyond |x| = 6 they are -1/+1 and 0 to double
    // precision (erfc(6) = 2e-17, exp(-36) = 2e-16): most cells are far
    // from the evaporation band, where exp(-x^2) would take the slow
    // underflow path of libm.
    inline void erfAndGauss(const double x, double& e, double& g)
    {
        if (x < -6)
        {
            e = -1;
            g = 0;
        }
        else if (x > 6)
        {
            e = 1;
            g = 0;
        }
        else
        {
            e = ::erf(x);
            g = ::exp(-x*x);
        }
    }
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
    irreversible_(dict.getOrDefault<bool>("irreversible", true))
{}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::apparentHeatCapacityModel::x(const scalar T) const
{
    return (T - Tv_)/(sqrt(2.0)*dT_);
}


Foam::scalar Foam::apparentHeatCapacityModel::sigmaIntegral
(
    const scalar T
) const
{
    // S = sqrt(2) dT/2 [x + x erf(x) + exp(-x^2)/sqrt(pi)]
    const scalar xi = x(T);
    scalar e, g;
    erfAndGauss(xi, e, g);
    return
        0.5*sqrt(2.0)*dT_
       *(xi + xi*e + g/sqrt(constant::mathematical::pi));
}


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


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::apparentHeatCapacityModel::sigma(const scalar T) const
{
    scalar e, g;
    erfAndGauss(x(T), e, g);
    return 0.5*(1.0 + e);
}


Foam::scalar Foam::apparentHeatCapacityModel::dSigmaDT(const scalar T) const
{
    scalar e, g;
    erfAndGauss(x(T), e, g);
    return g/(sqrt(2.0*constant::mathematical::pi)*dT_);
}


Foam::scalar Foam::apparentHeatCapacityModel::evaporatedFraction
(
    const scalar T,
    const scalar TMax
) const
{
    return sigma(irreversible_ ? max(T, TMax) : T);
}


Foam::scalar Foam::apparentHeatCapacityModel::enthalpy
(
    const scalar T,
    const scalar TMax
) const
{
    if (!irreversible_ || T >= TMax)
    {
        return heatingEnthalpy(T);
    }

    return heatingEnthalpy(TMax) - sensibleCapacity(sigma(TMax))*(TMax - T);
}


Foam::scalar Foam::apparentHeatCapacityModel::capacity
(
    const scalar T,
    const scalar TMax
) const
{
    if (!irreversible_ || T >= TMax)
    {
        return sensibleCapacity(sigma(T)) + latentCapacity(T);
    }

    return sensibleCapacity(sigma(TMax));
}

// ************************************************************************* //
