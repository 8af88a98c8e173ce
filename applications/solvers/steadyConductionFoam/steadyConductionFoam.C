/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
-------------------------------------------------------------------------------
Application
    steadyConductionFoam

Description
    Steady heat conduction with a conductivity that varies from cell to cell
    (a composite: solid grains, liquid bridges, gas), as in Mansour (2015)
    §2.3, eq. 2.9:

        div(kappa grad T) = 0

    kappa is the cell field 0/kappa [W/(m K)] (> 0, checked); its face
    values are fvc::interpolate(kappa), whose scheme fvSchemes sets
    (interpolate(kappa) harmonic: the exact series conductance of two
    half-cells of a piecewise constant kappa). laplacianFoam has a uniform
    DT, hence this solver. One SIMPLE iteration with the non-orthogonal
    correctors of fvSolution SIMPLE solves the linear problem.

    Prints, and writes to postProcessing/heatFlow.dat (with its area), the
    heat flow [W] into the domain through each patch that is neither empty, wedge,
    symmetry nor coupled: Q_p = sum_f kappa_f snGrad(T)_f |S_f| (for a
    wedge mesh: the flow through the wedge; etc/grainScale scales it).

Usage
    steadyConductionFoam

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "simpleControl.H"
#include "OFstream.H"
#include "emptyPolyPatch.H"
#include "wedgePolyPatch.H"
#include "symmetryPolyPatch.H"
#include "symmetryPlanePolyPatch.H"
#include "checkedRead.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Steady conduction div(kappa grad T) = 0 with the cell field"
        " 0/kappa; prints the heat flow through each patch"
    );

    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    simpleControl simple(mesh);

    Info<< "Reading field T" << endl;
    volScalarField T
    (
        IOobject("T", runTime.timeName(), mesh, IOobject::MUST_READ,
            IOobject::AUTO_WRITE),
        mesh
    );
    if (T.dimensions() != dimTemperature)
    {
        FatalErrorInFunction
            << "Field T (" << T.objectPath() << ") has dimensions "
            << T.dimensions() << ": expected a temperature "
            << dimTemperature << nl << exit(FatalError);
    }

    Info<< "Reading field kappa" << endl;
    volScalarField kappa
    (
        IOobject("kappa", runTime.timeName(), mesh, IOobject::MUST_READ,
            IOobject::NO_WRITE),
        mesh
    );
    if (kappa.dimensions() != dimPower/dimLength/dimTemperature)
    {
        FatalErrorInFunction
            << "Field kappa (" << kappa.objectPath() << ") has dimensions "
            << kappa.dimensions() << ": expected W/(m K) "
            << dimPower/dimLength/dimTemperature << nl << exit(FatalError);
    }
    checkedRead::check
    (
        kappa.objectPath(), "kappa", kappa.primitiveField(),
        checkedRead::positive()
    );

    const surfaceScalarField kappaf("kappaf", fvc::interpolate(kappa));

    Info<< nl << "Solving div(kappa grad T) = 0" << endl;

    while (simple.loop())
    {
        while (simple.correctNonOrthogonal())
        {
            fvScalarMatrix TEqn(fvm::laplacian(kappaf, T));
            TEqn.solve();
        }

        // Heat flow into the domain through each boundary patch
        autoPtr<OFstream> osPtr;
        if (Pstream::master())
        {
            mkDir(runTime.globalPath()/"postProcessing");
            osPtr.reset
            (
                new OFstream(runTime.globalPath()/"postProcessing/heatFlow.dat")
            );
            osPtr() << "# patch heatFlowIn [W] area [m2]" << nl;
        }
        forAll(mesh.boundary(), patchi)
        {
            const fvPatch& p = mesh.boundary()[patchi];
            if
            (
                p.coupled()
             || isA<emptyPolyPatch>(p.patch())
             || isA<wedgePolyPatch>(p.patch())
             || isA<symmetryPolyPatch>(p.patch())
             || isA<symmetryPlanePolyPatch>(p.patch())
            )
            {
                continue;
            }
            const scalar Q = gSum
            (
                kappaf.boundaryField()[patchi]
               *T.boundaryField()[patchi].snGrad()
               *p.magSf()
            );
            const scalar A = gSum(p.magSf());
            Info<< "heat flow into the domain through patch " << p.name()
                << " = " << Q << " W (area " << A << " m2)" << endl;
            if (osPtr.valid())
            {
                osPtr() << p.name() << ' ' << Q << ' ' << A << nl;
            }
        }

        runTime.write();
        runTime.printExecutionTime(Info);
    }

    Info<< "End\n" << endl;

    return 0;
}

// ************************************************************************* //
