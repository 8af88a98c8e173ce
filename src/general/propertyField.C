/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "propertyField.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::volScalarField Foam::propertyField
(
    const fvMesh& mesh,
    const word& name,
    const dimensionedScalar& uniformValue
)
{
    IOobject io
    (
        name,
        mesh.time().timeName(),
        mesh,
        IOobject::MUST_READ,
        IOobject::NO_WRITE
    );

    if (io.typeHeaderOk<volScalarField>(true))
    {
        Info<< "    " << name << ": cell field from " << io.objectPath()
            << endl;
        volScalarField fld(io, mesh);
        fld.dimensions().reset(uniformValue.dimensions());
        return fld;
    }

    io.readOpt() = IOobject::NO_READ;
    return volScalarField(io, mesh, uniformValue);
}

// ************************************************************************* //
