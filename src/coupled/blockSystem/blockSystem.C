/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "blockSystem.H"
#include "petscSession.H"
#include "syncTools.H"
#include "processorPolyPatch.H"
#include "cyclicPolyPatch.H"
#include "checkedRead.H"
#include "DynamicList.H"
#include <petscksp.h>
#include <cfenv>
#include <cmath>
#include <sstream>
#include <algorithm>
#include <type_traits>
#include <set>

static_assert
(
    std::is_same<PetscInt, Foam::label>::value
 && std::is_same<PetscScalar, Foam::scalar>::value,
    "PETSc's PetscInt and PetscScalar must be OpenFOAM's label and scalar"
    " (Debian's petsc-dev real: 32-bit indices, double; OpenFOAM Int32 DP)"
);

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(blockSystem, 0);
}

const Foam::Enum<Foam::blockSystem::matrixType>
Foam::blockSystem::matrixTypeNames
({
    { matrixType::baij, "baij" },
    { matrixType::aij, "aij" },
});

const Foam::Enum<Foam::blockSystem::solverType>
Foam::blockSystem::solverTypeNames
({
    { solverType::gmres, "gmres" },
    { solverType::fgmres, "fgmres" },
    { solverType::bcgs, "bcgs" },
});

const Foam::Enum<Foam::blockSystem::preconditionerType>
Foam::blockSystem::preconditionerTypeNames
({
    { preconditionerType::bjacobi, "bjacobi" },
    { preconditionerType::asm_, "asm" },
    { preconditionerType::fieldsplit, "fieldsplit" },
    { preconditionerType::lu, "lu" },
    { preconditionerType::cpr, "cpr" },
    { preconditionerType::none, "none" },
});

const Foam::Enum<Foam::blockSystem::forcingType>
Foam::blockSystem::forcingTypeNames
({
    { forcingType::none, "none" },
    { forcingType::eisenstatWalker, "eisenstatWalker" },
});

const Foam::Enum<Foam::blockSystem::subPreconditionerType>
Foam::blockSystem::subPreconditionerTypeNames
({
    { subPreconditionerType::ilu, "ilu" },
    { subPreconditionerType::lu, "lu" },
});


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// True if the PETSc option -<prefix><name> is set
bool hasOption(const std::string& prefix, const std::string& name)
{
    const std::string full("-" + prefix + name);
    PetscBool set = PETSC_FALSE;
    Foam::petscSession::check
    (
        PetscOptionsHasName(nullptr, nullptr, full.c_str(), &set),
        "PetscOptionsHasName"
    );
    return set;
}


// The options that createSolver set itself (its defaults, not the
// user's: without '-'), which PETSc may leave unread when the user's
// options choose another solver (blockSystem::warnUnusedOptions)
std::set<std::string> ownDefaults;

// Set the PETSc option -<prefix><name> unless it is already set (from
// PETSC_OPTIONS, which so takes precedence); the user's (petscOptions)
// with own false
void setDefaultOption
(
    const std::string& prefix,
    const std::string& name,
    const std::string& value,
    const bool own = true
)
{
    const std::string full("-" + prefix + name);
    if (!hasOption(prefix, name))
    {
        if (own)
        {
            ownDefaults.insert(prefix + name);
        }
        Foam::petscSession::check
        (
            PetscOptionsSetValue
            (
                nullptr,
                full.c_str(),
                value.empty() ? nullptr : value.c_str()
            ),
            "PetscOptionsSetValue"
        );
    }
}

// An option name: '-' followed by a letter (-1e-3 is a value)
bool isOptionName(const std::string& s)
{
    return s.size() > 1 && s[0] == '-' && std::isalpha(s[1]);
}


// The options of the keyword petscOptions ("-name [value] ..."), under the
// prefix, unless already set; returns their names under the prefix
std::vector<std::string> setUserOptions
(
    const Foam::dictionary& dict,
    const std::string& prefix
)
{
    std::vector<std::string> names;
    const Foam::string extra =
        dict.getOrDefault<Foam::string>("petscOptions", "");
    std::istringstream is(extra);
    Foam::List<std::string> tokens;
    std::string t;
    while (is >> t)
    {
        tokens.append(t);
    }
    for (Foam::label i = 0; i < tokens.size(); ++i)
    {
        const std::string& name = tokens[i];
        if (!isOptionName(name))
        {
            FatalIOErrorInFunction(dict)
                << "petscOptions: '" << name.c_str()
                << "' is neither an option (-name) nor the value after"
                << " one" << Foam::exit(Foam::FatalIOError);
        }
        std::string value;
        if (i + 1 < tokens.size() && !isOptionName(tokens[i + 1]))
        {
            value = tokens[++i];
        }
        setDefaultOption(prefix, name.substr(1), value, false);
        names.push_back(prefix + name.substr(1));
    }
    return names;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::blockSystem::setNeighbourCells()
{
    const label nInternal = mesh_.nInternalFaces();
    const labelList& own = mesh_.faceOwner();

    // Global index of every cell next to the boundary, swapped across the
    // coupled patches
    labelList bndGlobal(mesh_.nFaces() - nInternal);
    forAll(bndGlobal, bFacei)
    {
        bndGlobal[bFacei] = offset_ + own[nInternal + bFacei];
    }
    syncTools::swapBoundaryFaceList(mesh_, bndGlobal);

    nbrGlobalCell_.setSize(bndGlobal.size(), -1);
    for (const polyPatch& pp : mesh_.boundaryMesh())
    {
        // Face-to-face couplings only: a face of an AMI patch couples to
        // several faces, which the exchange above does not give
        if
        (
            pp.coupled()
         && !isA<processorPolyPatch>(pp)
         && !isA<cyclicPolyPatch>(pp)
        )
        {
            FatalErrorInFunction
                << "Patch " << pp.name() << " of type " << pp.type()
                << ": the block system couples cells across processor and"
                << " cyclic patches only (one face to one face)"
                << exit(FatalError);
        }
        if (pp.coupled())
        {
            forAll(pp, i)
            {
                const label bFacei = pp.start() + i - nInternal;
                nbrGlobalCell_[bFacei] = bndGlobal[bFacei];
            }
        }
    }
}


void Foam::blockSystem::createMatrix(const matrixType type)
{
    const label nCells = mesh_.nCells();
    const label nInternal = mesh_.nInternalFaces();
    const labelList& own = mesh_.faceOwner();
    const labelList& nei = mesh_.faceNeighbour();

    // The block columns of each block row (global indices, sorted, each
    // once): the cell's own, its internal faces' neighbours, the cells
    // across its coupled boundary faces
    List<DynamicList<label>> rowCols(nCells);
    forAll(rowCols, celli)
    {
        rowCols[celli].append(offset_ + celli);
    }
    for (label facei = 0; facei < nInternal; ++facei)
    {
        rowCols[own[facei]].append(offset_ + nei[facei]);
        rowCols[nei[facei]].append(offset_ + own[facei]);
    }
    forAll(nbrGlobalCell_, bFacei)
    {
        if (nbrGlobalCell_[bFacei] >= 0)
        {
            rowCols[own[nInternal + bFacei]].append(nbrGlobalCell_[bFacei]);
        }
    }
    rowStart_.setSize(nCells + 1);
    rowStart_[0] = 0;
    forAll(rowCols, celli)
    {
        DynamicList<label>& cols = rowCols[celli];
        std::sort(cols.begin(), cols.end());
        cols.resize(std::unique(cols.begin(), cols.end()) - cols.begin());
        rowStart_[celli + 1] = rowStart_[celli] + cols.size();
    }
    cols_.setSize(rowStart_[nCells]);
    forAll(rowCols, celli)
    {
        std::copy
        (
            rowCols[celli].cbegin(), rowCols[celli].cend(),
            &cols_[rowStart_[celli]]
        );
    }
    values_.setSize(nBlock_*nBlock_*cols_.size(), Zero);

    // The slots of the blocks each assembly call adds to
    diagSlot_.setSize(nCells);
    forAll(diagSlot_, celli)
    {
        diagSlot_[celli] = slot(celli, offset_ + celli);
    }
    ownerSlot_.setSize(nInternal);
    neighbourSlot_.setSize(nInternal);
    for (label facei = 0; facei < nInternal; ++facei)
    {
        ownerSlot_[facei] = slot(own[facei], offset_ + nei[facei]);
        neighbourSlot_[facei] = slot(nei[facei], offset_ + own[facei]);
    }
    nbrSlot_.setSize(nbrGlobalCell_.size(), -1);
    forAll(nbrGlobalCell_, bFacei)
    {
        if (nbrGlobalCell_[bFacei] >= 0)
        {
            nbrSlot_[bFacei] =
                slot(own[nInternal + bFacei], nbrGlobalCell_[bFacei]);
        }
    }

    // Block non-zeros per block row: on this rank (d), on others (o):
    // exactly the pattern
    List<PetscInt> dnnz(nCells, 0);
    List<PetscInt> onnz(nCells, 0);
    forAll(rowCols, celli)
    {
        for (const label col : rowCols[celli])
        {
            if (globalCells_.isLocal(col))
            {
                ++dnnz[celli];
            }
            else
            {
                ++onnz[celli];
            }
        }
    }

    const PetscInt n = PetscInt(nBlock_*nCells);
    petscSession::check(MatCreate(PETSC_COMM_WORLD, &A_), "MatCreate");
    petscSession::check
    (
        MatSetSizes(A_, n, n, PETSC_DETERMINE, PETSC_DETERMINE),
        "MatSetSizes"
    );
    const bool parallel = Pstream::parRun();
    petscSession::check
    (
        MatSetType
        (
            A_,
            type == matrixType::baij
          ? (parallel ? MATMPIBAIJ : MATSEQBAIJ)
          : (parallel ? MATMPIAIJ : MATSEQAIJ)
        ),
        "MatSetType"
    );
    petscSession::check(MatSetBlockSize(A_, nBlock_), "MatSetBlockSize");
    petscSession::check
    (
        MatXAIJSetPreallocation
        (
            A_, nBlock_, dnnz.cdata(), onnz.cdata(), nullptr, nullptr
        ),
        "MatXAIJSetPreallocation"
    );
    // A missing pattern entry is a bug of the preallocation: an error
    petscSession::check
    (
        MatSetOption(A_, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE),
        "MatSetOption"
    );
    // Every rank sets its own rows only
    petscSession::check
    (
        MatSetOption(A_, MAT_NO_OFF_PROC_ENTRIES, PETSC_TRUE),
        "MatSetOption"
    );

    petscSession::check(MatCreateVecs(A_, &x_, &b_), "MatCreateVecs");
}


void Foam::blockSystem::createSolver
(
    const dictionary& dict,
    const string& chosenBy
)
{
    checkedRead::checkKeywords
    (
        dict,
        {
            "matrix", "solver", "preconditioner", "subPreconditioner",
            "iluLevels", "asmOverlap", "tolerance", "relTol", "maxIter",
            "gmresRestart", "petscOptions", "forcing", "forcingMax",
            "diagonalScale", "cprField", "cprDecoupling", "cprAmg",
            "cprRebuildFactor"
        },
        "block solver settings (blockSystem)"
    );

    // (the choices by checkedRead::getChoice: a word not among them is a
    // FatalIOError naming the keyword too, which OpenFOAM's Enum does not)
    const solverType solver =
        checkedRead::getChoice
        (
            dict, "solver", solverTypeNames, solverType::gmres
        );
    const preconditionerType pc =
        checkedRead::getChoice
        (
            dict, "preconditioner", preconditionerTypeNames,
            preconditionerType::bjacobi
        );
    const subPreconditionerType subPc =
        checkedRead::getChoice
        (
            dict, "subPreconditioner", subPreconditionerTypeNames,
            subPreconditionerType::ilu
        );
    const label iluLevels =
        checkedRead::getLabelOrDefault(dict, "iluLevels", 0, 0, 10);
    const label asmOverlap =
        checkedRead::getLabelOrDefault(dict, "asmOverlap", 1, 0, 10);
    const scalar tolerance =
        checkedRead::getOrDefault
        (
            dict, "tolerance", dimless, 1e-12, checkedRead::nonNegative()
        ).value();
    const scalar relTol =
        checkedRead::getOrDefault
        (
            dict, "relTol", dimless, 1e-10, checkedRead::closedOpen(0, 1)
        ).value();
    if (tolerance <= 0 && relTol <= 0)
    {
        FatalIOErrorInFunction(dict)
            << "tolerance and relTol are both 0: the block solver would"
            << " never stop; give tolerance > 0 or relTol in (0, 1)"
            << exit(FatalIOError);
    }
    const label maxIter =
        checkedRead::getLabelOrDefault(dict, "maxIter", 1000, 1);
    relTol_ = relTol;
    forcing_ =
        checkedRead::getChoice
        (
            dict, "forcing", forcingTypeNames, forcingType::none
        );
    forcingMax_ =
        checkedRead::getOrDefault
        (
            dict, "forcingMax", dimless, 0.01, checkedRead::closedOpen(0, 1)
        ).value();
    if (forcing_ == forcingType::none && dict.found("forcingMax"))
    {
        // A bound that would be silently unused
        FatalIOErrorInFunction(dict)
            << "Keyword 'forcingMax' in " << dict.name() << " with forcing"
            << " none: it bounds the forcing term of forcing"
            << " eisenstatWalker only; valid: remove it, or give forcing"
            << " eisenstatWalker"
            << exit(FatalIOError);
    }
    if (forcing_ == forcingType::eisenstatWalker && forcingMax_ < relTol)
    {
        FatalIOErrorInFunction(dict)
            << "forcingMax " << forcingMax_ << " < relTol " << relTol
            << " in " << dict.name() << ": the forcing term is bounded to"
            << " [relTol, forcingMax]; give forcingMax in [relTol, 1)"
            << exit(FatalIOError);
    }
    const label restart =
        checkedRead::getLabelOrDefault(dict, "gmresRestart", 50, 1, 10000);
    const matrixType mType =
        checkedRead::getChoice
        (
            dict, "matrix", matrixTypeNames, matrixType::baij
        );
    if (pc == preconditionerType::fieldsplit && mType == matrixType::baij)
    {
        FatalIOErrorInFunction(dict)
            << "preconditioner fieldsplit needs 'matrix aij;' (PETSc"
            << " extracts the fields of aij matrices only); matrix is baij"
            << exit(FatalIOError);
    }

    // Symmetric diagonal scaling of the solves (see Description)
    const bool diagonalScale =
        dict.getOrDefault<bool>("diagonalScale", false);
    if (diagonalScale && pc == preconditionerType::cpr)
    {
        // The pressure stage's decoupling weights are those of the
        // unscaled blocks: not validated on the scaled system
        FatalIOErrorInFunction(dict)
            << "Keyword 'diagonalScale' = true in " << dict.name()
            << " with preconditioner cpr: its pressure stage is not"
            << " validated on a diagonally scaled system; valid: remove"
            << " diagonalScale (or false), or another preconditioner"
            << exit(FatalIOError);
    }

    // The CPR's settings (its second stage: block Jacobi with
    // subPreconditioner and iluLevels)
    const wordList cprKeys
    ({
        "cprField", "cprDecoupling", "cprAmg", "cprRebuildFactor"
    });
    if (pc != preconditionerType::cpr)
    {
        for (const word& key : cprKeys)
        {
            if (dict.found(key))
            {
                // A setting that would be silently unused
                FatalIOErrorInFunction(dict)
                    << "Keyword '" << key << "' in " << dict.name()
                    << " with preconditioner "
                    << preconditionerTypeNames[pc] << ": " << key
                    << " is a setting of preconditioner cpr only; valid:"
                    << " remove it, or give preconditioner cpr"
                    << exit(FatalIOError);
            }
        }
    }
    word cprAmg;
    if (pc == preconditionerType::cpr)
    {
        const label field =
            checkedRead::getLabel(dict, "cprField", 0, nBlock_ - 1);
        const cprPressureStage::decouplingType decoupling =
            checkedRead::getChoice
            (
                dict, "cprDecoupling", cprPressureStage::decouplingTypeNames,
                cprPressureStage::decouplingType::quasiImpes
            );
        const cprPressureStage::amgType amg =
            checkedRead::getChoice
            (
                dict, "cprAmg", cprPressureStage::amgTypeNames,
                cprPressureStage::amgType::hypre
            );
        std::string why;
        if (!cprPressureStage::available(amg, why))
        {
            wordList have;
            std::string whyNot;
            for (const word& name : cprPressureStage::amgTypeNames.names())
            {
                if
                (
                    cprPressureStage::available
                    (
                        cprPressureStage::amgTypeNames[name], whyNot
                    )
                )
                {
                    have.append(name);
                }
            }
            FatalIOErrorInFunction(dict)
                << "Keyword 'cprAmg' = " << cprPressureStage::amgTypeNames[amg]
                << " in " << dict.name() << ": this PETSc has not this"
                << " AMG (" << why.c_str() << "); valid choices here: "
                << flatOutput(have) << exit(FatalIOError);
        }
        // The rebuild criterion of the AMG hierarchy (cprPressureStage.H):
        // 0 (a new one every sub-step) or a factor in [1, 100]
        const scalar rebuildFactor =
            checkedRead::getOrDefault
            (
                dict, "cprRebuildFactor", dimless, cprRebuildFactorDefault,
                checkedRead::closed(0, 100)
            ).value();
        if (rebuildFactor > 0 && rebuildFactor < 1)
        {
            FatalIOErrorInFunction(dict)
                << "Keyword 'cprRebuildFactor' = " << rebuildFactor
                << " in " << dict.name() << ": the factor of the GMRES"
                << " iterations per decade over those in the sub-step of"
                << " the last build of the AMG hierarchy at which it is"
                << " built anew; valid:"
                << " 0 (a new hierarchy every sub-step) or [1, 100]"
                << exit(FatalIOError);
        }
        cprAmg = cprPressureStage::amgTypeNames[amg];
        cpr_.reset
        (
            new cprPressureStage
            (
                nBlock_, field, decoupling, dict.dictName() + "_cpr_",
                rebuildFactor
            )
        );
    }

    createMatrix(mType);

    // Options under the prefix <dictionary name>_
    prefix_ = dict.dictName() + "_";
    const std::string& prefix = prefix_;

    // Where the preconditioner and the factor solver type come from, for
    // checkFactorSolver's message: PETSC_OPTIONS (set before any of
    // these), else the keyword petscOptions, else the keywords (written
    // in dict, or set there by the caller: chosenBy), else the defaults
    const std::string env
    (
        "the environment variable PETSC_OPTIONS (-" + prefix
    );
    std::string pcFrom
    (
        hasOption(prefix, "pc_type") ? env + "pc_type)" : ""
    );
    std::string factorFrom
    (
        hasOption(prefix, "pc_factor_mat_solver_type")
      ? env + "pc_factor_mat_solver_type)" : ""
    );
    const bool scaleFromEnv = hasOption(prefix, "ksp_diagonal_scale");

    // The preconditioner set in PETSc's options database before this
    // solver set any (PetscInitialize read PETSC_OPTIONS, PETSC_OPTIONS_YAML,
    // the -options_file they name, .petscrc): PETSc runs it over every
    // choice of the caller's (pendularEngineSetup's log line) and of the
    // keywords (hostile testing 2026-12-05b, finding 5)
    if (!pcFrom.empty())
    {
        char value[256] = "";
        PetscBool set = PETSC_FALSE;
        petscSession::check
        (
            PetscOptionsGetString
            (
                nullptr, prefix.c_str(), "-pc_type", value, sizeof(value),
                &set
            ),
            "PetscOptionsGetString"
        );
        Info<< "Newton steps' linear solver: PETSc's options database (the"
            << " environment's PETSC_OPTIONS, PETSC_OPTIONS_YAML or an"
            << " -options_file) sets -" << prefix.c_str() << "pc_type "
            << value << ": PETSc runs it, whatever the line above chose"
            << endl;
    }

    // The user's PETSc options first (they win over the keywords)
    dictOptions_ = setUserOptions(dict, prefix);

    const std::string inFile(" in " + dict.name());
    const std::string petscOptions
    (
        "petscOptions \""
      + dict.getOrDefault<string>("petscOptions", "") + "\"" + inFile
    );
    dictOptionsSource_ = petscOptions;
    if (pcFrom.empty() && hasOption(prefix, "pc_type"))
    {
        pcFrom = petscOptions;
    }
    if (factorFrom.empty() && hasOption(prefix, "pc_factor_mat_solver_type"))
    {
        factorFrom = petscOptions;
    }
    if (pcFrom.empty())
    {
        pcFrom =
            "preconditioner " + preconditionerTypeNames[pc]
          + (
                !chosenBy.empty()
              ? " chosen by the solver, not written" + inFile + " ("
              + chosenBy + ")"
              : dict.found("preconditioner")
              ? inFile
              : " (blockSystem's default: no keyword preconditioner"
              + inFile + ")"
            );
    }
    if (factorFrom.empty())
    {
        factorFrom =
            pc == preconditionerType::lu && Pstream::parRun()
          ? "MUMPS, blockSystem's default for lu in parallel"
          : "PETSc's default for the matrix type";
    }

    setDefaultOption(prefix, "ksp_type", solverTypeNames[solver]);
    setDefaultOption(prefix, "ksp_gmres_restart", std::to_string(restart));
    setDefaultOption(prefix, "ksp_pc_side", "right");
    setDefaultOption(prefix, "ksp_norm_type", "unpreconditioned");
    setDefaultOption(prefix, "ksp_initial_guess_nonzero", "true");
    if (diagonalScale)
    {
        // (fix: A and b unscaled after each solve, as the Newton engine's
        // chord steps solve again with the same A)
        setDefaultOption(prefix, "ksp_diagonal_scale", "true");
        setDefaultOption(prefix, "ksp_diagonal_scale_fix", "true");
    }

    const std::string sub(subPreconditionerTypeNames[subPc]);
    switch (pc)
    {
        case preconditionerType::bjacobi:
            setDefaultOption(prefix, "pc_type", "bjacobi");
            setDefaultOption(prefix, "sub_pc_type", sub);
            setDefaultOption
            (
                prefix, "sub_pc_factor_levels", std::to_string(iluLevels)
            );
            break;
        case preconditionerType::asm_:
            setDefaultOption(prefix, "pc_type", "asm");
            setDefaultOption
            (
                prefix, "pc_asm_overlap", std::to_string(asmOverlap)
            );
            setDefaultOption(prefix, "sub_pc_type", sub);
            setDefaultOption
            (
                prefix, "sub_pc_factor_levels", std::to_string(iluLevels)
            );
            break;
        case preconditionerType::fieldsplit:
            setDefaultOption(prefix, "pc_type", "fieldsplit");
            setDefaultOption(prefix, "pc_fieldsplit_type", "multiplicative");
            break;
        case preconditionerType::lu:
            setDefaultOption(prefix, "pc_type", "lu");
            if (Pstream::parRun())
            {
                setDefaultOption
                (
                    prefix, "pc_factor_mat_solver_type", "mumps"
                );
            }
            break;
        case preconditionerType::cpr:
            // Stage 1 the shell (cprPressureStage, attached by
            // createKsp), stage 2 block Jacobi, multiplicatively
            setDefaultOption(prefix, "pc_type", "composite");
            setDefaultOption(prefix, "pc_composite_type", "multiplicative");
            setDefaultOption(prefix, "pc_composite_pcs", "shell,bjacobi");
            setDefaultOption(prefix, "sub_1_sub_pc_type", sub);
            setDefaultOption
            (
                prefix, "sub_1_sub_pc_factor_levels",
                std::to_string(iluLevels)
            );
            setDefaultOption(prefix, "cpr_ksp_type", "preonly");
            setDefaultOption(prefix, "cpr_pc_type", cprAmg);
            if (cprAmg == "hypre")
            {
                // BoomerAMG's parallel coarsening and its interpolation
                // (bench/pendular3D/README.md: the same iterations and
                // serial time as hypre's default, Falgout's, and the
                // 2-rank solves 16-45 % faster)
                setDefaultOption
                (
                    prefix, "cpr_pc_hypre_boomeramg_coarsen_type", "PMIS"
                );
                setDefaultOption
                (
                    prefix, "cpr_pc_hypre_boomeramg_interp_type", "ext+i"
                );
                setDefaultOption
                (
                    prefix, "cpr_pc_hypre_boomeramg_P_max", "4"
                );
            }
            break;
        case preconditionerType::none:
            setDefaultOption(prefix, "pc_type", "none");
            break;
    }

    checkFactorSolver
    (
        dict, pcFrom, factorFrom, createKsp(relTol, tolerance, maxIter)
    );

    KSPType kspType;
    PC pcObj;
    PCType pcType;
    petscSession::check(KSPGetType(ksp_, &kspType), "KSPGetType");
    petscSession::check(KSPGetPC(ksp_, &pcObj), "KSPGetPC");
    petscSession::check(PCGetType(pcObj, &pcType), "PCGetType");
    solverName_ = word(std::string("PETSc-") + kspType + "-" + pcType);

    if (pc == preconditionerType::cpr && !cpr_)
    {
        // PETSc's options set another preconditioner (createKsp): said,
        // with both sources
        // (pcFrom names the keyword when pc_type is the keyword's
        // composite: the options changed its stages)
        const bool byPcType = pcFrom.compare(0, 15, "preconditioner ") != 0;
        Info<< "blockSystem " << solverName_ << ": preconditioner cpr"
            << inFile.c_str() << " overridden by "
            << (
                   byPcType
                 ? pcFrom
                 : std::string
                   (
                       "PETSc's options of the composite's stages"
                       " (PETSC_OPTIONS or petscOptions: its first stage"
                       " not a shell)"
                   )
               ).c_str()
            << ": PETSc's pc_type " << pcType
            << ", no pressure stage (the cpr keywords unused)" << endl;
    }

    if (cpr_)
    {
        // Diagonal scaling set by PETSc's options (PETSC_OPTIONS or
        // petscOptions; the keyword diagonalScale is refused above), read
        // from the KSP as the options made it: besides the pressure
        // stage's weights (those of the unscaled blocks), the rebuild
        // criterion's rate would mix the unscaled |r_0| with PETSc's
        // scaled |r_n|
        PetscBool scaled = PETSC_FALSE;
        petscSession::check
        (
            KSPGetDiagonalScale(ksp_, &scaled), "KSPGetDiagonalScale"
        );
        if (scaled)
        {
            const std::string option("-" + prefix + "ksp_diagonal_scale");
            FatalIOErrorInFunction(dict)
                << "PETSc option " << option.c_str() << " (from "
                << (
                       scaleFromEnv
                     ? std::string("the environment variable PETSC_OPTIONS")
                     : petscOptions
                   ).c_str()
                << ") with preconditioner cpr in " << dict.name()
                << ": its pressure stage is not validated on a diagonally"
                << " scaled system, and its rebuild criterion would compare"
                << " the unscaled initial residual with the scaled final"
                << " one; valid: remove " << option.c_str()
                << " (or give it false), or another preconditioner"
                << exit(FatalIOError);
        }
    }
}


void Foam::blockSystem::warnUnusedOptions() const
{
    unusedOptionsChecked_ = true;

    // Not collective: every rank reads its own options database (the same
    // options on every rank); the warning is the master's
    PetscInt n = 0;
    char** names = nullptr;
    char** values = nullptr;
    petscSession::check
    (
        PetscOptionsLeftGet(nullptr, &n, &names, &values),
        "PetscOptionsLeftGet"
    );
    std::string fromDict, fromEnv;
    for (PetscInt i = 0; i < n; ++i)
    {
        const std::string name(names[i] ? names[i] : "");
        if
        (
            name.compare(0, prefix_.size(), prefix_) != 0
         || ownDefaults.count(name)
        )
        {
            continue;   // another object's, or a default of createSolver's
        }
        const std::string shown
        (
            " -" + name + (values[i] ? std::string(" ") + values[i] : "")
        );
        if
        (
            std::find(dictOptions_.cbegin(), dictOptions_.cend(), name)
         != dictOptions_.cend()
        )
        {
            fromDict += shown;
        }
        else
        {
            fromEnv += shown;
        }
    }
    petscSession::check
    (
        PetscOptionsLeftRestore(nullptr, &n, &names, &values),
        "PetscOptionsLeftRestore"
    );

    if (!fromDict.empty() || !fromEnv.empty())
    {
        std::string msg
        (
            "PETSc did not use these options of the block solver "
          + std::string(solverName_) + " in its first solve:"
        );
        if (!fromDict.empty())
        {
            msg +=
                "\n    from " + dictOptionsSource_ + " (each under the prefix -"
              + prefix_ + "):" + fromDict;
        }
        if (!fromEnv.empty())
        {
            msg += "\n    from the environment variable PETSC_OPTIONS:" + fromEnv;
        }
        WarningInFunction
            << msg.c_str() << nl
            << "    A misspelt option, the prefix given twice in petscOptions"
            << " (it is written without it), or an option of another"
            << " solver or preconditioner than the one chosen: PETSc"
            << " ignores it. The solver PETSc runs is named above (Newton"
            << " steps' linear solver)." << endl;
    }
}


int Foam::blockSystem::createKsp
(
    const scalar relTol,
    const scalar tolerance,
    const label maxIter
) const
{
    petscSession::check(KSPCreate(PETSC_COMM_WORLD, &ksp_), "KSPCreate");
    petscSession::check
    (
        KSPSetOptionsPrefix(ksp_, prefix_.c_str()),
        "KSPSetOptionsPrefix"
    );
    petscSession::check(KSPSetOperators(ksp_, A_, A_), "KSPSetOperators");
    petscSession::check
    (
        KSPSetTolerances(ksp_, relTol, tolerance, PETSC_DEFAULT, maxIter),
        "KSPSetTolerances"
    );
    const PetscErrorCode ierr = KSPSetFromOptions(ksp_);
    if (cpr_ && !ierr)
    {
        // The shell of the composite's first stage; none when PETSc's
        // options (PETSC_OPTIONS, petscOptions: they win over the
        // keywords) set another preconditioner: then no pressure stage
        // (its diagonal-scaling refusal and AMG rebuilds follow the
        // preconditioner PETSc uses)
        PC pc;
        petscSession::check(KSPGetPC(ksp_, &pc), "KSPGetPC");
        PetscBool isComposite = PETSC_FALSE;
        petscSession::check
        (
            PetscObjectTypeCompare
            (
                reinterpret_cast<PetscObject>(pc), PCCOMPOSITE, &isComposite
            ),
            "PetscObjectTypeCompare"
        );
        PC stage;
        PetscBool isShell = PETSC_FALSE;
        if (isComposite)
        {
            petscSession::check
            (
                PCCompositeGetPC(pc, 0, &stage), "PCCompositeGetPC"
            );
            petscSession::check
            (
                PetscObjectTypeCompare
                (
                    reinterpret_cast<PetscObject>(stage), PCSHELL, &isShell
                ),
                "PetscObjectTypeCompare"
            );
        }
        if (isShell)
        {
            cpr_->reset();
            cpr_->attach(stage);
        }
        else
        {
            cpr_.clear();
        }
    }
    return ierr;
}


bool Foam::blockSystem::canFactor
(
    const char* solverType,
    const int factorType,
    std::string& why
) const
{
    const MatFactorType ftype = MatFactorType(factorType);
    why.clear();

    // Registration first (MatGetFactorAvailable, no object made): a type
    // this PETSc lacks for the matrix type
    PetscBool registered = PETSC_FALSE;
    petscSession::check
    (
        MatGetFactorAvailable(A_, solverType, ftype, &registered),
        "MatGetFactorAvailable"
    );
    bool ok = registered;
    reduce(ok, andOp<bool>());
    if (!ok)
    {
        why = "not registered for this matrix type";
        return false;
    }

    // Then a factorisation itself (PETSc 3.18 registers MUMPS's Cholesky
    // for baij matrices and refuses it only when the factor matrix is made:
    // "Cannot use PETSc BAIJ matrices with Cholesky, use SBAIJ or AIJ
    // matrix", mumps.c; registration alone passed that combination, which
    // failed at the first solve), as PCSetUp_LU and PCSetUp_Cholesky do
    // it: MatGetFactor, the symbolic and the numeric factorisation, of a
    // probe of A_'s type and block size, one identity block per rank (A_
    // is not assembled yet, and MatGetFactor refuses an unassembled
    // matrix). Each step on every rank, the next only if every rank
    // passed (the steps are collective)
    Mat P = nullptr, F = nullptr;
    IS row = nullptr, col = nullptr;
    MatType matType;
    petscSession::check(MatGetType(A_, &matType), "MatGetType");
    const PetscInt B = nBlock_;
    const PetscInt one = 1, zero = 0;
    List<PetscScalar> identity(B*B, Zero);
    for (label i = 0; i < B; ++i)
    {
        identity[i*B + i] = 1;
    }
    petscSession::check(MatCreate(PETSC_COMM_WORLD, &P), "MatCreate");
    petscSession::check
    (
        MatSetSizes(P, B, B, PETSC_DETERMINE, PETSC_DETERMINE),
        "MatSetSizes"
    );
    petscSession::check(MatSetType(P, matType), "MatSetType");
    petscSession::check(MatSetBlockSize(P, B), "MatSetBlockSize");
    petscSession::check
    (
        MatXAIJSetPreallocation(P, B, &one, &zero, nullptr, nullptr),
        "MatXAIJSetPreallocation"
    );
    const PetscInt r = Pstream::myProcNo();
    petscSession::check
    (
        MatSetValuesBlocked
        (
            P, 1, &r, 1, &r, identity.cdata(), INSERT_VALUES
        ),
        "MatSetValuesBlocked"
    );
    petscSession::check
    (
        MatAssemblyBegin(P, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin"
    );
    petscSession::check
    (
        MatAssemblyEnd(P, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd"
    );

    MatFactorInfo info;
    petscSession::check
    (
        MatFactorInfoInitialize(&info), "MatFactorInfoInitialize"
    );
    const bool isLu = ftype == MAT_FACTOR_LU;
    auto step = [&](const PetscErrorCode ierr, const char* call)
    {
        bool passed = ierr == 0;
        if (!passed)
        {
            why = std::string(call) + ": " + petscSession::lastError();
        }
        reduce(passed, andOp<bool>());
        if (!passed && why.empty())
        {
            why = std::string(call) + " failed on another rank";
        }
        ok = ok && passed;
    };
    step(MatGetFactor(P, solverType, ftype, &F), "MatGetFactor");
    if (ok)
    {
        PetscBool useOrdering = PETSC_FALSE;
        step
        (
            MatFactorGetCanUseOrdering(F, &useOrdering),
            "MatFactorGetCanUseOrdering"
        );
        if (ok && useOrdering)
        {
            step
            (
                MatGetOrdering(P, MATORDERINGNATURAL, &row, &col),
                "MatGetOrdering"
            );
        }
    }
    if (ok)
    {
        step
        (
            isLu
          ? MatLUFactorSymbolic(F, P, row, col, &info)
          : MatCholeskyFactorSymbolic(F, P, row, &info),
            isLu ? "MatLUFactorSymbolic" : "MatCholeskyFactorSymbolic"
        );
    }
    if (ok)
    {
        step
        (
            isLu
          ? MatLUFactorNumeric(F, P, &info)
          : MatCholeskyFactorNumeric(F, P, &info),
            isLu ? "MatLUFactorNumeric" : "MatCholeskyFactorNumeric"
        );
    }
    if (row) ISDestroy(&row);
    if (col) ISDestroy(&col);
    if (F) MatDestroy(&F);
    MatDestroy(&P);
    return ok;
}


void Foam::blockSystem::checkFactorSolver
(
    const dictionary& dict,
    const std::string& pcFrom,
    const std::string& factorFrom,
    const int setFromOptions
) const
{
    // KSPSetFromOptions's failure (its message kept before any other call)
    const std::string optionsError
    (
        setFromOptions ? petscSession::lastError() : ""
    );
    PC pc;
    petscSession::check(KSPGetPC(ksp_, &pc), "KSPGetPC");
    PetscBool isFactor = PETSC_FALSE;
    petscSession::check
    (
        PetscObjectTypeCompareAny
        (
            reinterpret_cast<PetscObject>(pc), &isFactor, PCLU, PCCHOLESKY,
            ""
        ),
        "PetscObjectTypeCompareAny"
    );
    if (!isFactor)
    {
        petscSession::check(setFromOptions, "KSPSetFromOptions");
        return;
    }
    PCType pcType;
    petscSession::check(PCGetType(pc, &pcType), "PCGetType");
    const bool isLu = word(pcType) == PCLU;
    const MatFactorType factor = isLu ? MAT_FACTOR_LU : MAT_FACTOR_CHOLESKY;

    // The solver type set by the options (null: PETSc's choice, the first
    // one registered for the matrix type)
    MatSolverType asked = nullptr;
    petscSession::check
    (
        PCFactorGetMatSolverType(pc, &asked), "PCFactorGetMatSolverType"
    );
    // The factorisation refused when the options were read (PETSc makes
    // the factor matrix there when the solver type is given: MUMPS's
    // Cholesky on baij), or by canFactor (when it is PETSc's default, the
    // factor matrix is made at the first solve)
    std::string why;
    if (setFromOptions)
    {
        why = "KSPSetFromOptions: " + optionsError;
    }
    else if (canFactor(asked, factor, why))
    {
        return;
    }

    // The factor solver types of PETSc 3.18 (petscmat.h's MATSOLVER...
    // but MATLAB's and the GPUs') that this build can factor A_'s type by
    MatType matType;
    petscSession::check(MatGetType(A_, &matType), "MatGetType");
    wordList have;
    std::string whyNot;
    for
    (
        const char* t :
        {
            MATSOLVERMUMPS, MATSOLVERSUPERLU_DIST, MATSOLVERSUPERLU,
            MATSOLVERPETSC, MATSOLVERUMFPACK, MATSOLVERCHOLMOD, MATSOLVERKLU,
            MATSOLVERSTRUMPACK, MATSOLVERPASTIX, MATSOLVERMKL_PARDISO,
            MATSOLVERMKL_CPARDISO, MATSOLVERSCALAPACK, MATSOLVERELEMENTAL,
            MATSOLVERSPARSEELEMENTAL, MATSOLVERSPQR, MATSOLVERLUSOL,
            MATSOLVERESSL, MATSOLVERBAS
        }
    )
    {
        if (canFactor(t, factor, whyNot))
        {
            have.append(word(t));
        }
    }
    wordList otherPcs;
    for (const word& name : preconditionerTypeNames.names())
    {
        if (name != "lu")
        {
            otherPcs.append(name);
        }
    }
    FatalIOErrorInFunction(dict)
        << (isLu ? "LU" : "Cholesky") << " factorisation (PETSc pc_type "
        << pcType << ", from " << pcFrom.c_str() << ") by '"
        << (asked ? asked : "(PETSc's default)") << "' (from "
        << factorFrom.c_str() << "): this PETSc cannot factor a " << matType
        << " matrix so on " << Pstream::nProcs() << " rank(s): "
        << why.c_str() << nl
        << "    Factor solver types available here for this matrix: ";
    if (have.empty())
    {
        FatalIOError<< "none";
    }
    else
    {
        FatalIOError<< flatOutput(have);
    }
    FatalIOError<< nl
        << "    Valid choices: "
        << (
               isLu
             ? "preconditioner lu" : "petscOptions \"-pc_type cholesky\""
           )
        << " in " << dict.name()
        << " with one of these (petscOptions \"-pc_factor_mat_solver_type"
        << " TYPE\" there, or -" << prefix_.c_str()
        << "pc_factor_mat_solver_type TYPE in PETSC_OPTIONS), or another"
        << " preconditioner " << flatOutput(otherPcs) << " (bjacobi and asm"
        << " with subPreconditioner "
        << flatOutput(subPreconditionerTypeNames.names())
        << ", fieldsplit with matrix "
        << matrixTypeNames[matrixType::aij]
        << ")" << exit(FatalIOError);
}


Foam::scalar Foam::blockSystem::forcingTerm(const scalar normB) const
{
    // Eisenstat and Walker (1996), choice 2 and its safeguard; gamma 0.9,
    // alpha 2 (local convergence of order alpha)
    const scalar gamma = 0.9;
    scalar eta = forcingMax_;
    if (forcingNorm_ > 0)
    {
        eta = gamma*sqr(normB/forcingNorm_);
        const scalar safeguard = gamma*sqr(forcingEta_);
        if (safeguard > 0.1)
        {
            eta = max(eta, safeguard);
        }
        eta = min(eta, forcingMax_);
    }
    eta = max(eta, relTol_);
    forcingNorm_ = normB;
    forcingEta_ = eta;
    return eta;
}


void Foam::blockSystem::checkBlock
(
    const scalarSquareMatrix& m,
    const char* what
) const
{
    if (m.n() != nBlock_)
    {
        FatalErrorInFunction
            << what << ": a block of size " << m.n() << " for a system of "
            << nBlock_ << " unknowns per cell" << abort(FatalError);
    }
}


Foam::label Foam::blockSystem::slot(const label celli, const label col) const
{
    // (pointers, not &cols_[i]: the last row ends at cols_.size(), which
    // UList's operator[] refuses under FULLDEBUG)
    const label* first = cols_.cdata() + rowStart_[celli];
    const label* last = cols_.cdata() + rowStart_[celli + 1];
    const label* it = std::lower_bound(first, last, col);
    if (it == last || *it != col)
    {
        FatalErrorInFunction
            << "Block column " << col << " is not in the pattern of cell "
            << celli << "'s row" << abort(FatalError);
    }
    return label(it - first);
}


inline void Foam::blockSystem::addBlock
(
    const label celli,
    const label j,
    const scalar sign,
    const scalarSquareMatrix& M
)
{
    // Row celli's m blocks are held as PETSc's row-oriented input of one
    // block row: value (r, c) of block j at r m B + j B + c
    const label B = nBlock_;
    const label stride = B*(rowStart_[celli + 1] - rowStart_[celli]);
    scalar* __restrict__ v = &values_[B*B*rowStart_[celli] + j*B];
    const scalar* __restrict__ Mv = M.cdata();
    for (label r = 0; r < B; ++r, v += stride, Mv += B)
    {
        for (label c = 0; c < B; ++c)
        {
            v[c] += sign*Mv[c];
        }
    }
}


// * * * * * * * * * * * * * * * Static Functions * * * * * * * * * * * * //

bool Foam::blockSystem::allFinite(const UList<scalar>& values)
{
    bool finite = true;
    for (const scalar v : values)
    {
        if (!std::isfinite(v))
        {
            finite = false;
            break;
        }
    }
    reduce(finite, andOp<bool>());
    return finite;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::blockSystem::blockSystem
(
    const polyMesh& mesh,
    const label nBlock,
    const dictionary& dict,
    const string& chosenBy
)
:
    mesh_(mesh),
    nBlock_(nBlock),
    globalCells_(mesh.nCells()),
    offset_(globalCells_.offset(Pstream::myProcNo())),
    nbrGlobalCell_(),
    source_(nBlock*mesh.nCells(), Zero),
    A_(nullptr),
    b_(nullptr),
    x_(nullptr),
    ksp_(nullptr),
    solverName_(),
    prefix_(),
    cpr_(),
    failure_(),
    dictOptions_(),
    dictOptionsSource_(),
    unusedOptionsChecked_(false),
    relTol_(0),
    forcing_(forcingType::none),
    forcingMax_(0.01),
    forcingNorm_(0),
    forcingEta_(0)
{
    petscSession::checkActive("blockSystem");
    if (nBlock < 1)
    {
        FatalErrorInFunction
            << "nBlock = " << nBlock << ": at least 1 unknown per cell"
            << exit(FatalError);
    }
    setNeighbourCells();
    createSolver(dict, chosenBy);
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * //

Foam::blockSystem::~blockSystem()
{
    if (ksp_) KSPDestroy(&ksp_);
    if (x_) VecDestroy(&x_);
    if (b_) VecDestroy(&b_);
    if (A_) MatDestroy(&A_);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::blockSystem::clear()
{
    values_ = Zero;
    source_ = Zero;
}


void Foam::blockSystem::addDiag(const label celli, const scalarSquareMatrix& D)
{
    checkBlock(D, "addDiag");
    addBlock(celli, diagSlot_[celli], 1, D);
}


void Foam::blockSystem::addFaceFlux
(
    const label facei,
    const scalarSquareMatrix& dFdOwn,
    const scalarSquareMatrix& dFdNei
)
{
    checkBlock(dFdOwn, "addFaceFlux");
    checkBlock(dFdNei, "addFaceFlux");

    // Rows: owner (+F), neighbour (-F); columns: owner, neighbour (the
    // signs exact: the values PETSc's ADD_VALUES summed before, in the
    // same order)
    const label o = mesh_.faceOwner()[facei];
    const label n = mesh_.faceNeighbour()[facei];
    addBlock(o, diagSlot_[o], 1, dFdOwn);
    addBlock(o, ownerSlot_[facei], 1, dFdNei);
    addBlock(n, neighbourSlot_[facei], -1, dFdOwn);
    addBlock(n, diagSlot_[n], -1, dFdNei);
}


void Foam::blockSystem::addBoundaryFaceFlux
(
    const label facei,
    const scalarSquareMatrix& dFdOwn,
    const scalarSquareMatrix& dFdNbr
)
{
    checkBlock(dFdOwn, "addBoundaryFaceFlux");
    const label o = mesh_.faceOwner()[facei];
    addBlock(o, diagSlot_[o], 1, dFdOwn);

    const label j = nbrSlot_[facei - mesh_.nInternalFaces()];
    if (j >= 0)
    {
        checkBlock(dFdNbr, "addBoundaryFaceFlux");
        addBlock(o, j, 1, dFdNbr);
    }
}


void Foam::blockSystem::assemble()
{
    // One call per block row, every block of the pattern inserted: no
    // zeroing of the matrix needed
    const label B = nBlock_;
    forAll(diagSlot_, celli)
    {
        const PetscInt row = offset_ + celli;
        const label start = rowStart_[celli];
        petscSession::check
        (
            MatSetValuesBlocked
            (
                A_, 1, &row, rowStart_[celli + 1] - start, &cols_[start],
                &values_[B*B*start], INSERT_VALUES
            ),
            "MatSetValuesBlocked"
        );
    }
    petscSession::check
    (
        MatAssemblyBegin(A_, MAT_FINAL_ASSEMBLY),
        "MatAssemblyBegin"
    );
    petscSession::check
    (
        MatAssemblyEnd(A_, MAT_FINAL_ASSEMBLY),
        "MatAssemblyEnd"
    );

    // diagonalScale: PETSc takes D from the matrix at the solver's set-up
    // only, and a matrix assembled in place leaves the set-up done (PETSc
    // 3.18 KSPSetUp): without this, every solve of the solver's life was
    // scaled by its first matrix's diagonal (measured: d = 0.5, 0.25 of a
    // 2 x 2 matrix with diagonal 4, 16 kept for the next one's 100, 1e4).
    // KSPSetOperators asks for the set-up again, D of this matrix
    PetscBool scaled = PETSC_FALSE;
    petscSession::check
    (
        KSPGetDiagonalScale(ksp_, &scaled), "KSPGetDiagonalScale"
    );
    if (scaled)
    {
        petscSession::check
        (
            KSPSetOperators(ksp_, A_, A_), "KSPSetOperators"
        );
    }
}


void Foam::blockSystem::multiply(const scalarField& x, scalarField& y) const
{
    if (x.size() != source_.size())
    {
        FatalErrorInFunction
            << "x has " << x.size() << " values, the system "
            << source_.size() << abort(FatalError);
    }
    PetscScalar* p;
    petscSession::check(VecGetArray(x_, &p), "VecGetArray");
    std::copy(x.cbegin(), x.cend(), p);
    petscSession::check(VecRestoreArray(x_, &p), "VecRestoreArray");

    petscSession::check(MatMult(A_, x_, b_), "MatMult");

    y.setSize(source_.size());
    const PetscScalar* q;
    petscSession::check(VecGetArrayRead(b_, &q), "VecGetArrayRead");
    std::copy(q, q + y.size(), y.begin());
    petscSession::check(VecRestoreArrayRead(b_, &q), "VecRestoreArrayRead");
}


Foam::solverPerformance Foam::blockSystem::solve
(
    scalarField& x,
    const bool failOnDivergence
) const
{
    if (x.size() != source_.size())
    {
        FatalErrorInFunction
            << "x has " << x.size() << " values, the system "
            << source_.size() << abort(FatalError);
    }

    // The floating-point traps that OpenFOAM sets (FOAM_SIGFPE) are held
    // from here to the end of PETSc's solve. PETSc expects non-trapping
    // arithmetic (it installs no trap itself unless asked, -fp_trap) and
    // detects a failed factorisation after the fact (a zero pivot of a
    // block, or an overflowing or NaN block: PetscKernel_A_gets_inverse_A_3
    // of the block ILU overflowed, SIGFPE, before the traps were held),
    // reporting it as KSP_DIVERGED_PC_FAILED or KSP_DIVERGED_NANORINF. The
    // initial residual too: a right-hand side of 1e155 (a fixedPressure
    // p_l of 1e160 Pa) overflowed its sum of squares, SIGFPE in this
    // function, before the solve (coupledBlockSystem, section 4). The
    // flags raised inside are discarded with the environment restored
    // (fesetenv, not feupdateenv, which would raise them again under the
    // traps); a non-finite right-hand side or solution is caught below
    std::fenv_t fpEnv;
    std::feholdexcept(&fpEnv);

    // A right-hand side with a NaN or an infinity (on any rank): no
    // system to solve (the solution is left as given)
    const bool finiteSource = allFinite(source_);

    // (cpr: the initial guess and forcing state, for a second solve on a
    // new AMG hierarchy, below)
    const scalarField x0(cpr_ ? x : scalarField());
    const scalar forcingNorm0 = forcingNorm_;
    const scalar forcingEta0 = forcingEta_;

    // Initial residual |b - A x0|
    scalarField r;
    multiply(x, r);
    r = source_ - r;
    const scalar initialResidual = Foam::sqrt(gSumSqr(r));

    PetscErrorCode ierr = 0;
    if (finiteSource && forcing_ == forcingType::eisenstatWalker)
    {
        const scalar eta = forcingTerm(Foam::sqrt(gSumSqr(source_)));
        PetscReal rtol, abstol, dtol;
        PetscInt maxits;
        petscSession::check
        (
            KSPGetTolerances(ksp_, &rtol, &abstol, &dtol, &maxits),
            "KSPGetTolerances"
        );
        petscSession::check
        (
            KSPSetTolerances(ksp_, eta, abstol, dtol, maxits),
            "KSPSetTolerances"
        );
    }
    if (finiteSource)
    {
        PetscScalar* p;
        // diagonalScale: the correction dx of A dx = b - A x0 from dx = 0
        // (PETSc scales a non-zero initial guess by the reciprocal of its
        // first D, kept for the solver's life: wrong once D is the next
        // matrix's, assemble)
        PetscBool scaled = PETSC_FALSE;
        petscSession::check
        (
            KSPGetDiagonalScale(ksp_, &scaled), "KSPGetDiagonalScale"
        );
        petscSession::check(VecGetArray(b_, &p), "VecGetArray");
        if (scaled)
        {
            std::copy(r.cbegin(), r.cend(), p);
        }
        else
        {
            std::copy(source_.cbegin(), source_.cend(), p);
        }
        petscSession::check(VecRestoreArray(b_, &p), "VecRestoreArray");
        petscSession::check(VecGetArray(x_, &p), "VecGetArray");
        if (scaled)
        {
            std::fill(p, p + x.size(), PetscScalar(0));
        }
        else
        {
            std::copy(x.cbegin(), x.cend(), p);
        }
        petscSession::check(VecRestoreArray(x_, &p), "VecRestoreArray");

        ierr = KSPSolve(ksp_, b_, x_);
        if (scaled && !ierr)
        {
            // x0 + dx, copied to x below
            petscSession::check(VecGetArray(x_, &p), "VecGetArray");
            forAll(x, i)
            {
                p[i] += x[i];
            }
            petscSession::check(VecRestoreArray(x_, &p), "VecRestoreArray");
        }
    }
    std::fesetenv(&fpEnv);
    petscSession::check(ierr, "KSPSolve");
    if (!unusedOptionsChecked_)
    {
        warnUnusedOptions();
    }

    if (!finiteSource)
    {
        failure_ = "a non-finite right-hand side (NaN or infinity)";
        const bool converged = false;
        if (failOnDivergence)
        {
            FatalErrorInFunction
                << "The block solver " << solverName_ << " (" << nBlock_
                << " unknowns per cell, " << globalCells_.size()
                << " cells): " << failure_.c_str() << exit(FatalError);
        }
        return solverPerformance
        (
            solverName_, "block", initialResidual, initialResidual, 0,
            converged, true
        );
    }

    KSPConvergedReason reason;
    PetscInt nIter;
    PetscReal finalResidual;
    petscSession::check
    (
        KSPGetConvergedReason(ksp_, &reason),
        "KSPGetConvergedReason"
    );
    petscSession::check(KSPGetIterationNumber(ksp_, &nIter), "KSPGetIt");
    petscSession::check
    (
        KSPGetResidualNorm(ksp_, &finalResidual),
        "KSPGetResidualNorm"
    );

    const PetscScalar* q;
    petscSession::check(VecGetArrayRead(x_, &q), "VecGetArrayRead");
    std::copy(q, q + x.size(), x.begin());
    petscSession::check(VecRestoreArrayRead(x_, &q), "VecRestoreArrayRead");

    // A solution with a NaN or an infinity (on any rank) is no solution,
    // whatever PETSc's reason
    const bool finite = allFinite(x);

    const char* reasonText = nullptr;
    KSPGetConvergedReasonString(ksp_, &reasonText);
    failure_.clear();
    if (!finite)
    {
        failure_ =
            std::string("a non-finite solution (KSPConvergedReason ")
          + (reasonText ? reasonText : "?") + ")";
    }
    else if
    (
        reason == KSP_DIVERGED_PC_FAILED || reason == KSP_DIVERGED_NANORINF
    )
    {
        // A breakdown (PC_FAILED: a zero pivot or a non-finite block of
        // the factorisation; NANORINF: a NaN or infinity in the
        // iterations), not a solve short of its tolerance. GMRES's
        // DIVERGED_BREAKDOWN with a finite solution is one (measured on 2
        // ranks, tests/pendularNewton: at the residuals' round-off floor
        // near convergence; the step was good)
        failure_ =
            std::string(reasonText ? reasonText : "?")
          + " (KSPConvergedReason " + std::to_string(int(reason)) + ")";
        if (reason == KSP_DIVERGED_PC_FAILED)
        {
            PC pc;
            PCFailedReason pcReason = PC_NOERROR;
            if
            (
                KSPGetPC(ksp_, &pc) == 0
             && PCGetFailedReasonRank(pc, &pcReason) == 0
             && pcReason != PC_NOERROR
            )
            {
                failure_ +=
                    std::string(": ") + PCFailedReasons[pcReason];
            }
        }
    }

    if (!failure_.empty())
    {
        // A failed preconditioner keeps its state (measured: fieldsplit
        // returned inf on the next, regular system; KSPReset of fieldsplit
        // ends in a segmentation fault in PETSc 3.18): a new solver for
        // the next solve
        PetscReal rtol, abstol, dtol;
        PetscInt maxits;
        petscSession::check
        (
            KSPGetTolerances(ksp_, &rtol, &abstol, &dtol, &maxits),
            "KSPGetTolerances"
        );
        petscSession::check(KSPDestroy(&ksp_), "KSPDestroy");
        petscSession::check
        (
            createKsp(rtol, abstol, maxits), "KSPSetFromOptions"
        );
    }

    const bool converged = reason > 0 && finite;

    // cpr: the rebuild criterion of its AMG hierarchy (cprPressureStage.H;
    // the iterations and norms are global: every rank decides alike). A
    // solve stopped short on a hierarchy built for an earlier matrix is
    // solved again at once on a new one (the matrix assembled again: its
    // state increased, PETSc sets the preconditioner up again)
    if (cpr_ && failure_.empty())
    {
        const std::string why =
            cpr_->solved(nIter, initialResidual, finalResidual, converged);
        if (!why.empty())
        {
            Info<< "blockSystem " << solverName_ << ": cpr's AMG hierarchy"
                << " built anew (build " << cpr_->nBuilds() + 1 << "): "
                << why.c_str()
                << (converged ? " (at the next set-up)" : "; solved again")
                << endl;
            if (!converged)
            {
                x = x0;
                forcingNorm_ = forcingNorm0;
                forcingEta_ = forcingEta0;
                // (an assembly increases the matrix's state)
                petscSession::check
                (
                    MatAssemblyBegin(A_, MAT_FINAL_ASSEMBLY),
                    "MatAssemblyBegin"
                );
                petscSession::check
                (
                    MatAssemblyEnd(A_, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd"
                );
                // (both solves' Krylov iterations: the count of the
                // logs' -ksp_converged_reason lines and GMRES totals)
                solverPerformance again = solve(x, failOnDivergence);
                again.nIterations() += label(nIter);
                return again;
            }
        }
    }

    if (!converged && failOnDivergence)
    {
        PetscReal rtol, abstol, dtol;
        PetscInt maxits;
        KSPGetTolerances(ksp_, &rtol, &abstol, &dtol, &maxits);
        FatalErrorInFunction
            << "The block solver " << solverName_ << " (" << nBlock_
            << " unknowns per cell, " << globalCells_.size() << " cells)"
            << " did not converge: "
            << (failure_.empty() ? (reasonText ? reasonText : "?") : failure_)
            << " (KSPConvergedReason " << int(reason) << ") after "
            << nIter << " iterations; residual " << initialResidual
            << " -> " << finalResidual << ", asked tolerance " << abstol
            << ", relTol " << rtol << ", maxIter " << maxits << nl
            << "    Look at the preconditioner (e.g. 'preconditioner asm;',"
            << " 'iluLevels 1;', 'preconditioner lu;') or maxIter in the"
            << " settings; PETSC_OPTIONS=\"-" << prefix_.c_str()
            << "ksp_monitor_true_residual\" shows the iterations"
            << exit(FatalError);
    }

    return solverPerformance
    (
        solverName_,
        "block",
        initialResidual,
        finalResidual,
        label(nIter),
        converged,
        !failure_.empty()
    );
}


Foam::tmp<Foam::scalarField> Foam::blockSystem::component
(
    const scalarField& x,
    const label nBlock,
    const label k
)
{
    auto tres = tmp<scalarField>::New(x.size()/nBlock);
    scalarField& res = tres.ref();
    forAll(res, i)
    {
        res[i] = x[nBlock*i + k];
    }
    return tres;
}


void Foam::blockSystem::setComponent
(
    scalarField& x,
    const label nBlock,
    const label k,
    const scalarField& xk
)
{
    forAll(xk, i)
    {
        x[nBlock*i + k] = xk[i];
    }
}


// ************************************************************************* //
