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


bool Foam::readCellValues
(
    const fvMesh& mesh,
    const word& name,
    scalarField& values
)
{
    IOobject io
    (
        name,
        mesh.time().timeName(),
        mesh,
        IOobject::MUST_READ,
        IOobject::NO_WRITE,
        false
    );
    if (!io.typeHeaderOk<volScalarField>(true))
    {
        return false;
    }
    volScalarField fld(io, mesh);
    values = fld.primitiveField();
    return true;
}

// ************************************************************************* //
