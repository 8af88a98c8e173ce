/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
-------------------------------------------------------------------------------
Application
    pendularFoam

Description
    Heat, Darcy flow of the air/vapour mixture, Fick diffusion of the vapour
    and evaporation/condensation of the pendular water of a granular soil
    (EWGM report, Canot 2024, §1-2, model A: local Kelvin-Laplace
    equilibrium of the vapour with the menisci; model B with the water
    model nonEquilibrium). Conservation laws, per bulk volume (the state
    class pendularState: the unknowns, the closures of pendularMedium and
    its waterModel, the face fluxes and these balances' residuals):

        water   dW/dt + div(F_w) = 0,  F_w = rho_w v_g + j
        air     dA/dt + div(F_a) = 0,  F_a = rho_a v_g - j
        energy  dE/dt + div(-k_e grad T + F_a h_a + F_w h_w) = 0

        v_g = -(K_g/mu_g) grad p_g            (Darcy, eq. 10)
        j   = -xi D_wa rho_g grad(rho_w/rho_g)   (Fick, eq. 3)
        (xi: the soil's vapourDiffusionModel, by default tau_s)

    Unknowns: T, p_g and the water content W; the liquid fraction alpha_l,
    the vapour pressure p_w (Kelvin-Laplace) and the air pressure
    p_a = p_g - p_w follow in each cell. Each step is implicit (backward
    Euler, or BDF2: the time scheme's default, pendularEngineSetup); with
    engine segregated the three equations are solved in turn for corrections with
    approximate Jacobians (total gas mass for p_g, the water at fixed p_g
    for W, the energy at fixed p_g and W for T) and iterated until every
    correction is below its tolerance, so that the discrete conservation
    laws hold with the exact face fluxes: the water and energy balances
    close to the tolerance. A step that does not converge is cut and
    retried.

    Boundary conditions (report §2) follow from those of T, p (p_g) and pw:
        heated and open:      T fixed (table, fireTemperature ...),
                              p and pw fixed (pw a history if needed);
        heated and impermeable: T fixed, p and pw zeroGradient;
        insulated and impermeable: zeroGradient for all three.
    On an impermeable patch no gas or vapour crosses; on an open one the
    gas leaving carries the cell's composition and enthalpy, the gas
    entering the atmosphere's.

    Controls (adaptiveTimeStepControls: read and range-checked before the
    first step):
        system/controlDict: adjustTimeStep, maxDeltaT, minDeltaT,
                            maxDeltaTemperature, maxDeltaTGrowth
        system/fvSolution:  nonlinear { engine; maxIter; TTol; pTol;
                            WTol; balanceTolerance; strictBalance; }
    engine: newton (Newton on the coupled balances of a sub-step:
    src/coupled pendularNewton, its linear solver set by fvSolution's
    optional 'coupled' dictionary; the default, models A and B, model B
    backward Euler only, on any mesh) or segregated (the iterations
    above, only when asked). The engine's and the time scheme's
    defaults, refusals and the Newton steps' linear solver: src/coupled
    pendularEngineSetup.
    Saturated zone (liquidFlow's saturatedZone, Newton engine; issue 14):
    a cell is two-phase (T, p_g, W) or liquid-only (T, p_l, X, X the air
    dissolved per mass of water by Henry's law; primary-variable switching,
    Class, Helmig & Bastian 2002), switched by pendularNewton between its
    iterations. The phase state is carried from sub-step to sub-step
    (restored on a rejected one) and written: gasPresent (1/0), Xair, pl;
    in a liquid-only cell p holds p_l + p_c(1) and W its water. At the
    start 0/alphaL = 1 makes a cell liquid-only at its bubble point (p_l =
    p - p_c(1), X Henry's at p - p_w(T, 1)), unless gasPresent, Xair and
    pl are given. nonlinear { gasSeed; } is the gas fraction a cell starts
    with when its gas appears (default 1e-4). The air dissolved in the
    liquid crossing a patch is in the air balance.
    A water, air or energy balance missing balanceTolerance (default 1e-6)
    prints a warning (balanceMonitor); with strictBalance true (default
    false) it makes the exit status 1. T must
    be above 0 K (and the initial soil at or above 200 K: temperatureCheck).
    Restart (startFrom latestTime): the step controller's state
    (uniform/subStepController) and BDF2's level before the last accepted
    sub-step (pendularBdf2Levels: <time>/*.bdf2Old*, T.bdf2Older,
    uniform/variableStepBdf2) are read back, so that the resumed run takes
    the uninterrupted run's steps; a time written without them is resumed
    with a first step by backward Euler (said in the log).

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "pendularState.H"
#include "checkedRead.H"
#include "andersonAcceleration.H"
#include "adaptiveTimeStepControls.H"
#include "subStepController.H"
#include "OStringStream.H"
#include "variableStepBdf2.H"
#include "pendularBdf2Levels.H"
#include "balanceMonitor.H"
#include "temperatureCheck.H"
#include "upwind.H"
#include "gaussConvectionScheme.H"
#include "petscSession.H"
#include "pendularNewton.H"
#include "pendularEngineSetup.H"
#include "meshNonOrthogonality.H"
#include "nanInjection.H"
#include "exitWithStatus.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Heat, Darcy air/vapour flow, vapour diffusion and pendular water"
        " (EWGM model A) in a granular soil"
    );

    #include "setRootCaseLists.H"
    adaptiveTimeStepControls::checkTimeEntries(args);
    #include "createTime.H"
    #include "createMesh.H"
    #include "readControls.H"
    #include "checkNonlinearKeywords.H"
    #include "createFields.H"
    #include "createBalances.H"
    #include "createNewton.H"

    // A restart's local error limit (uniform/subStepController) holds only
    // where this run makes local error estimates: BDF2 with adaptive steps
    if (scheme != timeScheme::BDF2 || !stepControls.adjustTimeStep())
    {
        subSteps.clearNextStepLimit();
    }
    #include "restartBdf2.H"

    Info<< "\nStarting time loop\n" << endl;

    while (runTime.run())
    {
        subSteps.setDeltaT(runTime);

        ++runTime;

        Info<< "Time = " << runTime.timeName() << nl << endl;

        #include "solveStep.H"

        if (runTime.writeTime() && scheme == timeScheme::BDF2)
        {
            bdf2Levels.store(bdf2, pRef, AOlder, EOlder);
        }
        runTime.write();

        if (runTime.writeTime())
        {
            #include "reportBalances.H"
        }

        runTime.printExecutionTime(Info);
    }

    Info<< "End\n" << endl;

    // Non-zero if a balance missed balanceTolerance. PETSc ends before MPI
    // (exitWithStatus does not return: main's objects are not destroyed)
    const int status = balances.exitStatus();
    newton.clear();
    petsc.clear();
    exitWithStatus(status);
}


// ************************************************************************* //
