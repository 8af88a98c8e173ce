/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "effectiveConductivityModel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(effectiveConductivityModel, 0);
    defineRunTimeSelectionTable(effectiveConductivityModel, dictionary);
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::effectiveConductivityModel::effectiveConductivityModel
(
    const dictionary& coeffs
)
:
    coeffs_(coeffs)
{}


// ************************************************************************* //
