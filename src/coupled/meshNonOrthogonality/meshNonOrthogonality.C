/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "meshNonOrthogonality.H"
#include "surfaceFields.H"
#include "unitConversion.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(meshNonOrthogonality, 0);
}

const Foam::scalar Foam::meshNonOrthogonality::correctedTan = 1e-6;


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::meshNonOrthogonality::meshNonOrthogonality(const fvMesh& mesh)
:
    MeshObject<fvMesh, Foam::GeometricMeshObject, meshNonOrthogonality>
    (
        mesh
    ),
    tanMax_(0)
{
    const surfaceVectorField& k = mesh.nonOrthCorrectionVectors();
    tanMax_ = max(mag(k.primitiveField()));
    forAll(k.boundaryField(), patchi)
    {
        if (k.boundaryField()[patchi].coupled())
        {
            tanMax_ = max(tanMax_, max(mag(k.boundaryField()[patchi])));
        }
    }
    reduce(tanMax_, maxOp<scalar>());
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::meshNonOrthogonality::maxDegrees() const
{
    return radToDeg(Foam::atan(tanMax_));
}


// ************************************************************************* //
