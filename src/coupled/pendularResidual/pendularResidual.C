/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "pendularResidual.H"
#include "meshNonOrthogonality.H"
#include "surfaceFields.H"
#include "processorFvPatch.H"
#include "cyclicFvPatch.H"
#include "cyclicPolyPatch.H"
#include "processorCyclicPolyPatch.H"
#include "zeroGradientFvPatchFields.H"
#include "syncTools.H"
#include "waterModel.H"
#include "liquidFlow.H"
#include "surfaceHeatLossFvPatchScalarField.H"
#include "relativeHumidityFvPatchScalarField.H"
#include "mixedFvPatchFields.H"
#include "calculatedFvPatchFields.H"
#include "unitConversion.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(pendularResidual, 0);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::pendularResidual::pendularResidual
(
    const pendularMedium& medium,
    const volScalarField& T,
    const volScalarField& p,
    const volScalarField& pw,
    const scalar pRef,
    const scalarField& x0,
    const scalarField& alphaOld,
    const scalar dt,
    const differenceScheme scheme,
    const labelList& phases0
)
:
    coupledResidual
    (
        T.mesh(), 3,
        // T [K], p_g - p_ref [Pa], W [kg/m3]: the scales of the steps
        // where |x| is smaller (a dry cell holds ~1e-3 kg/m3 of vapour)
        scalarField({300.0, 1.0, 1e-4}),
        scheme
    ),
    fvMesh_(T.mesh()),
    medium_(medium),
    T_(T),
    p_(p),
    pw_(pw),
    pRef_(pRef),
    kind_(fvMesh_.boundary().size(), patchKind::other),
    surfaceBalance_(fvMesh_.boundary().size(), false),
    humidity_(fvMesh_.boundary().size(), scalar(-1)),
    bcFields_(3),
    bcInternal_(),
    bcBoundary_(),
    bcCell_(),
    bcDifference_(),
    dt_(dt),
    W0_(fvMesh_.nCells()),
    A0_(fvMesh_.nCells()),
    E0_(fvMesh_.nCells()),
    WH_(fvMesh_.nCells(), Zero),
    AH_(fvMesh_.nCells(), Zero),
    EH_(fvMesh_.nCells(), Zero),
    a0_(1),
    a0W_(fvMesh_.nCells(), 1),
    eulerCells_(),
    eulerHistory_(),
    Tn_(fvMesh_.nCells()),
    alphaOld_(alphaOld),
    cache_(fvMesh_.nCells()),
    cacheNext_(fvMesh_.nCells(), Zero),
    nbrCache_(),
    satCache_(fvMesh_.nCells()),
    satNext_(fvMesh_.nCells(), Zero),
    nbrPorosity_(),
    nbrAlphaOld_(),
    phase_(fvMesh_.nCells(), label(bothPhases)),
    nbrPhase_(),
    liquidBoundaryCell_(),
    liquidOnlyScales_(xScale()),
    nonOrthCorrected_(meshNonOrthogonality::New(fvMesh_).corrected()),
    snGradCorr_(),
    deltaCoeffs_()
{
    checkSnGradSchemes(fvMesh_);
    forAll(deltaCoeffs_, k)
    {
        deltaCoeffs_[k] =
            twoPointDeltaCoeffs(fvMesh_, correctedFieldNames()[k]);
    }
    if (nonOrthCorrected_)
    {
        snGradCorr_.setSize(nCorrected*fvMesh_.nFaces(), Zero);
    }

    if (medium_.saturatedZone())
    {
        liquidOnlyScales_[1] = 1/medium_.storage();
    }

    // No state cached yet: keys no unknown can take
    nbrCache_.setSize(fvMesh_.nBoundaryFaces());
    for (auto& entries : cache_)
    {
        for (cacheEntry& e : entries)
        {
            e.x[0] = e.x[1] = e.x[2] = -GREAT;
            e.phase = -1;
            e.stepped = false;
        }
    }
    for (cacheEntry& e : nbrCache_)
    {
        e.x[0] = e.x[1] = e.x[2] = -GREAT;
        e.phase = -1;
        e.stepped = false;
    }
    for (auto& sats : satCache_)
    {
        for (pendularMedium::saturationState& sat : sats)
        {
            sat.T = -GREAT;
        }
    }

    // The patch kinds of pendularFoam (pendularState); AMI patches are
    // refused
    kind_ = pendularState::patchKinds(p_, pw_);
    forAll(surfaceBalance_, patchi)
    {
        surfaceBalance_[patchi] =
            isA<surfaceHeatLossFvPatchScalarField>(T_.boundaryField()[patchi]);
        const relativeHumidityFvPatchScalarField* rh =
            isA<relativeHumidityFvPatchScalarField>
            (
                pw_.boundaryField()[patchi]
            );
        if (rh && rh->followsPatchTemperature())
        {
            // (the residual's life is one sub-step, at its new time)
            humidity_[patchi] = rh->relativeHumidity();
        }
    }
    checkCoupledPatches(fvMesh_);

    // The boundary conditions of T, p and pw at the fields' values
    // (collective)
    forAll(bcFields_, k)
    {
        const volScalarField& fld = k == 0 ? T_ : k == 1 ? p_ : pw_;
        bcFields_.set
        (
            k,
            new volScalarField
            (
                IOobject
                (
                    fld.name() + "BoundaryCoeffs", fld.instance(), fvMesh_,
                    IOobject::NO_READ, IOobject::NO_WRITE, false
                ),
                fld
            )
        );
    }
    updateBoundaryCoeffs(nullptr);

    // The porosity and guess of the cells across processor and cyclic
    // patches (collective)
    syncTools::swapBoundaryCellList
    (
        fvMesh_, medium_.porosity().primitiveField(), nbrPorosity_
    );
    syncTools::swapBoundaryCellList(fvMesh_, alphaOld_, nbrAlphaOld_);
    setPhases(phases0.empty() ? phase_ : phases0);

    // The cells with a face on a patch the liquid may cross
    // (liquidBoundarySwitch)
    if (const liquidFlow* liquid = medium_.liquidFlowPtr())
    {
        liquidBoundaryCell_.setSize(fvMesh_.nCells(), false);
        const polyBoundaryMesh& pbm = fvMesh_.boundaryMesh();
        forAll(pbm, patchi)
        {
            if
            (
                !fvMesh_.boundary()[patchi].coupled()
             && liquid->type(patchi) != liquidFlow::patchType::impermeable
            )
            {
                for (const label celli : pbm[patchi].faceCells())
                {
                    liquidBoundaryCell_[celli] = true;
                }
            }
        }
    }

    forAll(W0_, celli)
    {
        // Model B: the old state is the one accepted at the end of the
        // last sub-step, at its liquid fraction alphaOld (the state of x0
        // would relax it once more over dt); model A: the state of x0
        const scalar phi = medium_.porosity()[celli];
        const scalar* x0c = &x0[3*celli];
        const cellState s =
            medium_.nonEquilibrium()
          ? pendularState::closure
            (
                medium_, phi, x0c[0], x0c[1] + pRef_, x0c[2],
                alphaOld_[celli],
                medium_.freeVapourDensity(x0c[2], alphaOld_[celli], phi)
            )
          : state(celli, x0c);
        Tn_[celli] = x0[3*celli];
        W0_[celli] = s.W;
        A0_[celli] = s.A;
        E0_[celli] = s.E;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::pendularResidual::bdf2
(
    const scalar a0,
    const scalar a1,
    const scalar a2,
    const scalarField& Wold,
    const scalarField& Aold,
    const scalarField& Eold,
    const scalarField& WOlder,
    const scalarField& AOlder,
    const scalarField& EOlder
)
{
    if (medium_.nonEquilibrium())
    {
        // Model B's liquid fraction is backward Euler's solution of its
        // rate law over the step (relaxedAlphaL): BDF2 of the balances
        // with it would be first order in alpha (pendularFoam refuses the
        // combination with a FatalIOError before any step)
        FatalErrorInFunction
            << "pendularResidual: BDF2 with model B (nonEquilibrium), whose"
            << " rate law is backward Euler only" << exit(FatalError);
    }
    a0_ = a0;
    DynamicList<label> cells;
    DynamicList<scalar> history;
    const scalarField& phi = medium_.porosity().primitiveField();
    forAll(W0_, celli)
    {
        const scalar H = a1*Wold[celli] - a2*WOlder[celli];
        if
        (
            H < 0
         && WOlder[celli]
          < medium_.kinkWater(phi[celli], Tn_[celli])
        )
        {
            // W >= 0 out of reach: backward Euler for this water
            a0W_[celli] = 1;
            W0_[celli] = Wold[celli];
            WH_[celli] = 0;
            cells.append(celli);
            history.append(H - Wold[celli]);
        }
        else
        {
            a0W_[celli] = a0;
            W0_[celli] = Wold[celli];
            WH_[celli] = a2*(Wold[celli] - WOlder[celli]);
        }
        A0_[celli] = Aold[celli];
        AH_[celli] = a2*(Aold[celli] - AOlder[celli]);
        E0_[celli] = Eold[celli];
        EH_[celli] = a2*(Eold[celli] - EOlder[celli]);
    }
    eulerCells_.transfer(cells);
    eulerHistory_.transfer(history);
}


void Foam::pendularResidual::setPhases(const labelList& phases)
{
    if (phases.size() != fvMesh_.nCells())
    {
        FatalErrorInFunction
            << "pendularResidual::setPhases: " << phases.size()
            << " phase states for " << fvMesh_.nCells() << " cells"
            << exit(FatalError);
    }
    forAll(phases, celli)
    {
        if
        (
            phases[celli] != bothPhases
         && !(phases[celli] == liquidOnly && medium_.saturatedZone())
        )
        {
            FatalErrorInFunction
                << "pendularResidual::setPhases: cell " << celli
                << " phase state " << phases[celli] << "; valid: "
                << label(bothPhases) << " (bothPhases), "
                << label(liquidOnly) << " (liquidOnly, with liquidFlow's"
                << " saturatedZone only)" << exit(FatalError);
        }
    }
    // (a copy first: phases may be phase_ itself)
    labelList newPhases(phases);
    phase_.transfer(newPhases);
    syncTools::swapBoundaryCellList(fvMesh_, phase_, nbrPhase_);
}


const Foam::scalar* Foam::pendularResidual::cellTermStepScales
(
    const label celli
) const
{
    return
        phase_[celli] == liquidOnly
      ? liquidOnlyScales_.cdata()
      : coupledResidual::cellTermStepScales(celli);
}


Foam::scalar Foam::pendularResidual::cellStep
(
    const label celli,
    const label bFacei,
    const scalar* y,
    const label j,
    const scalar h
) const
{
    const label phase = celli >= 0 ? phase_[celli] : nbrPhase_[bFacei];
    if (j == 2 && phase == bothPhases)
    {
        const scalar phi =
            celli >= 0 ? medium_.porosity()[celli] : nbrPorosity_[bFacei];
        // The gas room: the water a two-phase cell holds below S_l = 1
        const scalar room = phi*medium_.rhoL() - y[2];
        if (room > 0 && h > 0.5*room)
        {
            return -max(0.5*room, 1e-4*h);
        }
    }
    return liquidBoundarySwitch(celli, y, j, h) ? -h : h;
}


bool Foam::pendularResidual::liquidBoundarySwitch
(
    const label celli,
    const scalar* y,
    const label j,
    const scalar h
) const
{
    const liquidFlow* liquid = medium_.liquidFlowPtr();
    if (!liquid || celli < 0 || !liquidBoundaryCell_[celli])
    {
        return false;
    }
    const label nInternal = fvMesh_.nInternalFaces();
    const polyBoundaryMesh& pbm = fvMesh_.boundaryMesh();
    scalar yp[3] = {y[0], y[1], y[2]};
    yp[j] += h;
    // The cell's two states, evaluated once, at its first permeable
    // boundary face (copies: state() returns a reference into the cell's
    // cache, which the second evaluation may overwrite)
    bool evaluated = false;
    cellState c, cp;
    for (const label facei : fvMesh_.cells()[celli])
    {
        if (facei < nInternal)
        {
            continue;
        }
        const label patchi = pbm.whichPatch(facei);
        if
        (
            fvMesh_.boundary()[patchi].coupled()
         || liquid->type(patchi) == liquidFlow::patchType::impermeable
        )
        {
            continue;
        }
        if (!evaluated)
        {
            c = state(celli, y);
            cp = state(celli, yp);
            evaluated = true;
        }
        const label i = facei - pbm[patchi].start();
        scalar E;
        const scalar Fl =
            liquidBoundaryFlux
            (
                facei, patchi, i, c, boundaryState(patchi, i, c), E
            );
        const scalar Flp =
            liquidBoundaryFlux
            (
                facei, patchi, i, cp, boundaryState(patchi, i, cp), E
            );
        if ((Fl >= 0) != (Flp >= 0))
        {
            return true;
        }
    }
    return false;
}


bool Foam::pendularResidual::phaseConsistent
(
    const label celli,
    const scalar* x
) const
{
    const scalar phi = medium_.porosity()[celli];
    const scalar T = x[0];
    const scalar rhoL = medium_.rhoL();
    const scalar pw1 = medium_.saturatedVapourPressure(T);
    if (phase_[celli] == bothPhases)
    {
        const scalar rhoW1 = medium_.Mw()*pw1/(medium_.R()*T);
        return (x[2]/phi - rhoW1)/(rhoL - rhoW1) < 1;
    }
    const scalar pn = x[1] + pRef_ + medium_.pcSaturated(T);
    return pn > 0 && pw1 + medium_.airPressure(x[2], T) <= pn;
}


Foam::label Foam::pendularResidual::switchPhases
(
    scalarField& x,
    const boolList& heldBefore,
    boolList& switched,
    boolList& held,
    const scalar gasSeed,
    const bool hysteresis
)
{
    const label n = fvMesh_.nCells();
    switched.setSize(n);
    switched = false;
    held.setSize(n);
    held = false;
    labelList phases(phase_);
    label nSwitched = 0;
    const scalar rhoL = medium_.rhoL();
    // The band h_p, relative to the pressure (see the header: above the
    // straddle measured at the bubble point, 31 Pa at 1 atm)
    const scalar hp = 1e-3;
    for (label c = 0; c < n && medium_.saturatedZone(); ++c)
    {
        scalar* xc = &x[3*c];
        const scalar phi = medium_.porosity()[c];
        const scalar T = xc[0];
        const bool wide = hysteresis && heldBefore[c];
        const scalar pw1 = medium_.saturatedVapourPressure(T);
        const scalar pc1 = medium_.pcSaturated(T);
        if (phase_[c] == bothPhases)
        {
            const scalar rhoW1 = medium_.Mw()*pw1/(medium_.R()*T);
            const scalar S = (xc[2]/phi - rhoW1)/(rhoL - rhoW1);
            const scalar pg = xc[1] + pRef_;
            held[c] = S >= 1;
            if (S >= 1 + (wide ? medium_.storage()*hp*mag(pg) : 0))
            {
                if (debug)
                {
                    Pout<< "    switch cell " << c << " -> liquidOnly: T "
                        << T << " p_g " << pg << " S - 1 " << S - 1
                        << " (band "
                        << (wide ? medium_.storage()*hp*mag(pg) : 0) << ")"
                        << endl;
                }
                xc[1] = pg - pc1 - pRef_;
                xc[2] = medium_.dissolvedAir(max(pg - pw1, scalar(0)), T);
                phases[c] = liquidOnly;
                switched[c] = true;
                ++nSwitched;
            }
        }
        else
        {
            const scalar pn = xc[1] + pRef_ + pc1;
            const scalar pBubble = pw1 + medium_.airPressure(xc[2], T);
            held[c] = pn <= 0 || pBubble > pn;
            if (pn <= 0 || pBubble > (1 + (wide ? hp : 0))*pn)
            {
                // The gas fraction that keeps the cell's stored air: the
                // two-phase state at the cell's p_l with 1 - s of liquid
                // holds the air of the liquid-only one (A increases with
                // s: the gas's air and Henry's at p_l + p_c(1 - s));
                // within [seedMin, gasSeed], gasSeed where p_l + p_c(1) <=
                // 0 (issue 14, see the header)
                const capillaryPressureModel& pcLaw =
                    medium_.liquidFlowPtr()->capillaryPressure();
                const scalar Tl =
                    min
                    (
                        max(T, medium_.minimumTemperature()),
                        medium_.dryOutTemperature()
                    );
                const scalar sLo = min(seedMin_, gasSeed);
                scalar seed = gasSeed;
                if (pn > 0)
                {
                    const pendularMedium::saturationState& sat =
                        saturation(c, T);
                    const scalar A0 =
                        state(phi, alphaOld_[c], xc, sat, liquidOnly).A;
                    auto airAt = [&](const scalar s)
                    {
                        const scalar y[3] =
                        {
                            T, xc[1] + pcLaw.pc(1 - s, Tl),
                            medium_.waterContent(1 - s, T, phi)
                        };
                        return
                            state(phi, alphaOld_[c], y, sat, bothPhases).A;
                    };
                    if (airAt(sLo) >= A0)
                    {
                        seed = sLo;
                    }
                    else if (airAt(gasSeed) > A0)
                    {
                        // Bisection in ln s to 1e-6 of s
                        scalar a = sLo, b = gasSeed;
                        while (b > a*(1 + 1e-6))
                        {
                            const scalar m = sqrt(a*b);
                            (airAt(m) < A0 ? a : b) = m;
                        }
                        seed = sqrt(a*b);
                    }
                }
                const scalar alpha = 1 - seed;
                if (debug)
                {
                    Pout<< "    switch cell " << c << " -> bothPhases: T "
                        << T << " p_l " << xc[1] + pRef_ << " X " << xc[2]
                        << " p_b/(p_l + p_c1) - 1 "
                        << (pn > 0 ? pBubble/pn - 1 : GREAT)
                        << " (band " << (wide ? hp : 0) << ") seed "
                        << 1 - alpha << endl;
                }
                xc[2] = medium_.waterContent(alpha, T, phi);
                xc[1] = xc[1] + pcLaw.pc(alpha, Tl);
                phases[c] = bothPhases;
                switched[c] = true;
                ++nSwitched;
            }
        }
    }
    setPhases(phases);
    return nSwitched;
}


Foam::scalar Foam::pendularResidual::waterEulerCorrection
(
    const scalarField& x
) const
{
    const scalarField& V = fvMesh_.V();
    scalar c = 0;
    forAll(eulerCells_, i)
    {
        const label celli = eulerCells_[i];
        c += V[celli]*((a0_ - 1)*x[3*celli + 2] - eulerHistory_[i]);
    }
    return returnReduce(c, sumOp<scalar>());
}


void Foam::pendularResidual::updateBoundaryCoeffs
(
    const scalarField* x
) const
{
    volScalarField& Tc = bcFields_[0];
    volScalarField& pc = bcFields_[1];
    volScalarField& pwc = bcFields_[2];
    const scalar R = medium_.R();
    forAll(fvMesh_.boundary(), patchi)
    {
        const fvPatch& patch = fvMesh_.boundary()[patchi];
        if (!x || patch.coupled())
        {
            continue;
        }
        for (const label celli : patch.faceCells())
        {
            const cellState& c = state(celli, &(*x)[3*celli]);
            Tc[celli] = c.T;
            pc[celli] = c.p;
            pwc[celli] = c.rhoW*R*c.T/medium_.Mw();
        }
    }
    // The face value of field k on patch patchi is the cell's, a = 1, b =
    // 0 (in place: the lists keep their storage from one evaluation to
    // the next)
    auto cellValue = [&](const label k, const label patchi, const label n)
    {
        bcInternal_[k][patchi].setSize(n);
        bcInternal_[k][patchi] = 1;
        bcBoundary_[k][patchi].setSize(n);
        bcBoundary_[k][patchi] = Zero;
        bcDifference_[k][patchi].setSize(n);
        bcDifference_[k][patchi] = Zero;
    };
    forAll(bcFields_, k)
    {
        volScalarField::Boundary& bf = bcFields_[k].boundaryFieldRef();
        bcInternal_[k].setSize(bf.size());
        bcBoundary_[k].setSize(bf.size());
        bcCell_[k].setSize(bf.size());
        bcDifference_[k].setSize(bf.size());
        forAll(bf, patchi)
        {
            fvPatchScalarField& pf = bf[patchi];
            if (pf.coupled())
            {
                bcInternal_[k][patchi].clear();
                bcBoundary_[k][patchi].clear();
                bcCell_[k][patchi].clear();
                bcDifference_[k][patchi].clear();
                continue;
            }
            pf.patchInternalField(bcCell_[k][patchi]);
            if (polyPatch::constraintType(pf.patch().type()))
            {
                // wedge, symmetryPlane, symmetry (empty: no faces): the
                // face value of a scalar is the cell's, exactly (the
                // transform of a scalar is the identity: no flux), a = 1,
                // b = 0, as before 2026-12-03 (bit for bit: the runs of
                // tests/hearthCaseTemplatesPendular identical). Not their
                // coefficients, a = 0 and b = phi_b for a scalar wedge
                // (OpenFOAM's implicit form, the face held at its last
                // value: exact at the iterate, a spurious derivative
                // k delta |S| in the Jacobian). Taken before the
                // evaluation (b = the last iterate's phi_b - a phi_c, the
                // change of phi_c), they conducted through the wedges
                // (measured: 3 and 4 rejected sub-steps in that test)
                cellValue(k, patchi, pf.size());
                continue;
            }
            if (k == 0 && surfaceBalance_[patchi])
            {
                // surfaceHeatLoss: the face temperature is its surface
                // balance's (boundaryState), not its linearisation; the
                // copy takes that value at the iterate (its update would
                // look up pendularState's kappa, the start of the
                // sub-step's)
                cellValue(k, patchi, pf.size());
                if (x)
                {
                    const labelUList& cells = pf.patch().faceCells();
                    scalarField Tw(pf.size());
                    forAll(Tw, i)
                    {
                        Tw[i] =
                            boundaryState
                            (
                                patchi, i, state(cells[i], &(*x)[3*cells[i]])
                            ).T;
                    }
                    pf == Tw;
                }
                continue;
            }
            // The condition updated at the iterate (one that depends on
            // the state, e.g. a radiating surface, at the cells' values
            // above) and evaluated there (its values; updated again at
            // the next iterate), then its coefficients (a condition whose
            // b is its value less a times the cell's, as OpenFOAM's
            // transform conditions, is then consistent with the iterate)
            pf.updateCoeffs();
            pf.evaluate();
            const tmp<scalarField> w(fvMesh_.weights().boundaryField()[patchi]);
            bcInternal_[k][patchi] = pf.valueInternalCoeffs(w);
            bcBoundary_[k][patchi] = pf.valueBoundaryCoeffs(w);
            bcDifference_[k][patchi] =
                pf.snGrad()/pf.patch().deltaCoeffs();
        }
    }
}


void Foam::pendularResidual::transferBoundaryValues
(
    volScalarField& T,
    volScalarField& p,
    volScalarField& pw
) const
{
    volScalarField* fields[3] = {&T, &p, &pw};
    forAll(bcFields_, k)
    {
        if (&fields[k]->mesh() != &fvMesh_)
        {
            FatalErrorInFunction
                << "Field " << fields[k]->name() << " not on the residual's"
                << " mesh" << exit(FatalError);
        }
        volScalarField::Boundary& bf = fields[k]->boundaryFieldRef();
        forAll(bf, patchi)
        {
            if
            (
                bf[patchi].coupled()
             || (k == 0 && isA<surfaceHeatLossFvPatchScalarField>(bf[patchi]))
            )
            {
                continue;
            }
            bf[patchi] == bcFields_[k].boundaryField()[patchi];
        }
    }
}


bool Foam::pendularResidual::followsCondition(const fvPatch& patch)
{
    // (processorCyclic is a processor patch)
    return
        !patch.coupled()
     || isA<processorFvPatch>(patch)
     || isA<cyclicFvPatch>(patch);
}


void Foam::pendularResidual::checkCoupledPatches(const fvMesh& mesh)
{
    for (const fvPatch& patch : mesh.boundary())
    {
        if (followsCondition(patch))
        {
            continue;
        }
        FatalIOError
        (
            FUNCTION_NAME, __FILE__, __LINE__,
            mesh.boundaryMesh().objectPath(), -1, -1
        )
            << "Patch '" << patch.name() << "' of type '" << patch.type()
            << "' in " << mesh.boundaryMesh().objectPath() << ": the"
            << " Newton engine (nonlinear { engine newton; }, the default)"
            << " couples a face to one face only; valid patch types with"
            << " engine newton: patch, wall, symmetryPlane, symmetry, wedge,"
            << " empty, cyclic, processor, processorCyclic (or nonlinear {"
            << " engine segregated; } in " << mesh.solutionDict().name()
            << ")" << exit(FatalIOError);
    }
}


void Foam::pendularResidual::checkLiquidCoupledPatches
(
    const fvMesh& mesh,
    const pendularMedium& medium
)
{
    // (collective: on every rank, before any rank-dependent test)
    const bool nonOrth = meshNonOrthogonality::New(mesh).corrected();
    const liquidFlow* liquid = medium.liquidFlowPtr();
    if (!liquid)
    {
        return;
    }
    const vector& g = liquid->darcy().g();
    const scalar tol = 1e-6*mag(g);
    const fileName gFile(mesh.time().constant()/"g");
    const fileName boundaryFile(mesh.boundaryMesh().objectPath());
    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        // The cyclic pairs, whole or split over processors
        const cyclicPolyPatch* cyc = isA<cyclicPolyPatch>(pp);
        const processorCyclicPolyPatch* procCyc =
            isA<processorCyclicPolyPatch>(pp);
        if (!cyc && !procCyc)
        {
            continue;
        }
        const coupledPolyPatch& cpp = refCast<const coupledPolyPatch>(pp);
        const coupledPolyPatch& named =
            cyc ? refCast<const coupledPolyPatch>(pp) : procCyc->referPatch();
        // A rotation R with R g != g: g.x is not the same at a face and at
        // its image, the liquid's potential not periodic
        for (const tensor& R : cpp.forwardT())
        {
            if (mag((R & g) - g) <= tol)
            {
                continue;
            }
            FatalIOError
            (
                FUNCTION_NAME, __FILE__, __LINE__, gFile, -1, -1
            )
                << "Gravity g = " << g << " in " << gFile << " is not"
                << " parallel to the rotation axis ";
            if (isA<cyclicPolyPatch>(named))
            {
                FatalIOError
                    << refCast<const cyclicPolyPatch>(named).rotationAxis();
            }
            FatalIOError
                << " (rotation tensor " << R << ") of cyclic patch '"
                << named.name() << "' in " << boundaryFile << ": the"
                << " liquid's potential p_g - p_c - rho_l g.x is not"
                << " periodic across the pair; valid with liquidFlow: a"
                << " rotational pair whose axis is parallel to g, or a"
                << " translational pair" << exit(FatalIOError);
        }
        // A translation s with g.s != 0 on a non-orthogonal mesh: the
        // potential's cell values across the pair differ by rho_l g.s,
        // which the non-orthogonal correction's gradients take as a jump
        // (updateDeferred; the two-point part, liquidDarcyFlux::massFlux,
        // takes g.d with the face's own d)
        if (!nonOrth)
        {
            continue;
        }
        for (const vector& sep : cpp.separation())
        {
            if (mag(g & sep) <= tol*mag(sep))
            {
                continue;
            }
            FatalIOError
            (
                FUNCTION_NAME, __FILE__, __LINE__, gFile, -1, -1
            )
                << "Gravity g = " << g << " in " << gFile << " has a"
                << " component along the separation " << sep << " m of"
                << " cyclic patch '" << named.name() << "' in "
                << boundaryFile << " on a non-orthogonal mesh: the"
                << " non-orthogonal correction of the liquid's potential"
                << " p_g - p_c - rho_l g.x would take its jump rho_l g.s"
                << " across the pair as a gradient; valid with liquidFlow"
                << " and a translational pair: g normal to its separation"
                << " (g.s = 0), or an orthogonal mesh"
                << exit(FatalIOError);
        }
    }
}


Foam::wordList Foam::pendularResidual::correctedFieldNames()
{
    return wordList({"T", "p", "omegaW", "liquidPotential"});
}


const Foam::surfaceScalarField*
Foam::pendularResidual::twoPointDeltaCoeffs
(
    const fvMesh& mesh,
    const word& field
)
{
    // A field to ask the scheme its delta coefficients with (they do not
    // depend on its values)
    const volScalarField probe
    (
        IOobject
        (
            "snGradSchemeProbe", mesh.time().timeName(), mesh,
            IOobject::NO_READ, IOobject::NO_WRITE, false
        ),
        mesh,
        dimensionedScalar(dimless, Zero)
    );
    const tmp<fv::snGradScheme<scalar>> scheme =
        fv::snGradScheme<scalar>::New
        (
            mesh, mesh.snGradScheme("snGrad(" + field + ')')
        );
    const surfaceScalarField* dc = &scheme().deltaCoeffs(probe)();
    return
        dc == &mesh.nonOrthDeltaCoeffs() || dc == &mesh.deltaCoeffs()
      ? dc
      : nullptr;
}


Foam::word Foam::pendularResidual::snGradSchemeName
(
    const fvMesh& mesh,
    const word& field
)
{
    // (fvSchemes hands the entry's stream rewound to each reader)
    ITstream& is = mesh.snGradScheme("snGrad(" + field + ')');
    word name;
    is >> name;
    is.rewind();
    return name;
}


Foam::wordList Foam::pendularResidual::supportedSnGradSchemes()
{
    return wordList
    (
        {"corrected", "uncorrected", "limited", "faceCorrected", "orthogonal"}
    );
}


void Foam::pendularResidual::checkSnGradSchemes(const fvMesh& mesh)
{
    const wordList valid(supportedSnGradSchemes());
    for (const word& name : correctedFieldNames())
    {
        // By name first: the fit schemes and skewCorrected have the mesh's
        // delta coefficients but corrections of their own, which an
        // orthogonal mesh does not skip (updateDeferred does)
        const word scheme = snGradSchemeName(mesh, name);
        if (valid.found(scheme) && twoPointDeltaCoeffs(mesh, name))
        {
            continue;
        }
        string validList;
        for (const word& v : valid)
        {
            validList += (validList.empty() ? "" : ", ") + v;
        }
        const dictionary& snGradDict =
            mesh.schemesDict().subDict("snGradSchemes");
        const word key = "snGrad(" + name + ')';
        FatalIOErrorInFunction(snGradDict)
            << "Keyword '" << (snGradDict.found(key) ? key : word("default"))
            << "' in " << snGradDict.name() << ": the snGrad scheme of "
            << name << " (" << scheme << ") is not supported by"
            << " pendularFoam's Newton engine, whose face fluxes take the"
            << " two-point gradient with the mesh's delta coefficients and"
            << " the scheme's non-orthogonal correction only: valid schemes "
            << validList.c_str() << " (or nonlinear { engine segregated; })"
            << exit(FatalIOError);
    }
}


void Foam::pendularResidual::updateDeferred
(
    const scalarField& x,
    const scalarField&
) const
{
    // The boundary conditions at x (collective), then the non-orthogonal
    // corrections (the same on every rank: meshNonOrthogonality::corrected
    // is reduced)
    updateBoundaryCoeffs(&x);
    if (!nonOrthCorrected_)
    {
        return;
    }
    const liquidFlow* liquid = medium_.liquidFlowPtr();
    const wordList names(correctedFieldNames());
    const dimensionSet dims[nCorrected] =
        {dimTemperature, dimPressure, dimless, dimPressure};
    PtrList<volScalarField> fields(nCorrected);
    forAll(names, k)
    {
        fields.set
        (
            k,
            new volScalarField
            (
                IOobject
                (
                    names[k], fvMesh_.time().timeName(), fvMesh_,
                    IOobject::NO_READ, IOobject::NO_WRITE, false
                ),
                fvMesh_,
                dimensionedScalar(dims[k], Zero),
                calculatedFvPatchScalarField::typeName
            )
        );
    }
    volScalarField& Tf = fields[0];
    volScalarField& pf = fields[1];
    volScalarField& omegaf = fields[2];
    volScalarField& Phif = fields[3];
    const vectorField& C = fvMesh_.C();
    forAll(Tf, celli)
    {
        const cellState& s = state(celli, &x[3*celli]);
        Tf[celli] = s.T;
        pf[celli] = s.p;
        omegaf[celli] = s.omega;
        if (liquid)
        {
            const liquidDarcyFlux::liquidState l = liquidState(s);
            Phif[celli] =
                l.pg - l.pc
              - liquid->darcy().rhoLiquid()*(liquid->darcy().g() & C[celli]);
        }
    }
    // The faces of patches that are not coupled: pendularState's values
    // (boundaryState); those of coupled patches: the cells across
    // (correctBoundaryConditions, collective)
    forAll(fvMesh_.boundary(), patchi)
    {
        const fvPatch& patch = fvMesh_.boundary()[patchi];
        if (patch.coupled())
        {
            continue;
        }
        scalarField& Tp = Tf.boundaryFieldRef()[patchi];
        scalarField& pp = pf.boundaryFieldRef()[patchi];
        scalarField& omegap = omegaf.boundaryFieldRef()[patchi];
        scalarField& Phip = Phif.boundaryFieldRef()[patchi];
        forAll(Tp, i)
        {
            const label celli = patch.faceCells()[i];
            const cellState b =
                boundaryState(patchi, i, state(celli, &x[3*celli]));
            Tp[i] = b.T;
            pp[i] = b.p;
            omegap[i] = b.omega;
            Phip[i] = Phif[celli];
        }
    }
    forAll(fields, k)
    {
        fields[k].correctBoundaryConditions();
    }

    snGradCorr_ = Zero;
    const label nInternal = fvMesh_.nInternalFaces();
    forAll(fields, k)
    {
        // (the fvSchemes' scheme of the field, as fvc::snGrad selects it)
        const tmp<fv::snGradScheme<scalar>> scheme =
            fv::snGradScheme<scalar>::New
            (
                fvMesh_, fvMesh_.snGradScheme("snGrad(" + names[k] + ')')
            );
        if ((k == 3 && !liquid) || !scheme().corrected())
        {
            continue;
        }
        const tmp<surfaceScalarField> tcorr = scheme().correction(fields[k]);
        const surfaceScalarField& corr = tcorr();
        for (label facei = 0; facei < nInternal; ++facei)
        {
            snGradCorr_[nCorrected*facei + k] = corr[facei];
        }
        forAll(corr.boundaryField(), patchi)
        {
            const fvsPatchScalarField& cp = corr.boundaryField()[patchi];
            if (!cp.coupled())
            {
                continue;
            }
            const label start = fvMesh_.boundary()[patchi].start();
            forAll(cp, i)
            {
                snGradCorr_[nCorrected*(start + i) + k] = cp[i];
            }
        }
    }
}


Foam::tmp<Foam::scalarField> Foam::pendularResidual::pack
(
    const scalarField& T,
    const scalarField& p,
    const scalarField& W,
    const scalar pRef
)
{
    tmp<scalarField> tx(new scalarField(3*T.size()));
    scalarField& x = tx.ref();
    forAll(T, c)
    {
        x[3*c] = T[c];
        x[3*c + 1] = p[c] - pRef;
        x[3*c + 2] = W[c];
    }
    return tx;
}


const Foam::pendularResidual::cellState& Foam::pendularResidual::state
(
    const label celli,
    const scalar* x
) const
{
    FixedList<cacheEntry, nCache>& entries = cache_[celli];
    const label phase = phase_[celli];
    // A state at the same T and W (e.g. the Jacobian's step of p_g) has
    // the same liquid fraction and vapour: only the gas closure is new
    // (two-phase cells: a liquidOnly state is cheap). Not with model B,
    // whose relaxed liquid fraction depends on p_g too (the rate law's
    // rho_g and p_g; its other arguments, alphaOld_ and dt_, are fixed
    // for the residual's life: the key (x, phase) is complete). The first
    // such entry, found in the same pass as the state itself. A stepped
    // entry serves a stepped state only, and is no such entry
    scalar x0[3];
    const cellState* same = nullptr;
    for (const cacheEntry& e : entries)
    {
        if (e.x[0] == x[0] && e.x[2] == x[2] && e.phase == phase)
        {
            if (e.stepped)
            {
                if (e.x[1] == x[1] && steppedFrom(celli, -1, x, x0))
                {
                    return e.s;
                }
                continue;
            }
            if (e.x[1] == x[1])
            {
                return e.s;
            }
            if (!same)
            {
                same = &e.s;
            }
        }
    }
    if (same && (phase != bothPhases || medium_.nonEquilibrium()))
    {
        same = nullptr;
    }
    // A state the Jacobian stepped, and the state it is stepped from
    // (not with the saturated zone: stepped states as the residual's)
    const bool stepped =
        !medium_.saturatedZone() && steppedFrom(celli, -1, x, x0);
    // The root of the state stepped from (before this one takes a slot:
    // a hit, the state of the residual at x; else evaluated here)
    scalar alphaB = 0, rhoWB = 0, TB = 0;
    if (stepped && !same)
    {
        const cellState& b = state(celli, x0);
        alphaB = b.alpha;
        rhoWB = b.rhoW;
        TB = b.T;
    }
    label& next = cacheNext_[celli];
    cacheEntry& e = entries[next];
    next = (next + 1) % nCache;
    e.s =
        same
      ? pendularState::closure
        (
            medium_, medium_.porosity()[celli], x[0], x[1] + pRef_, x[2],
            same->alpha, same->rhoW
        )
      : stepped
      ? steppedState
        (
            medium_.porosity()[celli], alphaOld_[celli], x,
            saturation(celli, x[0]), phase, x0, alphaB, rhoWB, TB
        )
      : state
        (
            medium_.porosity()[celli], alphaOld_[celli], x,
            saturation(celli, x[0]), phase
        );
    e.stepped = stepped && !same;
    e.phase = phase;
    e.x[0] = x[0];
    e.x[1] = x[1];
    e.x[2] = x[2];
    return e.s;
}


const Foam::pendularMedium::saturationState&
Foam::pendularResidual::saturation
(
    const label celli,
    const scalar T
) const
{
    FixedList<pendularMedium::saturationState, 2>& sats = satCache_[celli];
    for (const pendularMedium::saturationState& sat : sats)
    {
        if (sat.T == T)
        {
            return sat;
        }
    }
    label& next = satNext_[celli];
    pendularMedium::saturationState& sat = sats[next];
    next = 1 - next;
    sat = medium_.saturationValues(T);
    return sat;
}


Foam::pendularResidual::cellState Foam::pendularResidual::state
(
    const scalar phi,
    const scalar alphaOld,
    const scalar* x,
    const pendularMedium::saturationState& sat,
    const label phase
) const
{
    if (phase == liquidOnly)
    {
        // No gas: (T, p_l - p_ref, X)
        return
            pendularState::liquidOnlyClosure
            (
                medium_, phi, x[0], x[1] + pRef_, x[2]
            );
    }
    // The water model's split of W (as pendularState::update() over the
    // sub-step): model A the liquid fraction holding W at T and the vapour
    // in Kelvin-Laplace equilibrium with it (alphaOld the guess of the
    // inversion); model B the liquid fraction relaxed over dt_ from
    // alphaOld by the backward-Euler rate law at (T, p_g, W) (Canot 2024,
    // §1, eq. after 17; waterModels::nonEquilibrium::relaxedAlphaL) and
    // the free vapour of the rest. Then pendularState's closure (p_wsat
    // and sigma at T, not their slopes)
    const scalar T = x[0];
    const scalar pg = x[1] + pRef_;
    const scalar W = x[2];
    scalar alpha, rhoW;
    medium_.water().liquidAndVapour
    (
        W, sat, phi, pg, alphaOld, dt_, alphaOld, alpha, rhoW
    );
    return pendularState::closure(medium_, phi, T, pg, W, alpha, rhoW);
}


Foam::pendularResidual::cellState Foam::pendularResidual::steppedState
(
    const scalar phi,
    const scalar alphaOld,
    const scalar* x,
    const pendularMedium::saturationState& sat,
    const label phase,
    const scalar* x0,
    const scalar alphaB,
    const scalar rhoWB,
    const scalar TB
) const
{
    if (phase != bothPhases || medium_.nonEquilibrium())
    {
        // liquidOnly: no inversion; model B: its rate law from alphaOld
        return state(phi, alphaOld, x, sat, phase);
    }
    const scalar T = x[0];
    const scalar pg = x[1] + pRef_;
    const scalar W = x[2];
    if (T == x0[0] && W == x0[2])
    {
        // A step of p_g: the liquid fraction and vapour stepped from
        return pendularState::closure(medium_, phi, T, pg, W, alphaB, rhoWB);
    }
    scalar alpha, rhoW;
    if
    (
        !medium_.alphaLNear
        (
            W, sat, phi, alphaB, rhoWB, TB, alpha, rhoW
        )
    )
    {
        // Inverted from the root stepped from (if dry: from alphaOld, as
        // the residual)
        medium_.water().liquidAndVapour
        (
            W, sat, phi, pg, alphaOld, dt_,
            alphaB > 0 ? alphaB : alphaOld, alpha, rhoW
        );
    }
    return pendularState::closure(medium_, phi, T, pg, W, alpha, rhoW);
}


Foam::pendularResidual::cellState Foam::pendularResidual::neighbourState
(
    const label bFacei,
    const scalar* xNei
) const
{
    const scalar phi = nbrPorosity_[bFacei];
    const scalar alphaOld = nbrAlphaOld_[bFacei];
    const label phase = nbrPhase_[bFacei];
    scalar x0[3];
    const bool stepped =
        !medium_.saturatedZone() && steppedFrom(-1, bFacei, xNei, x0);
    const scalar* key = stepped ? x0 : xNei;
    cacheEntry& e = nbrCache_[bFacei];
    if
    (
        !(
            e.x[0] == key[0] && e.x[1] == key[1] && e.x[2] == key[2]
         && e.phase == phase
        )
    )
    {
        e.s =
            state
            (
                phi, alphaOld, key, medium_.saturationValues(key[0]), phase
            );
        e.x[0] = key[0];
        e.x[1] = key[1];
        e.x[2] = key[2];
        e.phase = phase;
    }
    if (!stepped)
    {
        return e.s;
    }
    return
        steppedState
        (
            phi, alphaOld, xNei, medium_.saturationValues(xNei[0]), phase,
            x0, e.s.alpha, e.s.rhoW, e.s.T
        );
}


Foam::pendularResidual::cellState Foam::pendularResidual::boundaryState
(
    const label patchi,
    const label i,
    const cellState& c
) const
{
    // pendularState::update(): T, p, pw from their conditions, the
    // densities and enthalpies from those; K_g and k_e zeroGradient
    const fvPatchScalarField& Tp = T_.boundaryField()[patchi];
    const scalar R = medium_.R();
    const scalar pwc = c.rhoW*R*c.T/medium_.Mw();

    // Each face value from its cell's by the patch field's own
    // linearisation, phi_b = a phi_c + b (valueInternalCoeffs,
    // valueBoundaryCoeffs at the last iterate, updateBoundaryCoeffs), as
    // fvm::laplacian's boundary coefficients and the snGrad of
    // pendularState's fluxes: a fixed value (a = 0), zeroGradient (a = 1,
    // b = 0), fixedGradient g (a = 1, b = g/delta), mixed with value
    // fraction f (a = 1 - f, b = f phi_ref + (1 - f) g_ref/delta), any
    // other condition alike
    cellState b(c);
    b.T = boundaryValue(0, patchi, i, c.T);
    if (surfaceBalance_[patchi])
    {
        // The surface temperature balancing the condition's exact flux
        // with the half cell's conduction (as pendularState::update), not
        // the condition's value (a mixed condition 'fixes' it: Tp[i],
        // from the last evaluation, would lag over the iterations)
        b.T =
            refCast<const surfaceHeatLossFvPatchScalarField>(Tp)
           .wallTemperature
            (
                c.T, c.kappa*fvMesh_.boundary()[patchi].deltaCoeffs()[i]
            );
    }
    b.p = boundaryValue(1, patchi, i, c.p);
    // relativeHumidity without airTemperature: p_w = RH p_wsat(T_b) of
    // this face's T_b (the condition's, relativeHumidityFvPatchScalarField
    // ::updateCoeffs, at the solution; its copy in bcFields_ would take
    // T_b of the solver's T, the start of the sub-step, which it looks up)
    b.pw =
        humidity_[patchi] >= 0
      ? humidity_[patchi]*medium_.saturationPressure(b.T)
      : boundaryValue(2, patchi, i, pwc);
    b.pa = b.p - b.pw;
    b.rhoW = medium_.Mw()*b.pw/(R*b.T);
    b.rhoA = medium_.Ma()*b.pa/(R*b.T);
    b.rhoG = b.rhoW + b.rhoA;
    b.omega = b.rhoW/b.rhoG;
    b.hW = medium_.vapourEnthalpy(b.T);
    b.hA = medium_.airEnthalpy(b.T);
    return b;
}


void Foam::pendularResidual::flux
(
    const cellState& o,
    const cellState& n,
    const scalar magSf,
    const scalar w,
    const scalar* dc,
    const scalar* corr,
    scalar* F
) const
{
    // pendularState::fluxes(): linear interpolation (owner weight w) but
    // for xi D_wa (pendularState::faceValue: harmonic), upwind carried
    // values (owner where the flux is >= 0)
    // With liquidFlow, times k_rg of the face (liquidFlow::krgFace: as
    // k_rl, upwind of the gas pressure difference by default)
    // The snGrad of each field dc (phi_n - phi_o) + c, dc its scheme's
    // delta coefficient, c its non-orthogonal correction, written
    // dc (phi_n - phi_o + c/dc): without a correction the values of the
    // two-point fluxes, bit for bit
    const scalar dT = n.T - o.T + (corr ? corr[0]/dc[0] : 0);
    const scalar dp = n.p - o.p + (corr ? corr[1]/dc[1] : 0);
    const scalar dOmega = n.omega - o.omega + (corr ? corr[2]/dc[2] : 0);
    const liquidFlow* liquid = medium_.liquidFlowPtr();
    const scalar KgByMu =
        (w*o.Kg + (1 - w)*n.Kg)/medium_.gasViscosity()
       *(liquid ? liquid->krgFace(o.alpha, n.alpha, dp, w) : 1);
    const scalar q = -KgByMu*dp*dc[1]*magSf;
    const scalar j =
        -pendularState::faceValue(o.Dv, n.Dv, w)*(w*o.rhoG + (1 - w)*n.rhoG)
        *dOmega*dc[2]*magSf;
    const scalar Fw = (q >= 0 ? o.rhoW : n.rhoW)*q + j;
    const scalar Fa = (q >= 0 ? o.rhoA : n.rhoA)*q - j;
    F[0] = Fw;
    F[1] = Fa;
    F[2] =
        -(w*o.kappa + (1 - w)*n.kappa)*dT*dc[0]*magSf
      + Fa*(Fa >= 0 ? o.hA : n.hA)
      + Fw*(Fw >= 0 ? o.hW : n.hW);
}


void Foam::pendularResidual::scales
(
    const scalarField& x,
    scalarField& water,
    scalarField& gas,
    scalarField& energy
) const
{
    const label n = fvMesh_.nCells();
    water.setSize(n);
    gas.setSize(n);
    energy.setSize(n);
    const scalarField& V = fvMesh_.V();
    forAll(water, celli)
    {
        const scalar phi = medium_.porosity()[celli];
        const cellState s = state(celli, &x[3*celli]);
        const scalar pa = s.pa;
        water[celli] = a0W_[celli]*V[celli]/dt_;
        gas[celli] =
            s.liquidOnly
            // dA/dp_a of the dissolved air, phi M_a H^cp
          ? a0_*V[celli]*phi*medium_.Ma()*medium_.henry(s.T)/dt_
          : a0_*V[celli]*phi*(1 - s.alpha)*medium_.Ma()
           /(medium_.R()*s.T*dt_);
        if (medium_.saturatedZone() && !s.liquidOnly)
        {
            // and the dissolved air's, phi alpha M_a H^cp: the capacity
            // stays finite as the gas vanishes
            gas[celli] +=
                a0_*V[celli]*phi*s.alpha*medium_.Ma()*medium_.henry(s.T)
               /dt_;
        }
        energy[celli] =
            a0_*V[celli]
           *medium_.energyCapacity
            (
                medium_.saturation(s.T), s.W, s.alpha, pa, phi
            )/dt_;
    }
}


void Foam::pendularResidual::cellTerm
(
    const label celli,
    const scalar* x,
    scalar* S
) const
{
    const cellState& s = state(celli, x);
    const scalar VByDt = fvMesh_.V()[celli]/dt_;
    S[0] = VByDt*(a0W_[celli]*(s.W - W0_[celli]) - WH_[celli]);
    S[1] = VByDt*(a0_*(s.A - A0_[celli]) - AH_[celli]);
    S[2] = VByDt*(a0_*(s.E - E0_[celli]) - EH_[celli]);
}


void Foam::pendularResidual::faceFlux
(
    const label facei,
    const scalar* xOwn,
    const scalar* xNei,
    scalar* F
) const
{
    // (references into the cache of two different cells)
    const cellState& o = state(fvMesh_.faceOwner()[facei], xOwn);
    if (facei < fvMesh_.nInternalFaces())
    {
        const cellState& n = state(fvMesh_.faceNeighbour()[facei], xNei);
        const scalar dc[3] =
        {
            (*deltaCoeffs_[0])[facei],
            (*deltaCoeffs_[1])[facei],
            (*deltaCoeffs_[2])[facei]
        };
        flux
        (
            o, n, fvMesh_.magSf()[facei], fvMesh_.weights()[facei], dc,
            snGradCorrections(facei), F
        );
        addLiquidFlux(facei, o, n, F);
        return;
    }

    // A face of a processor or cyclic patch: the cell across at xNei
    label patchi, i;
    patchFace(facei, patchi, i);
    const label bFacei = facei - fvMesh_.nInternalFaces();
    const cellState n = neighbourState(bFacei, xNei);
    const scalar dc[3] =
    {
        deltaCoeffs_[0]->boundaryField()[patchi][i],
        deltaCoeffs_[1]->boundaryField()[patchi][i],
        deltaCoeffs_[2]->boundaryField()[patchi][i]
    };
    flux
    (
        o, n, fvMesh_.magSf().boundaryField()[patchi][i],
        fvMesh_.weights().boundaryField()[patchi][i], dc,
        snGradCorrections(facei), F
    );
    addLiquidFlux(facei, o, n, F);
}


void Foam::pendularResidual::boundaryFlux
(
    const label facei,
    const scalar* xOwn,
    scalar* F
) const
{
    label patchi, i;
    patchFace(facei, patchi, i);
    const fvPatch& patch = fvMesh_.boundary()[patchi];
    const cellState& c = state(fvMesh_.faceOwner()[facei], xOwn);
    const cellState b = boundaryState(patchi, i, c);
    const scalar magSf = patch.magSf()[i];
    const scalar dc = patch.deltaCoeffs()[i];
    // (phi_b - phi_c of the conditions, boundaryDifference; the surface
    // balance's temperature of surfaceHeatLoss, boundaryState)
    const scalar conduction =
       -c.kappa
       *(
            surfaceBalance_[patchi]
          ? b.T - c.T
          : boundaryDifference(0, patchi, i, c.T)
        )
       *dc*magSf;

    switch (kind_[patchi])
    {
        case patchKind::open:
        {
            // Outflow carries the cell's values (q > 0), inflow the
            // atmosphere's
            // (with liquidFlow, k_rg of the cell: the face holds its S)
            const liquidFlow* liquid = medium_.liquidFlowPtr();
            const scalar q =
               -c.Kg*(liquid ? liquid->krg(c.alpha) : 1)
               /medium_.gasViscosity()*boundaryDifference(1, patchi, i, c.p)
               *dc*magSf;
            const scalar j =
                -c.Dv*b.rhoG*(b.omega - c.omega)
                *dc*magSf;
            const scalar Fw = (q > 0 ? c.rhoW : b.rhoW)*q + j;
            const scalar Fa = (q > 0 ? c.rhoA : b.rhoA)*q - j;
            F[0] = Fw;
            F[1] = Fa;
            F[2] =
                conduction
              + Fa*(Fa > 0 ? c.hA : b.hA)
              + Fw*(Fw > 0 ? c.hW : b.hW);
            break;
        }
        case patchKind::semiPermeable:
        {
            // No air: the vapour diffuses with its Stefan flow,
            // F_w = j rho_g/rho_a (bounded by 100), upwind of j
            const scalar j =
                -c.Dv*b.rhoG*(b.omega - c.omega)
                *dc*magSf;
            const bool out = j > 0;
            const scalar rhoAf = out ? c.rhoA : b.rhoA;
            const scalar rhoGf = out ? c.rhoG : b.rhoG;
            F[0] = j*pendularState::stefanFactor(rhoAf, rhoGf);
            F[1] = 0;
            F[2] = conduction + F[0]*(out ? c.hW : b.hW);
            break;
        }
        default:
        {
            // Impermeable and constraint patches: conduction only
            F[0] = 0;
            F[1] = 0;
            F[2] = conduction;
        }
    }

    // The liquid by its own condition (liquidFlow: impermeable where not
    // given), the face state at the patch's saturation or liquid pressure
    // and the face's p_g and T; outflow carries the cell's enthalpy,
    // inflow the face's
    scalar FlE;
    const scalar Fl = liquidBoundaryFlux(facei, patchi, i, c, b, FlE);
    F[0] += Fl;
    F[2] += FlE;
    scalar FaE;
    F[1] += dissolvedAirBoundaryFlux(Fl, c, b, FaE);
    F[2] += FaE;
}


Foam::scalar Foam::pendularResidual::dissolvedAirBoundaryFlux
(
    const scalar Fl,
    const cellState& c,
    const cellState& b,
    scalar& enthalpyFlow
) const
{
    enthalpyFlow = 0;
    if (!medium_.saturatedZone() || Fl == 0)
    {
        return 0;
    }
    // The dissolved air: the cell's out, Henry's at the face's p_a in
    const scalar Fa = Fl*(Fl >= 0 ? c.X : medium_.dissolvedAir(b.pa, b.T));
    enthalpyFlow = Fa*(Fl >= 0 ? c.hA : b.hA);
    return Fa;
}


Foam::scalar Foam::pendularResidual::liquidBoundaryFlux
(
    const label facei,
    const label patchi,
    const label i,
    const cellState& c,
    const cellState& b,
    scalar& enthalpyFlow
) const
{
    enthalpyFlow = 0;
    const liquidFlow* liquid = medium_.liquidFlowPtr();
    if (!liquid || liquid->type(patchi) == liquidFlow::patchType::impermeable)
    {
        return 0;
    }
    const scalar Fl =
        liquid->boundaryFlux
        (
            facei, patchi, i, liquidState(c), b.p, liquidTemperature(b.T)
        );
    enthalpyFlow = Fl*medium_.liquidEnthalpy(Fl >= 0 ? c.T : b.T);
    return Fl;
}


Foam::liquidDarcyFlux::liquidState Foam::pendularResidual::liquidState
(
    const cellState& s
) const
{
    liquidDarcyFlux::liquidState l =
        medium_.liquidFlowPtr()->state
        (
            s.p, s.alpha, liquidTemperature(s.T)
        );
    // A cell without liquid (alpha_l = 0: above T_d; below it the
    // Kelvin-Laplace state keeps alpha_l > 0) gives none, whatever the
    // relative permeability law says at S = 0: the upwind k_rl of a flux
    // out of it is 0 (ours are all 0 there already: a safeguard)
    if (s.alpha <= 0)
    {
        l.krl = 0;
    }
    return l;
}


Foam::scalar Foam::pendularResidual::liquidTemperature
(
    const scalar T
) const
{
    return
        min
        (
            max(T, medium_.minimumTemperature()),
            medium_.dryOutTemperature()
        );
}


void Foam::pendularResidual::liquidBoundaryFlows
(
    const scalarField& x,
    scalarList& mass,
    scalarList& air,
    scalarList& energy
) const
{
    mass.setSize(fvMesh_.boundary().size());
    air.setSize(fvMesh_.boundary().size());
    energy.setSize(fvMesh_.boundary().size());
    mass = Zero;
    air = Zero;
    energy = Zero;
    const liquidFlow* liquid = medium_.liquidFlowPtr();
    forAll(fvMesh_.boundary(), patchi)
    {
        const fvPatch& patch = fvMesh_.boundary()[patchi];
        if
        (
            !liquid || patch.coupled()
         || liquid->type(patchi) == liquidFlow::patchType::impermeable
        )
        {
            continue;
        }
        forAll(patch, i)
        {
            const label celli = patch.faceCells()[i];
            const cellState c = state(celli, &x[3*celli]);
            const cellState b = boundaryState(patchi, i, c);
            scalar FlE, FaE;
            const scalar Fl =
                liquidBoundaryFlux(patch.start() + i, patchi, i, c, b, FlE);
            mass[patchi] += Fl;
            air[patchi] += dissolvedAirBoundaryFlux(Fl, c, b, FaE);
            energy[patchi] += FlE + FaE;
        }
    }
}


void Foam::pendularResidual::addLiquidFlux
(
    const label facei,
    const cellState& o,
    const cellState& n,
    scalar* F
) const
{
    const liquidFlow* liquid = medium_.liquidFlowPtr();
    if (!liquid)
    {
        return;
    }
    const scalar* corr = snGradCorrections(facei);
    const scalar Fl =
        liquid->faceFlux
        (
            facei,
            liquidState(o),
            liquidState(n),
            corr ? corr[3] : 0,
            deltaCoeffs_[3]
        );
    F[0] += Fl;
    F[2] += Fl*medium_.liquidEnthalpy(Fl >= 0 ? o.T : n.T);
    if (medium_.saturatedZone())
    {
        // The dissolved air, upwind, with the air's enthalpy
        const cellState& up = Fl >= 0 ? o : n;
        F[1] += Fl*up.X;
        F[2] += Fl*up.X*up.hA;
    }
}


// ************************************************************************* //
