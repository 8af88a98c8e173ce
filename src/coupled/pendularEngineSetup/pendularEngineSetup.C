/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "pendularEngineSetup.H"
#include "pendularMedium.H"
#include "pendularResidual.H"
#include "meshNonOrthogonality.H"
#include "variableStepBdf2.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::pendularEngineSetup::engine>
Foam::pendularEngineSetup::engineNames
({
    { engine::segregated, "segregated" },
    { engine::newton, "newton" }
});


const Foam::Enum<Foam::pendularEngineSetup::timeScheme>
Foam::pendularEngineSetup::timeSchemeNames
({
    { timeScheme::Euler, "Euler" },
    { timeScheme::BDF2, "BDF2" }
});


const Foam::label Foam::pendularEngineSetup::cprMinCells;


const Foam::wordList Foam::pendularEngineSetup::preconditionerKeys
({
    "preconditioner", "subPreconditioner", "iluLevels", "asmOverlap",
    "petscOptions"
});


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::string Foam::pendularEngineSetup::eulerDefault
(
    const engine eng,
    const pendularMedium& medium,
    const adaptiveTimeStepControls& controls
)
{
    if (eng != engine::newton)
    {
        return "engine segregated (backward Euler only)";
    }
    if (medium.nonEquilibrium())
    {
        return
            "model B (waterModel nonEquilibrium: its rate law is backward"
            " Euler's)";
    }
    if (medium.saturatedZone())
    {
        // Measured (2026-12-04): tests/pendularWaterTable's ponded column
        // with BDF2 had 8 of its 10 cells liquid-only at 400 s instead of
        // 10, its steady Darcy flow 1e-4 off instead of 1e-6, and its
        // filling column no write with both phase states (BDF2's history
        // across a cell's phase switch is not examined)
        return
            "liquidFlow's saturatedZone (its phase switching not validated"
            " with BDF2)";
    }
    if (!controls.adjustTimeStep())
    {
        return
            "adjustTimeStep no (the given steps: no local error drives"
            " them)";
    }
    if (!(controls.maxDeltaTGrowth() < variableStepBdf2::maxStepRatio))
    {
        return
            "maxDeltaTGrowth " + Foam::name(controls.maxDeltaTGrowth())
          + " not below 1 + sqrt(2) (variable-step BDF2's zero-stability)";
    }
    return string();
}


Foam::pendularEngineSetup::timeScheme
Foam::pendularEngineSetup::selectTimeScheme
(
    const bool given,
    const timeScheme read,
    const engine eng,
    const pendularMedium& medium,
    const adaptiveTimeStepControls& controls,
    const scalar localErrorTol
)
{
    const string why =
        given ? string() : eulerDefault(eng, medium, controls);
    const timeScheme scheme =
        given ? read
      : why.empty() ? timeScheme::BDF2 : timeScheme::Euler;
    if (scheme == timeScheme::BDF2)
    {
        Info<< "Time scheme: BDF2 (variable-step, localErrorTol "
            << localErrorTol << " K"
            << (given ? ")" : "; the default)") << endl;
    }
    else
    {
        Info<< "Time scheme: Euler (backward Euler"
            << (
                   given ? string(")")
                 : "; the default with " + why + ")"
               ).c_str()
            << endl;
    }
    return scheme;
}


void Foam::pendularEngineSetup::checkEngine
(
    const fvMesh& mesh,
    const pendularMedium& medium,
    const dictionary& nonlinearDict,
    const engine eng,
    const timeScheme scheme
)
{
    // The Newton engine runs on any mesh: processor and cyclic patches as
    // internal faces, the fvSchemes' snGrad schemes with their own delta
    // coefficients and non-orthogonal corrections (pendularResidual). Its
    // refusals, before the log line below: BDF2 with model B (its rate
    // law, waterModels::nonEquilibrium, is backward Euler over the step),
    // an AMI patch (pendularResidual::checkCoupledPatches) and an snGrad
    // scheme other than corrected, uncorrected, limited, faceCorrected,
    // orthogonal (checkSnGradSchemes), a cyclic pair across which the
    // liquid's potential is not periodic (checkLiquidCoupledPatches)
    if (eng == engine::newton)
    {
        if (medium.nonEquilibrium() && scheme == timeScheme::BDF2)
        {
            FatalIOErrorInFunction(nonlinearDict)
                << "Keyword 'timeScheme' = BDF2 in " << nonlinearDict.name()
                << " with model B (waterModel nonEquilibrium in "
                << medium.closures("pendular").name() << "), whose liquid"
                << " fraction relaxes over each step by the backward-Euler"
                << " solution of its rate law: valid choices with model B:"
                << " Euler" << exit(FatalIOError);
        }
        pendularResidual::checkCoupledPatches(mesh);
        pendularResidual::checkSnGradSchemes(mesh);
        pendularResidual::checkLiquidCoupledPatches(mesh, medium);
    }
    if
    (
        eng == engine::newton
     && meshNonOrthogonality::New(mesh).corrected()
    )
    {
        Info<< "Non-orthogonal mesh (up to "
            << meshNonOrthogonality::New(mesh).maxDegrees()
            << " degrees): the Newton engine's face fluxes with the snGrad"
            << " schemes' non-orthogonal corrections, held fixed in its"
            << " Jacobian (deferred correction)" << endl;
    }
    // Settings of a scheme or engine not run: a warning, not an error (the
    // project's comparisons switch timeScheme or engine by one line and
    // keep the other's settings: tests/pendularBdf2, pendularResidual)
    if (scheme == timeScheme::Euler && nonlinearDict.found("localErrorTol"))
    {
        WarningInFunction
            << "Keyword 'localErrorTol' in " << nonlinearDict.name()
            << " ignored: the time scheme is Euler (localErrorTol drives"
            << " BDF2's steps only)" << endl;
    }
    if (eng != engine::newton && mesh.solutionDict().found("coupled"))
    {
        WarningInFunction
            << "Sub-dictionary 'coupled' in " << mesh.solutionDict().name()
            << " ignored: the engine is segregated (coupled sets the Newton"
            << " engine's linear solver)" << endl;
    }
    if (scheme == timeScheme::BDF2 && eng != engine::newton)
    {
        FatalIOErrorInFunction(nonlinearDict)
            << "Keyword 'timeScheme' = BDF2 in " << nonlinearDict.name()
            << " needs engine newton (the segregated engine is backward"
            << " Euler only): valid choices with engine segregated: Euler"
            << exit(FatalIOError);
    }
}


void Foam::pendularEngineSetup::checkLiquidFlow
(
    const pendularMedium& medium,
    const dictionary& nonlinearDict,
    const engine eng
)
{
    // K_g lowered twice: kozenyCarman lowers the gas permeability with
    // alpha_l and liquidFlow's k_rg(S) lowers it again (two-phase Darcy's
    // intrinsic form is gasPermeabilityModel constant with K_g = K)
    if
    (
        medium.liquidFlowPtr()
     && medium.closures("pendular").getOrDefault<word>
        (
            "gasPermeabilityModel", "kozenyCarman"
        ) == "kozenyCarman"
    )
    {
        WarningInFunction
            << "gasPermeabilityModel kozenyCarman in "
            << medium.closures("pendular").name() << " with liquidFlow: the"
            << " gas permeability is lowered with alpha_l by Kozeny-Carman"
            << " and again by liquidFlow's k_rg(S); for two-phase Darcy's"
            << " intrinsic permeability use gasPermeabilityModel constant"
            << endl;
    }
    // The liquid's capillary flow (the soil's liquidFlow) is a term of the
    // Newton engine's residual (pendularResidual) only
    if (medium.liquidFlowPtr() && eng != engine::newton)
    {
        FatalIOErrorInFunction(nonlinearDict)
            << "liquidFlow in " << medium.closures("pendular").name()
            << " needs nonlinear { engine newton; } in "
            << nonlinearDict.name()
            << ": the segregated engine has no liquid flow"
            << exit(FatalIOError);
    }
}


Foam::dictionary Foam::pendularEngineSetup::coupledSolverDict
(
    const fvMesh& mesh,
    const bool saturatedZone,
    string& chosenBy
)
{
    dictionary coupledDict
    (
        mesh.solutionDict().isDict("coupled")
      ? mesh.solutionDict().subDict("coupled")
      : dictionary(fileName(mesh.solutionDict().name() + ".coupled"))
    );
    chosenBy.clear();

    // The Newton steps to relTol 1e-8 of the residual only: blockSystem's
    // absolute tolerance, 1e-12, is above the residuals in kg/s and W of
    // small cells near convergence, and stopped GMRES before its first
    // iteration (measured: 2-rank Newton stalled with dx = 0); its relTol
    // 1e-10 is below the round-off of the residuals there
    if (!coupledDict.found("tolerance"))
    {
        coupledDict.add("tolerance", scalar(0));
    }
    // (relTol given: kept, also on several ranks, below)
    const bool relTolGiven = coupledDict.found("relTol");
    if (!relTolGiven)
    {
        coupledDict.add("relTol", scalar(1e-8));
    }

    // The preconditioner's keywords given (petscOptions counts when it
    // sets a preconditioner's option: -pc_type, -sub_pc_type, ...: a "pc_"
    // in the name)
    wordList given;
    for (const word& key : preconditionerKeys)
    {
        if
        (
            coupledDict.found(key)
         && (
                key != "petscOptions"
             || coupledDict.get<string>(key).find("pc_")
             != std::string::npos
            )
        )
        {
            given.append(key);
        }
    }

    // The cells of the whole mesh (collective, every rank: each takes the
    // same choice below)
    const label nGlobalCells = returnReduce(mesh.nCells(), sumOp<label>());

    // The saturated zone on a decomposed mesh: a direct solve (MUMPS) by
    // default. The liquid-only cells' block is nearly incompressible
    // (storage c_s ~ 1e-10 1/Pa against the Darcy coupling), and block
    // Jacobi, exact on one rank (ILU(0) of a 1-D column's block
    // tridiagonal matrix is its LU), drops the coupling across the
    // processor boundary: GMRES then broke down at 100-150 iterations
    // short of relTol, and Newton took 4-29 iterations a step instead of
    // 3-4 (issue 14; tests/pendularSaturatedDrying's 40 cells to 20 s, 2
    // ranks: 80 steps and 1132 Newton iterations with block Jacobi ILU, 10
    // steps and 37 iterations with lu, as serial; asm 42 steps, asm with
    // LU blocks and overlap 2 14). Only when the user chose nothing of the
    // preconditioner: any of preconditionerKeys keeps blockSystem's
    // default (block Jacobi) with the user's settings
    if (saturatedZone && Pstream::parRun())
    {
        if (given.empty())
        {
            coupledDict.add("preconditioner", word("lu"));
            chosenBy =
                "pendularFoam's default for the saturated zone on "
              + Foam::name(Pstream::nProcs()) + " ranks: block Jacobi drops"
                " the coupling of the nearly incompressible liquid-only"
                " cells across the processor boundaries; set another"
                " preconditioner in " + coupledDict.name() + " to override";
            Info<< "Saturated zone on " << Pstream::nProcs() << " ranks: the"
                << " Newton steps solved by LU (MUMPS) by default (coupled {"
                << " preconditioner lu; }; give another 'preconditioner' in"
                << " system/fvSolution's coupled to override)" << endl;
        }
        else
        {
            Info<< "Saturated zone on " << Pstream::nProcs() << " ranks:"
                << " the preconditioner of the Newton steps as set in "
                << coupledDict.name() << " (" << given << " given; LU,"
                << " MUMPS, the default only when none of "
                << preconditionerKeys << " is given)" << endl;
        }
    }

    // Otherwise, when the user chose nothing of the preconditioner, CPR
    // (blockSystem: an AMG V-cycle on the decoupled gas pressure, then
    // block Jacobi/ILU(0)) on meshes of at least cprMinCells cells of the
    // whole mesh, block Jacobi/ILU(0) below
    if (given.empty() && chosenBy.empty() && nGlobalCells >= cprMinCells)
    {
        coupledDict.add("preconditioner", word("cpr"));
        chosenBy =
            "pendularFoam's default on " + Foam::name(nGlobalCells)
          + " cells, at least " + Foam::name(cprMinCells) + "; set"
            " another preconditioner in " + coupledDict.name()
          + " to override";
    }

    // Below cprMinCells on a decomposed mesh, block Jacobi/ILU(0) with
    // the solves diagonally scaled (blockSystem's diagonalScale), unless
    // the user chose the preconditioner or diagonalScale. Block Jacobi
    // drops the coupling across the processor boundary, and GMRES then
    // stopped at relTol 1e-8 of a residual norm that the largest rows
    // (W of the energy balance) decide, or broke down at its restarts:
    // the Newton steps inexact (2 ranks: 8228 Newton iterations against
    // serial's 776 on tests/pendularGasWithoutAir's column). And relTol
    // 1e-10 unless given. The measurements behind both choices, with
    // lu and asm: README.md, "Nonlinear engine", and
    // bench/pendularParallelDefault. Serial runs keep their solver (block
    // ILU(0) of a 1-D column is its LU: exact)
    if
    (
        Pstream::parRun() && given.empty() && chosenBy.empty()
     && !coupledDict.found("diagonalScale")
    )
    {
        coupledDict.add("diagonalScale", true);
        if (!relTolGiven)
        {
            coupledDict.set("relTol", scalar(1e-10));
        }
        Info<< "Newton steps' linear solver: preconditioner bjacobi, the"
            << " solves diagonally scaled"
            << (relTolGiven ? "" : " to relTol 1e-10")
            << " (diagonalScale true; pendularFoam's default on "
            << Pstream::nProcs() << " ranks below " << cprMinCells
            << " cells: block Jacobi drops the coupling across the"
            << " processor boundaries; set a preconditioner or"
            << " diagonalScale in " << coupledDict.name().c_str()
            << " to override)" << endl;
    }
    else if (given.empty() && coupledDict.found("preconditioner"))
    {
        Info<< "Newton steps' linear solver: preconditioner "
            << coupledDict.get<word>("preconditioner") << " ("
            << chosenBy.c_str() << ")" << endl;
    }
    else if (given.empty())
    {
        Info<< "Newton steps' linear solver: preconditioner bjacobi"
            << " (blockSystem's default on " << nGlobalCells << " cells,"
            << " below pendularFoam's " << cprMinCells << " for cpr; set"
            << " another preconditioner in " << coupledDict.name().c_str()
            << " to override)" << endl;
    }
    else
    {
        Info<< "Newton steps' linear solver: the preconditioner as set in "
            << coupledDict.name().c_str() << " (" << given << " given)"
            << endl;
    }

    // (a preconditioner set in PETSc's options database, e.g. by the
    // environment variable PETSC_OPTIONS, wins over every choice above:
    // blockSystem::createSolver says so in the line after this one)

    // preconditioner cpr (blockSystem): the pressure unknown is p_g - pRef,
    // the unknown 1 of (T, p_g - pRef, W) (pendularResidual), unless given
    if
    (
        coupledDict.getOrDefault<word>("preconditioner", "") == "cpr"
     && !coupledDict.found("cprField")
    )
    {
        coupledDict.add("cprField", label(1));
    }

    return coupledDict;
}


// ************************************************************************* //
