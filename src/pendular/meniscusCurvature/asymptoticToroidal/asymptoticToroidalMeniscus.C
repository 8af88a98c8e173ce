/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "asymptoticToroidalMeniscus.H"
#include "addToRunTimeSelectionTable.H"
#include "checkedRead.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace meniscusCurvatureModels
{
    defineTypeNameAndDebug(asymptoticToroidal, 0);
    addToRunTimeSelectionTable
    (
        meniscusCurvatureModel,
        asymptoticToroidal,
        dictionary
    );
}
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::meniscusCurvatureModels::asymptoticToroidal::asymptoticToroidal
(
    const dictionary& coeffs
)
:
    meniscusCurvatureModel(coeffs),
    R0_
    (
        checkedRead::get(coeffs, "R0", dimLength, checkedRead::positive())
       .value()
    ),
    C_
    (
        checkedRead::getOrDefault
        (
            coeffs, "C", dimless, 5.06, checkedRead::positive()
        ).value()
    ),
    cB_
    (
        checkedRead::getOrDefault
        (
            coeffs, "cB", dimless, 7.82e-2, checkedRead::positive()
        ).value()
    )
{}

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::meniscusCurvatureModels::asymptoticToroidal::K
(
    const scalar alphaL
) const
{
    return -C_/(R0_*std::sqrt(limited(alphaL)));
}


Foam::scalar Foam::meniscusCurvatureModels::asymptoticToroidal::dKdAlphaL
(
    const scalar alphaL
) const
{
    const scalar a = limited(alphaL);
    return 0.5*C_/(R0_*a*std::sqrt(a));
}


Foam::scalar Foam::meniscusCurvatureModels::asymptoticToroidal::alphaL
(
    const scalar K
) const
{
    // K >= K(1) = -C/R0: alpha_l >= 1, outside the range (and K = 0 would
    // divide by zero)
    if (-K*R0_ <= C_)
    {
        return 1;
    }
    const scalar a = sqr(C_/(R0_*K));
    return a > alphaLTiny ? a : scalar(0);
}


Foam::scalar
Foam::meniscusCurvatureModels::asymptoticToroidal::nonEquilibriumCoeff() const
{
    return cB_;
}


Foam::scalar
Foam::meniscusCurvatureModels::asymptoticToroidal::nonEquilibriumExponent()
const
{
    return -0.75;
}

// ************************************************************************* //
