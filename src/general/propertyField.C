/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "propertyField.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::word Foam::cellFieldInstance(const fvMesh& mesh, const word& name)
{
    const Time& runTime = mesh.time();
    const word start
    (
        runTime.timeName
        (
            runTime.controlDict().getOrDefault<scalar>
            (
                "startTime", runTime.startTime().value()
            )
        )
    );
    for (const word& instance : {runTime.timeName(), start})
    {
        IOobject io
        (
            name, instance, mesh, IOobject::MUST_READ, IOobject::NO_WRITE,
            false
        );
        if (io.typeHeaderOk<volScalarField>(true))
        {
            return instance;
        }
    }
    return word::null;
}


Foam::volScalarField Foam::propertyField
(
    const fvMesh& mesh,
    const word& name,
    const dimensionedScalar& uniformValue
)
{
    const word instance(cellFieldInstance(mesh, name));
    IOobject io
    (
        name,
        instance.empty() ? mesh.time().timeName() : instance,
        mesh,
        IOobject::MUST_READ,
        IOobject::NO_WRITE
    );

    if (!instance.empty())
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
    scalarField& values,
    word& instance
)
{
    const word found(cellFieldInstance(mesh, name));
    if (found.empty())
    {
        return false;
    }
    instance = found;
    IOobject io
    (
        name, instance, mesh, IOobject::MUST_READ, IOobject::NO_WRITE, false
    );
    volScalarField fld(io, mesh);
    values = fld.primitiveField();
    return true;
}

// ************************************************************************* //
