/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "cprPressureStage.H"
#include "petscSession.H"
#include <petscksp.h>
#include <cmath>
#include <limits>
#include <vector>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::cprPressureStage::decouplingType>
Foam::cprPressureStage::decouplingTypeNames
({
    { decouplingType::quasiImpes, "quasiImpes" },
    { decouplingType::none, "none" },
});


const Foam::Enum<Foam::cprPressureStage::amgType>
Foam::cprPressureStage::amgTypeNames
({
    { amgType::hypre, "hypre" },
    { amgType::ml, "ml" },
});


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::cprPressureStage::createMatrix(Mat A)
{
    // One value per block of A: the entries of the pressure column in the
    // rows of the pressure unknowns, on this rank (d) or another (o)
    PetscInt r0, r1;
    petscSession::check(MatGetOwnershipRange(A, &r0, &r1), "MatGetOwnership");
    const PetscInt B = nBlock_;
    const PetscInt n = (r1 - r0)/B;
    std::vector<PetscInt> dnnz(n, 0), onnz(n, 0);
    for (PetscInt i = 0; i < n; ++i)
    {
        const PetscInt row = r0 + B*i + field_;
        PetscInt nc;
        const PetscInt* cols;
        petscSession::check
        (
            MatGetRow(A, row, &nc, &cols, nullptr), "MatGetRow"
        );
        for (PetscInt j = 0; j < nc; ++j)
        {
            if (cols[j] % B == field_)
            {
                ++(cols[j] >= r0 && cols[j] < r1 ? dnnz[i] : onnz[i]);
            }
        }
        petscSession::check
        (
            MatRestoreRow(A, row, &nc, &cols, nullptr), "MatRestoreRow"
        );
    }
    MPI_Comm comm;
    petscSession::check
    (
        PetscObjectGetComm(reinterpret_cast<PetscObject>(A), &comm),
        "PetscObjectGetComm"
    );
    petscSession::check
    (
        MatCreateAIJ
        (
            comm, n, n, PETSC_DETERMINE, PETSC_DETERMINE,
            0, dnnz.data(), 0, onnz.data(), &Ap_
        ),
        "MatCreateAIJ"
    );
    petscSession::check(MatCreateVecs(Ap_, &yp_, &rp_), "MatCreateVecs");

    petscSession::check(KSPCreate(comm, &ksp_), "KSPCreate");
    petscSession::check
    (
        KSPSetOptionsPrefix(ksp_, prefix_.c_str()), "KSPSetOptionsPrefix"
    );
}


void Foam::cprPressureStage::cellWeights(const scalar* D, scalar* w) const
{
    const label B = nBlock_;
    const label p = field_;
    for (label k = 0; k < B; ++k)
    {
        w[k] = 0;
    }
    if (decoupling_ == decouplingType::quasiImpes)
    {
        // D^T w = e_p by Gaussian elimination with partial pivoting; M the
        // transpose, row-major, and the right-hand side in its last column
        std::vector<scalar> M(B*(B + 1), 0);
        scalar scale = 0;
        for (label i = 0; i < B; ++i)
        {
            for (label j = 0; j < B; ++j)
            {
                M[i*(B + 1) + j] = D[j*B + i];
                scale = max(scale, mag(D[j*B + i]));
            }
        }
        M[p*(B + 1) + B] = 1;
        bool regular = scale > 0;
        for (label k = 0; k < B && regular; ++k)
        {
            label piv = k;
            for (label i = k + 1; i < B; ++i)
            {
                if (mag(M[i*(B + 1) + k]) > mag(M[piv*(B + 1) + k]))
                {
                    piv = i;
                }
            }
            // (a pivot at round-off of the block's largest value, or not
            // finite: singular)
            const scalar pivot = M[piv*(B + 1) + k];
            if (!(std::abs(pivot) > 1e-14*scale && std::isfinite(pivot)))
            {
                regular = false;
                break;
            }
            for (label j = 0; j <= B; ++j)
            {
                std::swap(M[k*(B + 1) + j], M[piv*(B + 1) + j]);
            }
            for (label i = k + 1; i < B; ++i)
            {
                const scalar l = M[i*(B + 1) + k]/pivot;
                for (label j = k; j <= B; ++j)
                {
                    M[i*(B + 1) + j] -= l*M[k*(B + 1) + j];
                }
            }
        }
        if (regular)
        {
            for (label k = B - 1; k >= 0; --k)
            {
                scalar s = M[k*(B + 1) + B];
                for (label j = k + 1; j < B; ++j)
                {
                    s -= M[k*(B + 1) + j]*w[j];
                }
                w[k] = s/M[k*(B + 1) + k];
            }
            return;
        }
        for (label k = 0; k < B; ++k)
        {
            w[k] = 0;
        }
        const scalar Dpp = D[p*B + p];
        w[p] = Dpp != 0 && std::isfinite(Dpp) ? 1/Dpp : 1;
        return;
    }
    w[p] = 1;
}


int Foam::cprPressureStage::setUp(PC pc)
{
    PetscFunctionBeginUser;
    void* ctx;
    PetscCall(PCShellGetContext(pc, &ctx));
    cprPressureStage& s = *static_cast<cprPressureStage*>(ctx);
    Mat A;
    PetscCall(PCGetOperators(pc, nullptr, &A));
    // (-info :pc reports each set-up, the sub-step's first or a later
    // one, and the build kept or made: tests/pendularCpr replays the
    // criterion; PetscInfo's C cast of pc held from -Wold-style-cast)
    const bool keep = s.marked_ && s.Ap_ && !s.rebuild_ && !s.failed_;
    const std::string build =
        keep ? std::string("kept") : std::to_string(s.nBuilds_ + 1);
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wold-style-cast"
    PetscCall
    (
        PetscInfo
        (
            pc, "cprPressureStage: set-up (%s): build %s\n",
            s.firstSetUp_ ? "first" : "later", build.c_str()
        )
    );
#pragma GCC diagnostic pop
    s.firstSetUp_ = false;
    if (keep)
    {
        // The hierarchy, weights and A_p of the last build
        PetscFunctionReturn(0);
    }
    s.rebuild_ = false;
    s.refRate_ = -1;
    s.buildStep_ = true;
    ++s.nBuilds_;
    if (!s.Ap_)
    {
        s.createMatrix(A);
    }
    // (-log_view's events: the extraction of A_p and the weights, and
    // the AMG's set-up, each build)
    static PetscLogEvent extractEvent = 0, amgEvent = 0;
    if (!extractEvent)
    {
        PetscClassId id;
        PetscCall(PetscClassIdRegister("cprPressureStage", &id));
        PetscCall(PetscLogEventRegister("CprExtractAp", id, &extractEvent));
        PetscCall(PetscLogEventRegister("CprAmgSetUp", id, &amgEvent));
    }
    PetscCall(PetscLogEventBegin(extractEvent, 0, 0, 0, 0));
    PetscCall(MatZeroEntries(s.Ap_));

    const PetscInt B = s.nBlock_;
    const PetscInt p = s.field_;
    PetscInt r0, r1;
    PetscCall(MatGetOwnershipRange(A, &r0, &r1));
    const PetscInt n = (r1 - r0)/B;
    s.weights_.setSize(B*n);

    // Per cell: its B rows copied (one row of a matrix at a time is
    // PETSc's rule), the diagonal block, the weights, then the weighted
    // pressure columns added into the cell's row of A_p
    std::vector<std::vector<PetscInt>> cols(B);
    std::vector<std::vector<PetscScalar>> vals(B);
    std::vector<PetscScalar> D(B*B);
    std::vector<PetscInt> pCols;
    std::vector<PetscScalar> pVals;
    for (PetscInt i = 0; i < n; ++i)
    {
        const PetscInt row0 = r0 + B*i;
        std::fill(D.begin(), D.end(), 0);
        for (PetscInt k = 0; k < B; ++k)
        {
            PetscInt nc;
            const PetscInt* c;
            const PetscScalar* v;
            PetscCall(MatGetRow(A, row0 + k, &nc, &c, &v));
            cols[k].assign(c, c + nc);
            vals[k].assign(v, v + nc);
            PetscCall(MatRestoreRow(A, row0 + k, &nc, &c, &v));
            for (PetscInt j = 0; j < nc; ++j)
            {
                if (cols[k][j] >= row0 && cols[k][j] < row0 + B)
                {
                    D[k*B + cols[k][j] - row0] = vals[k][j];
                }
            }
        }
        scalar* w = &s.weights_[B*i];
        s.cellWeights(D.data(), w);
        const PetscInt rowP = r0/B + i;
        for (PetscInt k = 0; k < B; ++k)
        {
            if (w[k] == 0)
            {
                continue;
            }
            pCols.clear();
            pVals.clear();
            for (std::size_t j = 0; j < cols[k].size(); ++j)
            {
                if (cols[k][j] % B == p)
                {
                    pCols.push_back(cols[k][j]/B);
                    pVals.push_back(w[k]*vals[k][j]);
                }
            }
            PetscCall
            (
                MatSetValues
                (
                    s.Ap_, 1, &rowP, PetscInt(pCols.size()), pCols.data(),
                    pVals.data(), ADD_VALUES
                )
            );
        }
    }
    PetscCall(MatAssemblyBegin(s.Ap_, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(s.Ap_, MAT_FINAL_ASSEMBLY));
    // (the pattern is made: an entry outside it would be a bug)
    PetscCall(MatSetOption(s.Ap_, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE));
    PetscCall(PetscLogEventEnd(extractEvent, 0, 0, 0, 0));

    PetscCall(KSPSetOperators(s.ksp_, s.Ap_, s.Ap_));
    PetscCall(KSPSetFromOptions(s.ksp_));
    // (an AMG's error, e.g. a zero diagonal: a failed stage, see failed_)
    PetscCall(PetscLogEventBegin(amgEvent, 0, 0, 0, 0));
    s.failed_ = KSPSetUp(s.ksp_) != 0;
    PetscCall(PetscLogEventEnd(amgEvent, 0, 0, 0, 0));
    PetscFunctionReturn(0);
}


int Foam::cprPressureStage::apply(PC pc, Vec r, Vec z)
{
    PetscFunctionBeginUser;
    void* ctx;
    PetscCall(PCShellGetContext(pc, &ctx));
    cprPressureStage& s = *static_cast<cprPressureStage*>(ctx);
    const label B = s.nBlock_;
    const label n = s.weights_.size()/B;

    // Restriction r_p(c) = w_c^T r_c
    const PetscScalar* rv;
    PetscScalar* pv;
    PetscCall(VecGetArrayRead(r, &rv));
    PetscCall(VecGetArray(s.rp_, &pv));
    for (label i = 0; i < n; ++i)
    {
        scalar sum = 0;
        for (label k = 0; k < B; ++k)
        {
            sum += s.weights_[B*i + k]*rv[B*i + k];
        }
        pv[i] = sum;
    }
    PetscCall(VecRestoreArray(s.rp_, &pv));
    PetscCall(VecRestoreArrayRead(r, &rv));

    if (s.failed_ || KSPSolve(s.ksp_, s.rp_, s.yp_) != 0)
    {
        PetscCall(VecSet(z, std::numeric_limits<scalar>::quiet_NaN()));
        PetscFunctionReturn(0);
    }

    // Prolongation into the pressure unknowns
    PetscCall(VecSet(z, 0));
    PetscScalar* zv;
    const PetscScalar* yv;
    PetscCall(VecGetArray(z, &zv));
    PetscCall(VecGetArrayRead(s.yp_, &yv));
    for (label i = 0; i < n; ++i)
    {
        zv[B*i + s.field_] = yv[i];
    }
    PetscCall(VecRestoreArrayRead(s.yp_, &yv));
    PetscCall(VecRestoreArray(z, &zv));
    PetscFunctionReturn(0);
}


int Foam::cprPressureStage::view(PC pc, PetscViewer viewer)
{
    PetscFunctionBeginUser;
    void* ctx;
    PetscCall(PCShellGetContext(pc, &ctx));
    const cprPressureStage& s = *static_cast<cprPressureStage*>(ctx);
    PetscCall
    (
        PetscViewerASCIIPrintf
        (
            viewer, "pressure unknown %d of %d, decoupling %s\n",
            int(s.field_), int(s.nBlock_),
            decouplingTypeNames[s.decoupling_].c_str()
        )
    );
    if (s.ksp_)
    {
        PetscCall(PetscViewerASCIIPushTab(viewer));
        PetscCall(KSPView(s.ksp_, viewer));
        PetscCall(PetscViewerASCIIPopTab(viewer));
    }
    PetscFunctionReturn(0);
}


// * * * * * * * * * * * * * * * Static Functions * * * * * * * * * * * * //

bool Foam::cprPressureStage::available(const amgType amg, std::string& why)
{
    // A probe on this rank alone (PETSc's registrations are the same on
    // every rank)
    PC probe;
    petscSession::check(PCCreate(PETSC_COMM_SELF, &probe), "PCCreate");
    const PetscErrorCode ierr =
        PCSetType(probe, amgTypeNames[amg].c_str());
    why = ierr ? petscSession::lastError() : std::string();
    PCDestroy(&probe);
    return !ierr;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::cprPressureStage::cprPressureStage
(
    const label nBlock,
    const label field,
    const decouplingType decoupling,
    const std::string& prefix,
    const scalar rebuildFactor
)
:
    nBlock_(nBlock),
    field_(field),
    decoupling_(decoupling),
    prefix_(prefix),
    weights_(),
    failed_(false),
    rebuild_(true),
    marked_(false),
    rebuildFactor_(rebuildFactor),
    refRate_(-1),
    buildStep_(false),
    firstSetUp_(false),
    nBuilds_(0),
    Ap_(nullptr),
    ksp_(nullptr),
    rp_(nullptr),
    yp_(nullptr)
{}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * //

Foam::cprPressureStage::~cprPressureStage()
{
    reset();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::cprPressureStage::attach(PC pc)
{
    petscSession::check(PCShellSetContext(pc, this), "PCShellSetContext");
    petscSession::check(PCShellSetSetUp(pc, setUp), "PCShellSetSetUp");
    petscSession::check(PCShellSetApply(pc, apply), "PCShellSetApply");
    petscSession::check(PCShellSetView(pc, view), "PCShellSetView");
    petscSession::check
    (
        PCShellSetName(pc, "CPR pressure stage (AMG on the decoupled p)"),
        "PCShellSetName"
    );
}


std::string Foam::cprPressureStage::solved
(
    const label nIter,
    const scalar r0,
    const scalar rn,
    const bool converged
)
{
    if (!marked_ || rebuildFactor_ == 0 || rebuild_)
    {
        // (a build at each set-up or mark, or one already asked for)
        return std::string();
    }
    if (!converged)
    {
        // A build of an earlier sub-step's matrix (else nothing to gain)
        if (buildStep_)
        {
            return std::string();
        }
        rebuild_ = true;
        return
            "a solve stopped short of its tolerance after "
          + std::to_string(nIter) + " iterations";
    }
    // Iterations per decade (a solve with no reduction to measure, e.g.
    // 0 iterations at a zero right-hand side: no judgement)
    if (!(nIter > 0 && r0 > 0 && rn >= 0 && rn < r0))
    {
        return std::string();
    }
    const scalar rate =
        nIter/Foam::log10(r0/Foam::max(rn, r0*1e-300));
    if (buildStep_)
    {
        refRate_ = Foam::max(refRate_, rate);
        return std::string();
    }
    if (refRate_ < 0)
    {
        // No solve of the build's sub-step measured a rate (each stopped
        // short, or reduced nothing): the first later one is m_0
        refRate_ = rate;
        return std::string();
    }
    if (rate > rebuildFactor_*refRate_)
    {
        rebuild_ = true;
        return
            std::to_string(nIter) + " iterations, "
          + std::to_string(rate) + " a decade against "
          + std::to_string(refRate_) + " in the last build's sub-step"
          + " (factor " + std::to_string(rebuildFactor_) + ")";
    }
    return std::string();
}


void Foam::cprPressureStage::reset()
{
    if (ksp_) KSPDestroy(&ksp_);
    if (rp_) VecDestroy(&rp_);
    if (yp_) VecDestroy(&yp_);
    if (Ap_) MatDestroy(&Ap_);
    weights_.clear();
    failed_ = false;
    rebuild_ = true;
    refRate_ = -1;
    buildStep_ = false;
}


// ************************************************************************* //
