/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "vargaftikSurfaceTension.H"
#include "addToRunTimeSelectionTable.H"
#include "checkedRead.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace surfaceTensionLaws
{
    defineTypeNameAndDebug(vargaftik, 0);
    addToRunTimeSelectionTable(surfaceTensionLaw, vargaftik, dictionary);
}
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::surfaceTensionLaws::vargaftik::vargaftik(const dictionary& coeffs)
:
    surfaceTensionLaw(coeffs),
    B_
    (
        checkedRead::getOrDefault
        (
            coeffs, "B", dimForce/dimLength, 235.8e-3,
            checkedRead::positive()
        ).value()
    ),
    b_
    (
        checkedRead::getOrDefault
        (
            coeffs, "b", dimless, -0.625, checkedRead::closed(-1, GREAT)
        ).value()
    ),
    mu_
    (
        checkedRead::getOrDefault
        (
            coeffs, "mu", dimless, 1.256,
            validRange{1, GREAT, true, true}
        ).value()
    ),
    Tc_
    (
        checkedRead::getOrDefault
        (
            coeffs, "Tc", dimTemperature, 647.15, checkedRead::positive()
        ).value()
    )
{
    Tmax_ = Tc_;
}

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::surfaceTensionLaws::vargaftik::sigma(const scalar T) const
{
    checkRange(T);
    const scalar tau = (Tc_ - T)/Tc_;
    return (tau > 0) ? B_*std::pow(tau, mu_)*(1 + b_*tau) : scalar(0);
}


Foam::scalar Foam::surfaceTensionLaws::vargaftik::dSigmadT
(
    const scalar T
) const
{
    checkRange(T);
    const scalar tau = (Tc_ - T)/Tc_;
    if (tau <= 0)
    {
        return 0;
    }
    // dsigma/dtau times dtau/dT = -1/Tc
    return
       -B_/Tc_
       *(mu_*std::pow(tau, mu_ - 1)*(1 + b_*tau) + b_*std::pow(tau, mu_));
}

// ************************************************************************* //
