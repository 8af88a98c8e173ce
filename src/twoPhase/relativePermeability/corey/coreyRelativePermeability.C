/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "coreyRelativePermeability.H"
#include "addToRunTimeSelectionTable.H"
#include "checkedRead.H"

#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace relativePermeabilityModels
{
    defineTypeNameAndDebug(corey, 0);
    addToRunTimeSelectionTable
    (
        relativePermeabilityModel,
        corey,
        dictionary
    );
}
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::relativePermeabilityModels::corey::corey
(
    const dictionary& dict,
    const dictionary& coeffs
)
:
    relativePermeabilityModel(dict, coeffs),
    nl_
    (
        checkedRead::get
        (
            coeffs, "nl", dimless, checkedRead::closed(1, GREAT)
        ).value()
    ),
    ng_
    (
        checkedRead::get
        (
            coeffs, "ng", dimless, checkedRead::closed(1, GREAT)
        ).value()
    )
{}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::relativePermeabilityModels::corey::krlEff
(
    const scalar Se
) const
{
    return std::pow(Se, nl_);
}


Foam::scalar Foam::relativePermeabilityModels::corey::krgEff
(
    const scalar Se
) const
{
    return std::pow(1 - Se, ng_);
}


Foam::scalar Foam::relativePermeabilityModels::corey::dkrldSeEff
(
    const scalar Se
) const
{
    return nl_*std::pow(Se, nl_ - 1);
}


Foam::scalar Foam::relativePermeabilityModels::corey::dkrgdSeEff
(
    const scalar Se
) const
{
    return -ng_*std::pow(1 - Se, ng_ - 1);
}

// ************************************************************************* //
