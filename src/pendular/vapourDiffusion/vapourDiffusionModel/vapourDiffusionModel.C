/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "vapourDiffusionModel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(vapourDiffusionModel, 0);
    defineRunTimeSelectionTable(vapourDiffusionModel, dictionary);
}

// ************************************************************************* //
