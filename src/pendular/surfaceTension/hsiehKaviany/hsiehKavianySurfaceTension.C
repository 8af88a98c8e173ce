/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "hsiehKavianySurfaceTension.H"
#include "addToRunTimeSelectionTable.H"
#include "checkedRead.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace surfaceTensionLaws
{
    defineTypeNameAndDebug(hsiehKaviany, 0);
    addToRunTimeSelectionTable(surfaceTensionLaw, hsiehKaviany, dictionary);
}
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::surfaceTensionLaws::hsiehKaviany::hsiehKaviany(const dictionary& coeffs)
:
    surfaceTensionLaw(coeffs),
    sigma0_
    (
        checkedRead::getOrDefault
        (
            coeffs, "sigma0", dimForce/dimLength, 75.5e-3,
            checkedRead::positive()
        ).value()
    ),
    Tc_
    (
        checkedRead::getOrDefault
        (
            coeffs, "Tc", dimTemperature, 647.3, checkedRead::positive()
        ).value()
    ),
    dTm_
    (
        checkedRead::getOrDefault
        (
            coeffs, "dTm", dimTemperature, 6.14, checkedRead::nonNegative()
        ).value()
    ),
    n_
    (
        checkedRead::getOrDefault
        (
            coeffs, "n", dimless, 1.2, checkedRead::positive()
        ).value()
    ),
    span_(Tc_ - dTm_ - 273.16)
{
    if (span_ <= 0)
    {
        FatalIOErrorInFunction(coeffs)
            << "Keywords 'Tc' = " << Tc_ << " and 'dTm' = " << dTm_
            << " put the zero of the surface tension, Tc - dTm, at or below"
            << " the triple point 273.16 K in dictionary " << coeffs.name()
            << nl << exit(FatalIOError);
    }
    Tmax_ = Tc_ - dTm_;
}

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::surfaceTensionLaws::hsiehKaviany::sigma
(
    const scalar T
) const
{
    checkRange(T);
    const scalar x = 1 - (T - 273.16)/span_;
    return (x > 0) ? sigma0_*std::pow(x, n_) : scalar(0);
}


Foam::scalar Foam::surfaceTensionLaws::hsiehKaviany::dSigmadT
(
    const scalar T
) const
{
    checkRange(T);
    const scalar x = 1 - (T - 273.16)/span_;
    return (x > 0) ? -sigma0_*n_*std::pow(x, n_ - 1)/span_ : scalar(0);
}

// ************************************************************************* //
