/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "rankineSaturationPressure.H"
#include "addToRunTimeSelectionTable.H"
#include "checkedRead.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace saturationPressureLaws
{
    defineTypeNameAndDebug(rankine, 0);
    addToRunTimeSelectionTable(saturationPressureLaw, rankine, dictionary);
}
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::saturationPressureLaws::rankine::rankine(const dictionary& coeffs)
:
    saturationPressureLaw(coeffs),
    p0_
    (
        checkedRead::getOrDefault
        (
            coeffs, "p0", dimPressure, 1e5, checkedRead::positive()
        ).value()
    ),
    A_
    (
        checkedRead::getOrDefault
        (
            coeffs, "A", dimless, 13.7, checkedRead::closed(-GREAT, GREAT)
        ).value()
    ),
    B_
    (
        checkedRead::getOrDefault
        (
            coeffs, "B", dimTemperature, 5120, checkedRead::positive()
        ).value()
    )
{}

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::saturationPressureLaws::rankine::pSat(const scalar T) const
{
    checkRange(T);
    return p0_*std::exp(A_ - B_/T);
}


Foam::scalar Foam::saturationPressureLaws::rankine::dpSatdT
(
    const scalar T
) const
{
    return pSat(T)*B_/(T*T);
}

// ************************************************************************* //
