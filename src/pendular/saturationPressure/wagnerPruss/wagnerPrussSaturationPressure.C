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
    const scalar tau = 1 - T/Tc;

    scalar f, df;
    if (tau > 0)
    {
        const scalar s = std::sqrt(tau);
        const scalar t3 = tau*tau*tau;
        const scalar t7 = t3*t3*tau;
        f =
            a1*tau + a2*tau*s + a3*t3 + a4*t3*s + a5*t3*tau + a6*t7*s;
        df =
            a1 + 1.5*a2*s + 3*a3*tau*tau + 3.5*a4*tau*tau*s + 4*a5*t3
          + 7.5*a6*t3*t3*s;
    }
    else
    {
        // At and above the critical point: the first term only, continuous
        // with its derivative at tau = 0
        f = a1*tau;
        df = a1;
    }

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
{}

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::saturationPressureLaws::wagnerPruss::pSat
(
    const scalar T
) const
{
    scalar lnp, dlnpdT;
    lnReduced(T, lnp, dlnpdT);
    return pc*std::exp(lnp);
}


Foam::scalar Foam::saturationPressureLaws::wagnerPruss::dpSatdT
(
    const scalar T
) const
{
    scalar lnp, dlnpdT;
    lnReduced(T, lnp, dlnpdT);
    return pc*std::exp(lnp)*dlnpdT;
}

// ************************************************************************* //
