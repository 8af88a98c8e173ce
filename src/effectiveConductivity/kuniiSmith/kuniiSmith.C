/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "kuniiSmith.H"
#include "addToRunTimeSelectionTable.H"
#include "checkedRead.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace effectiveConductivityModels
{
    defineTypeNameAndDebug(kuniiSmith, 0);
    addToRunTimeSelectionTable
    (
        effectiveConductivityModel,
        kuniiSmith,
        dictionary
    );
}
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::effectiveConductivityModels::kuniiSmith::kuniiSmith
(
    const dictionary& coeffs
)
:
    twoComponentConductivityModel(coeffs),
    beta_
    (
        checkedRead::getOrDefault
        (
            coeffs, "beta", dimless, 0.895, checkedRead::positive()
        ).value()
    ),
    Phi_
    (
        checkedRead::getOrDefault
        (
            coeffs, "Phi", dimless, 0.058, checkedRead::positive()
        ).value()
    )
{}

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::effectiveConductivityModels::kuniiSmith::kappa
(
    const scalar kappaSolid,
    const scalar kappaFluid,
    const scalar porosity
) const
{
    return
        kappaFluid
       *(porosity + (1.0 - porosity)*beta_/(kappaFluid/kappaSolid + Phi_));
}

// ************************************************************************* //
