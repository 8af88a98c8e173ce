/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "linearSurfaceTension.H"
#include "addToRunTimeSelectionTable.H"
#include "checkedRead.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace surfaceTensionLaws
{
    defineTypeNameAndDebug(linear, 0);
    addToRunTimeSelectionTable(surfaceTensionLaw, linear, dictionary);
}
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::surfaceTensionLaws::linear::linear(const dictionary& coeffs)
:
    surfaceTensionLaw(coeffs),
    a_
    (
        checkedRead::getOrDefault
        (
            coeffs, "a", dimForce/dimLength, 76e-3, checkedRead::positive()
        ).value()
    ),
    b_
    (
        checkedRead::getOrDefault
        (
            coeffs, "b", dimForce/dimLength/dimTemperature, 0.17e-3,
            checkedRead::nonNegative()
        ).value()
    )
{
    // The zero of the law
    Tmax_ = b_ > 0 ? 273.15 + a_/b_ : GREAT;
}

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::surfaceTensionLaws::linear::sigma(const scalar T) const
{
    checkRange(T);
    return max(a_ - b_*(T - 273.15), scalar(0));
}


Foam::scalar Foam::surfaceTensionLaws::linear::dSigmadT(const scalar T) const
{
    checkRange(T);
    return (a_ - b_*(T - 273.15) > 0) ? -b_ : scalar(0);
}

// ************************************************************************* //
