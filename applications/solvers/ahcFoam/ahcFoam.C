/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
-------------------------------------------------------------------------------
Application
    ahcFoam

Description
    Transient conduction in a wet porous soil with evaporation of its water
    by the apparent heat capacity (AHC) method (Muhieddine 2009 §3.1,
    Mansour 2015 §4.1), in conservative enthalpy form:

        dH(T; TMax)/dt = div(k_e(T; TMax) grad T)

    H and k_e come from porousMedium (constant/soilProperties). Each step
    is implicit (backward Euler) and solved by modified-Picard iterations

        C^k (T^{k+1} - T^k)/dt + (H^k - H^n)/dt = div(k_e^k grad T^{k+1})

    until the normalised residual and the temperature change fall below
    their tolerances; at convergence H(T^{n+1}) - H^n is exactly the heat
    that entered, so the energy balance closes to the solver tolerance.
    A step that does not converge is cut in half and retried. The time step
    adapts to the largest temperature change per step and the iteration
    count. TMax, the maximum temperature reached in each cell, is written
    with T and the liquid water content. Each write prints the energy
    balance since the start of the run and the liquid water: now, at the
    start (of this part of a resumed run) and their difference, the water
    evaporated since then (reportEnergyBalance.H).

    Controls (adaptiveTimeStepControls: read and range-checked before the
    first step):
        system/controlDict:  adjustTimeStep, maxDeltaT, maxDeltaTemperature,
                             minDeltaT, maxDeltaTGrowth
        system/fvSolution:   nonlinear { maxIter; residualTol; TTol;
                             andersonDepth; extrapolate; linearRelTol;
                             conductivityJacobian; balanceTolerance;
                             strictBalance; }
    linearRelTol (default 0.01; 0 with conductivityJacobian): the linear
    solve of an iteration may stop at this fraction of its initial residual
    (inexact Newton, Dembo, Eisenstat & Steihaug 1982); an iteration that
    converges on such a solve is solved again to the solver's tolerances
    before it is accepted, so the energy balance is that of a full solve;
    after a sub-step whose linearisation was exact, the next first solve is
    full.
    conductivityJacobian (default false) adds Newton's derivative of the
    conduction fluxes with respect to k_e(T) to each iteration
    (conductivityJacobian.H): an asymmetric matrix, solved by PBiCGStab
    with DILU if the solver of T is PCG.
    An energy balance missing balanceTolerance (default 1e-6) prints a
    warning and makes the exit status 1 (balanceMonitor; strictBalance
    false: warning only). T must be above 0 K, and the initial soil at or
    above 200 K (temperatureCheck).

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "gaussLaplacianScheme.H"
#include "uncorrectedSnGrad.H"
#include "porousMedium.H"
#include "checkedRead.H"
#include "andersonAcceleration.H"
#include "conductivityJacobian.H"
#include "adaptiveTimeStepControls.H"
#include "subStepController.H"
#include "balanceMonitor.H"
#include "exitWithStatus.H"
#include "temperatureCheck.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Conduction in a wet porous soil with evaporation of its water"
        " (apparent heat capacity method)"
    );

    #include "setRootCaseLists.H"
    adaptiveTimeStepControls::checkTimeEntries(args);
    #include "createTime.H"
    #include "createMesh.H"
    #include "createControls.H"
    #include "checkNonlinearKeywords.H"
    #include "createFields.H"
    #include "createEnergyBalance.H"

    Info<< "\nStarting time loop\n" << endl;

    while (runTime.run())
    {
        #include "readControls.H"
        subSteps.setDeltaT(runTime);

        ++runTime;

        Info<< "Time = " << runTime.timeName() << nl << endl;

        #include "solveStep.H"

        if (runTime.writeTime())
        {
            liquidWater.primitiveFieldRef() =
                medium.liquidWater(T.primitiveField(), TMax.primitiveField());
            liquidWater.correctBoundaryConditions();
        }

        runTime.write();

        if (runTime.writeTime())
        {
            #include "reportEnergyBalance.H"
        }

        runTime.printExecutionTime(Info);
    }

    Info<< "End\n" << endl;

    // Non-zero if an energy balance missed balanceTolerance
    exitWithStatus(balances.exitStatus());
}


// ************************************************************************* //
