/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
-------------------------------------------------------------------------------
Application
    testAhcResidual

Description
    The discrete energy equation of ahcFoam recomputed from its written
    fields, step by step: for each pair of consecutive written times
    t^n, t^{n+1} (every step written, fixed steps),

        r_P = V_P (H(T^{n+1}; TMax^{n+1}) - H(T^n; TMax^n))/dt
            - V_P [div(k_e(T^{n+1}) grad T^{n+1})]_P

    with the soil's H and k_e (porousMedium) and the case's laplacian
    scheme. Backward Euler with every coefficient at the new time level
    makes r vanish to the solver tolerance. Printed per step:

        step <t> residual <max|r|/s> lagged <max|r_lag|/s>

    with s = max_P |V_P (H^{n+1} - H^n)/dt| (the largest rate of storage of
    the step) and r_lag the same residual with k_e at the old time level:
    what a solver whose conductivity lags a step would leave. The test
    checks the first against the solver tolerance and the second against
    the first, to show the case can tell the two apart.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "porousMedium.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Residual of ahcFoam's discrete energy equation recomputed from the"
        " written fields of consecutive steps"
    );
    timeSelector::addOptions();

    #include "setRootCase.H"
    #include "createTime.H"

    instantList times = timeSelector::select0(runTime, args);
    if (times.size() < 2)
    {
        FatalErrorInFunction
            << "Need at least two written times, found " << times.size()
            << exit(FatalError);
    }

    #include "createMesh.H"

    porousMedium medium(mesh);
    const scalarField& V = mesh.V();

    const auto readField = [&](const word& name)
    {
        return volScalarField
        (
            IOobject
            (
                name,
                runTime.timeName(),
                mesh,
                IOobject::MUST_READ,
                IOobject::NO_WRITE
            ),
            mesh
        );
    };

    // TMax as ahcFoam starts it where the initial time has none: T
    const auto readTMax = [&](const volScalarField& T)
    {
        IOobject io
        (
            "TMax",
            runTime.timeName(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        );
        if (io.typeHeaderOk<volScalarField>(true))
        {
            return volScalarField(io, mesh);
        }
        return volScalarField("TMax", T);
    };

    runTime.setTime(times[0], 0);
    volScalarField T0(readField("T"));
    volScalarField TMax0(readTMax(T0));

    for (label i = 1; i < times.size(); ++i)
    {
        const scalar dt = times[i].value() - times[i-1].value();
        runTime.setTime(times[i], i);
        const volScalarField T1(readField("T"));
        const volScalarField TMax1(readTMax(T1));

        const scalarField storage
        (
            V
           *(
                medium.enthalpy(T1.primitiveField(), TMax1.primitiveField())
              - medium.enthalpy(T0.primitiveField(), TMax0.primitiveField())
            )/dt
        );

        // k_e at the new and at the old time level, each with its own
        // boundary values; the gradient always of the new T
        const tmp<volScalarField> kappaNew(medium.kappa(T1, TMax1));
        const tmp<volScalarField> kappaOld(medium.kappa(T0, TMax0));

        const scalarField r
        (
            storage
          - V*fvc::laplacian(fvc::interpolate(kappaNew()), T1)().primitiveField()
        );
        const scalarField rLagged
        (
            storage
          - V*fvc::laplacian(fvc::interpolate(kappaOld()), T1)().primitiveField()
        );

        const scalar scale = max(gMax(mag(storage)), VSMALL);
        Info<< "step " << runTime.timeName()
            << " residual " << gMax(mag(r))/scale
            << " lagged " << gMax(mag(rLagged))/scale
            << " scale " << scale << endl;

        T0 == T1;
        TMax0 == TMax1;
    }

    Info<< "End" << endl;

    return 0;
}


// ************************************************************************* //
