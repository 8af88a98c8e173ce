/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "interpolationCellLinear.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{
    // Scalar and vector fields (the gradient of a tensor would be of
    // third rank)
    makeInterpolationType(interpolationCellLinear, scalar);
    makeInterpolationType(interpolationCellLinear, vector);
}

// ************************************************************************* //
