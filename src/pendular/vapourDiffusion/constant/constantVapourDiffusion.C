/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "constantVapourDiffusion.H"
#include "addToRunTimeSelectionTable.H"
#include "checkedRead.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace vapourDiffusionModels
{
    defineTypeNameAndDebug(constant, 0);
    addToRunTimeSelectionTable(vapourDiffusionModel, constant, dictionary);
}
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::vapourDiffusionModels::constant::constant(const dictionary& dict)
:
    vapourDiffusionModel(),
    tortuosity_
    (
        checkedRead::getOrDefault
        (
            dict, "tortuosity", dimless, 0.5, checkedRead::closed(SMALL, 1)
        ).value()
    )
{}

// ************************************************************************* //
