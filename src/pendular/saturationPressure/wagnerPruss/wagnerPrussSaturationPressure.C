/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "wagnerPrussSaturationPressure.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace saturationPressureLaws
{
    defineTypeNameAndDebug(wagnerPruss, 0);
    addToRunTimeSelectionTable
    (
        saturationPressureLaw,
        wagnerPruss,
        dictionary
    );
}
}

const Foam::scalar Foam::saturationPressureLaws::wagnerPruss::Tc = 647.096;
const Foam::scalar Foam::saturationPressureLaws::wagnerPruss::pc = 22.064e6;

namespace
{
    // Wagner & Pruss (1993), eq. 2.5 of Wagner & Pruss (2002)
    const Foam::scalar a1 = -7.85951783;
    const Foam::scalar a2 = 1.84408259;
    const Foam::scalar a3 = -11.7866497;
    const Foam::scalar a4 = 22.6807411;
    const Foam::scalar a5 = -15.9618719;
    const Foam::scalar a6 = 1.80122502;
}

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::saturationPressureLaws::wagnerPruss::lnReduced
(
    const scalar T,
    scalar& lnp,
    scalar& dlnpdT
) const
{
    // T in [Tmin, T_c] (checked by the callers): tau >= 0
    const scalar tau = max(1 - T/Tc, scalar(0));
    const scalar s = std::sqrt(tau);
    const scalar t3 = tau*tau*tau;
    const scalar t7 = t3*t3*tau;
    const scalar f =
        a1*tau + a2*tau*s + a3*t3 + a4*t3*s + a5*t3*tau + a6*t7*s;
    const scalar df =
        a1 + 1.5*a2*s + 3*a3*tau*tau + 3.5*a4*tau*tau*s + 4*a5*t3
      + 7.5*a6*t3*t3*s;

    lnp = Tc/T*f;
    dlnpdT = -(df + lnp)/T;
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::saturationPressureLaws::wagnerPruss::wagnerPruss
(
    const dictionary& coeffs
)
:
    saturationPressureLaw(coeffs)
{
    Tmax_ = Tc;
}

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::saturationPressureLaws::wagnerPruss::pSat
(
    const scalar T
) const
{
    checkRange(T);
    scalar lnp, dlnpdT;
    lnReduced(T, lnp, dlnpdT);
    return pc*std::exp(lnp);
}


Foam::scalar Foam::saturationPressureLaws::wagnerPruss::dpSatdT
(
    const scalar T
) const
{
    checkRange(T);
    scalar lnp, dlnpdT;
    lnReduced(T, lnp, dlnpdT);
    return pc*std::exp(lnp)*dlnpdT;
}

// ************************************************************************* //
