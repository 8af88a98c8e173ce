/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "propertyField.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::word Foam::cellFieldInstance(const fvMesh& mesh, const word& name)
{
    // The latest time at or before the run's that holds the file
    // (Time::findInstance): the solvers do not write the material fields,
    // so a run restarted from latestTime or from a startTime reads those
    // of the first run's start, or the ones soilProfile wrote at a later
    // time (review 2026-12-05d: controlDict's startTime alone missed both)
    const word instance
    (
        mesh.time().findInstance
        (
            mesh.dbDir(), name, IOobject::READ_IF_PRESENT
        )
    );
    if (instance.empty() || instance == mesh.time().constant())
    {
        return word::null;
    }
    IOobject io
    (
        name, instance, mesh, IOobject::MUST_READ, IOobject::NO_WRITE, false
    );
    return io.typeHeaderOk<volScalarField>(true) ? instance : word::null;
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
