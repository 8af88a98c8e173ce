/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "coupledResidual.H"
#include "syncTools.H"

#include <algorithm>
#include <limits>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::coupledResidual::differenceScheme>
Foam::coupledResidual::differenceSchemeNames
({
    { differenceScheme::central, "central" },
    { differenceScheme::forward, "forward" },
});


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::coupledResidual::step
(
    const scalar xj,
    const scalar scale
) const
{
    // The steps that balance truncation and round-off errors: eps^(1/3)
    // for central differences, eps^(1/2) for forward ones
    static const scalar eps = std::numeric_limits<scalar>::epsilon();
    static const scalar hCentral = Foam::cbrt(eps);
    static const scalar hForward = Foam::sqrt(eps);
    const scalar h =
        (scheme_ == differenceScheme::central ? hCentral : hForward)
       *max(mag(xj), scale);
    // A step that is exactly representable around xj
    volatile scalar xp = xj + h;
    return xp - xj;
}


template<class LocalFunction>
void Foam::coupledResidual::localJacobian
(
    const LocalFunction& G,
    const scalar* G0,
    scalar* y,
    const scalar* scale,
    const label celli,
    const label bFacei,
    scalarSquareMatrix& dGdy
) const
{
    const label B = nBlock_;
    scalar Gp[64], Gm[64];
    const bool central = scheme_ == differenceScheme::central;
    for (label j = 0; j < B; ++j)
    {
        const scalar yj = y[j];
        // The derived residual's step (differenceStep); a step that
        // cellStep reversed (the local functions are not differentiable
        // within it on the forward side) is one-sided in both schemes: a
        // central pair would cross to that side
        const scalar h =
            differenceStep(celli, bFacei, y, j, step(yj, scale[j]));
        const bool twoSided = central && h > 0;
        {
            // (steppedFrom: the local function may ask which state y is
            // stepped from; unset on leaving, an exception included)
            struct stepGuard
            {
                const coupledResidual& r;
                ~stepGuard()
                {
                    r.stepCell_ = r.stepFace_ = -1;
                }
            } guard{*this};
            stepCell_ = celli;
            stepFace_ = bFacei;
            stepUnknown_ = j;
            stepBase_ = yj;
            y[j] = yj + h;
            G(y, Gp);
            if (twoSided)
            {
                y[j] = yj - h;
                G(y, Gm);
            }
            y[j] = yj;
        }
        for (label i = 0; i < B; ++i)
        {
            dGdy(i, j) =
                twoSided ? (Gp[i] - Gm[i])/(2*h) : (Gp[i] - G0[i])/h;
        }
    }
}


void Foam::coupledResidual::evaluate
(
    const scalarField& x,
    scalarField& R,
    blockSystem* system
) const
{
    const label B = nBlock_;
    const label nInternal = mesh_.nInternalFaces();
    const labelList& own = mesh_.faceOwner();
    const labelList& nei = mesh_.faceNeighbour();

    R.setSize(x.size());
    R = Zero;

    if (system)
    {
        system->clear();
    }

    scalarSquareMatrix dOwn(B), dNei(B);
    scalar F[64], xo[64], xn[64];

    // The states across the coupled patches (collective), then the
    // deferred terms of a derived residual (collective)
    const tmp<scalarField> txNbr = neighbourStates(x);
    const scalarField& xNbr = txNbr();
    updateDeferred(x, xNbr);

    // Cell terms
    for (label celli = 0; celli < mesh_.nCells(); ++celli)
    {
        std::copy(&x[B*celli], &x[B*celli] + B, xo);
        cellTerm(celli, xo, F);
        for (label k = 0; k < B; ++k)
        {
            R[B*celli + k] += F[k];
        }
        if (system)
        {
            localJacobian
            (
                [&](const scalar* y, scalar* G) { cellTerm(celli, y, G); },
                F,
                xo,
                cellTermStepScales(celli),
                celli, -1,
                dOwn
            );
            system->addDiag(celli, dOwn);
        }
    }

    // Internal faces
    for (label facei = 0; facei < nInternal; ++facei)
    {
        const label o = own[facei], n = nei[facei];
        std::copy(&x[B*o], &x[B*o] + B, xo);
        std::copy(&x[B*n], &x[B*n] + B, xn);
        faceFlux(facei, xo, xn, F);
        for (label k = 0; k < B; ++k)
        {
            R[B*o + k] += F[k];
            R[B*n + k] -= F[k];
        }
        if (system)
        {
            localJacobian
            (
                [&](const scalar* y, scalar* G) { faceFlux(facei, y, xn, G); },
                F,
                xo,
                xScale_.cdata(),
                o, -1,
                dOwn
            );
            localJacobian
            (
                [&](const scalar* y, scalar* G) { faceFlux(facei, xo, y, G); },
                F,
                xn,
                xScale_.cdata(),
                n, -1,
                dNei
            );
            system->addFaceFlux(facei, dOwn, dNei);
        }
    }

    // Boundary faces: across coupled patches with the exchanged states
    for (const polyPatch& pp : mesh_.boundaryMesh())
    {
        if (isA<emptyPolyPatch>(pp))
        {
            // The faces of a 2-D or 1-D mesh's empty patches carry no flux
            continue;
        }
        forAll(pp, i)
        {
            const label facei = pp.start() + i;
            const label bFacei = facei - nInternal;
            const label o = own[facei];
            std::copy(&x[B*o], &x[B*o] + B, xo);
            if (pp.coupled())
            {
                std::copy(&xNbr[B*bFacei], &xNbr[B*bFacei] + B, xn);
                faceFlux(facei, xo, xn, F);
            }
            else
            {
                boundaryFlux(facei, xo, F);
            }
            for (label k = 0; k < B; ++k)
            {
                R[B*o + k] += F[k];
            }
            if (!system)
            {
                continue;
            }
            if (pp.coupled())
            {
                localJacobian
                (
                    [&](const scalar* y, scalar* G)
                    {
                        faceFlux(facei, y, xn, G);
                    },
                    F,
                    xo,
                    xScale_.cdata(),
                    o, -1,
                    dOwn
                );
                localJacobian
                (
                    [&](const scalar* y, scalar* G)
                    {
                        faceFlux(facei, xo, y, G);
                    },
                    F,
                    xn,
                    xScale_.cdata(),
                    -1, bFacei,
                    dNei
                );
            }
            else
            {
                localJacobian
                (
                    [&](const scalar* y, scalar* G)
                    {
                        boundaryFlux(facei, y, G);
                    },
                    F,
                    xo,
                    xScale_.cdata(),
                    o, -1,
                    dOwn
                );
            }
            system->addBoundaryFaceFlux(facei, dOwn, dNei);
        }
    }

    if (system)
    {
        system->assemble();
        system->source() = -R;
    }
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

void Foam::coupledResidual::patchFace
(
    const label facei,
    label& patchi,
    label& i
) const
{
    patchi = mesh_.boundaryMesh().whichPatch(facei);
    i = facei - mesh_.boundaryMesh()[patchi].start();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coupledResidual::coupledResidual
(
    const polyMesh& mesh,
    const label nBlock,
    const scalarField& xScale,
    const differenceScheme scheme
)
:
    mesh_(mesh),
    nBlock_(nBlock),
    xScale_(xScale),
    scheme_(scheme),
    bFaceVisit_(mesh.nFaces() - mesh.nInternalFaces(), label(-1)),
    exchange_
    (
        Pstream::parRun()
     || std::any_of
        (
            mesh.boundaryMesh().cbegin(), mesh.boundaryMesh().cend(),
            [](const polyPatch& pp) { return pp.coupled(); }
        )
    ),
    noNbr_
    (
        exchange_ ? 0 : nBlock*(mesh.nFaces() - mesh.nInternalFaces()),
        Zero
    ),
    stepCell_(-1),
    stepFace_(-1),
    stepUnknown_(0),
    stepBase_(0)
{
    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        const label start = pp.start() - mesh.nInternalFaces();
        const bool empty = isA<emptyPolyPatch>(pp);
        const bool coupled = pp.coupled();
        forAll(pp, i)
        {
            bFaceVisit_[start + i] =
                empty ? -2 : coupled ? start + i : -1;
        }
    }
    if
    (
        nBlock < 1 || nBlock > 64
     || xScale.size() != nBlock || min(xScale) <= 0
    )
    {
        FatalErrorInFunction
            << "nBlock = " << nBlock << " (1 to 64) with xScale " << xScale
            << ": one typical magnitude > 0 per unknown"
            << exit(FatalError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::coupledResidual::differenceStep
(
    const label celli,
    const label bFacei,
    const scalar* y,
    const label j,
    const scalar h
) const
{
    const scalar yj = y[j];
    volatile scalar yp = yj + cellStep(celli, bFacei, y, j, h);
    return yp - yj;
}


Foam::tmp<Foam::scalarField> Foam::coupledResidual::neighbourStates
(
    const scalarField& x
) const
{
    const label B = nBlock_;
    const label nInternal = mesh_.nInternalFaces();
    const label nBoundary = mesh_.nFaces() - nInternal;
    const labelList& own = mesh_.faceOwner();

    // A serial mesh without coupled patches has no state across (the
    // values are not read): no exchange (it cost 3 % of the CPU of
    // bench/pendularNewton's 1-D column, callgrind), nor a new field of
    // zeros at each call (3.6 % of column500_defaults' instructions,
    // callgrind, 2026-12-04: the memset). A parallel run always
    // exchanges: the condition is the same on every rank
    if (!exchange_)
    {
        return tmp<scalarField>(noNbr_);
    }
    auto txNbr = tmp<scalarField>::New(B*nBoundary, Zero);
    scalarField& xNbr = txNbr.ref();
    scalarField xk(nBoundary);
    for (label k = 0; k < B; ++k)
    {
        forAll(xk, bFacei)
        {
            xk[bFacei] = x[B*own[nInternal + bFacei] + k];
        }
        syncTools::swapBoundaryFaceList(mesh_, xk);
        forAll(xk, bFacei)
        {
            xNbr[B*bFacei + k] = xk[bFacei];
        }
    }
    return txNbr;
}


void Foam::coupledResidual::residual
(
    const scalarField& x,
    scalarField& R
) const
{
    evaluate(x, R, nullptr);
}


void Foam::coupledResidual::cellResidual
(
    const label celli,
    const scalarField& x,
    const scalarField& xNbr,
    scalar* Rc
) const
{
    // The terms of evaluate() that touch cell celli (not evaluate()
    // itself: the cell term and the fluxes of its faces only), summed in
    // the order of mesh.cells()[celli], not evaluate()'s face order: the
    // sums agree to rounding, not bit for bit.
    // Each call recomputes the states of celli's neighbours, unchanged
    // between the calls of one cell's local solve; measured (perf, 2026-12-02,
    // bench/pendularNewton column500_newton): cellResidual 1.5 % of the
    // run's CPU, localWaterSolves 4.7 %, evaluate() 50 %: not worth a cache
    const label B = nBlock_;
    const labelList& own = mesh_.faceOwner();
    const labelList& nei = mesh_.faceNeighbour();
    scalar F[64];

    cellTerm(celli, &x[B*celli], Rc);
    forCellFaces
    (
        celli,
        [&](const label facei, const label nbr, const label bFacei)
        {
            scalar sign = 1;
            if (nbr >= 0)
            {
                faceFlux(facei, &x[B*own[facei]], &x[B*nei[facei]], F);
                sign = own[facei] == celli ? 1 : -1;
            }
            else if (bFacei >= 0)
            {
                faceFlux(facei, &x[B*celli], &xNbr[B*bFacei], F);
            }
            else
            {
                boundaryFlux(facei, &x[B*celli], F);
            }
            for (label k = 0; k < B; ++k)
            {
                Rc[k] += sign*F[k];
            }
        }
    );
}


Foam::tmp<Foam::scalarField> Foam::coupledResidual::jacobian
(
    const scalarField& x,
    blockSystem& system
) const
{
    if (system.nBlock() != nBlock_ || &system.mesh() != &mesh_)
    {
        FatalErrorInFunction
            << "The block system (" << system.nBlock() << " unknowns per"
            << " cell) is not on this residual's mesh with " << nBlock_
            << " unknowns per cell" << abort(FatalError);
    }
    auto tR = tmp<scalarField>::New();
    evaluate(x, tR.ref(), &system);
    return tR;
}


// ************************************************************************* //
