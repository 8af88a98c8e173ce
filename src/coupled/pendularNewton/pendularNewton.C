/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "pendularNewton.H"
#include "checkedRead.H"
#include <cmath>
#include <functional>
#include <limits>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::pendularNewton::pendularNewton
(
    const fvMesh& mesh,
    const dictionary& linearDict,
    const scalar TTol,
    const scalar pTol,
    const scalar WTolAbs,
    const scalar dryingFactor,
    const label maxIter,
    const bool verbose,
    const string& linearChosenBy
)
:
    mesh_(mesh),
    system_(mesh, 3, linearDict, linearChosenBy),
    TTol_(TTol),
    pTol_(pTol),
    WTolAbs_(WTolAbs),
    dryingFactor_(dryingFactor),
    maxIter_(maxIter),
    gasSeed_(1e-4),
    hysteresis_(true),
    verbose_(verbose),
    nanResidual_
    (
        "pendularNewtonNaN", nanInjection::pendularNewtonResidual
    ),
    nanLocalWater_
    (
        "pendularNewtonLocalWaterNaN", nanInjection::pendularNewtonLocalWater
    ),
    linearHinted_
    (
        // (LU already in use: no hint to it)
        checkedRead::getChoice
        (
            linearDict, "preconditioner",
            blockSystem::preconditionerTypeNames,
            blockSystem::preconditionerType::bjacobi
        )
     == blockSystem::preconditionerType::lu
    ),
    airGuardsStep_(Zero),
    airGuardsRun_(Zero)
{
    // The unknowns' updates and the residuals are measured in units of
    // the tolerances (divided by them): a tolerance of 0 (or below, or
    // not finite) would divide by zero (SIGFPE at the first iteration).
    // The solvers refuse such values at read (range (0, inf)); a caller
    // that does not is stopped here, before any iteration
    if (!(TTol > 0 && pTol > 0 && WTolAbs > 0) || !std::isfinite(TTol)
     || !std::isfinite(pTol) || !std::isfinite(WTolAbs))
    {
        FatalErrorInFunction
            << "Tolerances TTol = " << TTol << " K, pTol = " << pTol
            << " Pa, WTol (absolute) = " << WTolAbs << " must be finite and"
            << " in (0, inf): the iterations measure their updates and"
            << " residuals in units of them" << exit(FatalError);
    }
    nanResidual_.report
    (
        "pendularNewton: the water residual of the first cell (master)"
    );
    nanLocalWater_.report
    (
        "pendularNewton: the water residual of a local water solve (master)"
    );
    nanInjection::checkNoAirProjection(mesh.time().controlDict());
    if (nanInjection::pendularNewtonNoAirProjection)
    {
        Info<< "OptimisationSwitch pendularNewtonNoAirProjection = "
            << nanInjection::pendularNewtonNoAirProjection
            << ": pendularNewton's iterates not projected onto"
            << " non-negative air"
            << (
                   nanInjection::pendularNewtonNoAirProjection > 1
                 ? ", nor refused for a gas density <= 0" : ""
               )
            << " (test only)" << endl;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::pendularNewton::nonFiniteCells
(
    const scalarField& R,
    const scalarField& sW,
    const scalarField& sG,
    const scalarField& sE
)
{
    // (std::isfinite classifies without an ordered comparison: no trap;
    // a zero scale, e.g. the gas's in a cell whose pores the iterate fills
    // with liquid, would divide by zero, a trap too)
    label n = 0;
    forAll(sW, c)
    {
        if
        (
            !std::isfinite(R[3*c]) || !std::isfinite(R[3*c + 1])
         || !std::isfinite(R[3*c + 2]) || !std::isfinite(sW[c])
         || !std::isfinite(sG[c]) || !std::isfinite(sE[c])
         || sW[c] == 0 || sG[c] == 0 || sE[c] == 0
        )
        {
            ++n;
        }
    }
    reduce(n, sumOp<label>());
    return n;
}


Foam::label Foam::pendularNewton::solveCellWater
(
    const pendularResidual& res,
    const label c,
    const scalar tol,
    scalarField& x,
    const scalarField& xNbr
) const
{
    // g(W) = R_w of cell c with W, the other unknowns fixed: increasing in
    // W (storage and evaporation); bracketed from the iterate (down to a
    // nearly empty cell, up by doubling), then Illinois regula falsi
    // (Dahlquist and Bjorck, 2008, Numerical Methods in Scientific
    // Computing I, ch. 6)
    // A non-finite g (a closure out of its range): x unchanged, -1
    // The gas density rho_g = rho_w + M_a p_a/(R T) decreases as W adds
    // vapour (at fixed T, p_g): with p_a < 0 it crosses zero, where
    // omega = rho_w/rho_g has a pole and g changes sign through it; a
    // bracket across it would converge onto the pole, rho_g = 0 exactly
    // and a division by zero (SIGFPE: tutorials/wetHearthCoupled's
    // hearth_pendSat_1_1e-14 on 200 cells at t = 5220.80 s, T = 441 K,
    // p_g = 2.86 bar below p_w = 7.54 bar). So every trial state's rho_g
    // must be positive (the model's range; checked on the state's cache
    // after the residual): else x unchanged, 0 (no local solve)
    scalar Rc[3];
    bool finite = true;
    bool gasDense = true;
    auto g = [&](const scalar W)
    {
        x[3*c + 2] = W;
        res.cellResidual(c, x, xNbr, Rc);
        if (nanLocalWater_.fire())
        {
            Rc[0] = std::numeric_limits<scalar>::quiet_NaN();
        }
        finite = finite && std::isfinite(Rc[0]);
        gasDense = gasDense && res.state(c, &x[3*c]).rhoG > 0;
        return Rc[0];
    };
    const scalar W0 = x[3*c + 2];
    const scalar g0 = g(W0);
    if (!finite)
    {
        return -1;
    }
    if (mag(g0) < tol || !gasDense)
    {
        return 0;
    }
    scalar a = W0, b = W0, ga = g0, gb = g0;
    if (g0 > 0)
    {
        a = 1e-6*W0;
        ga = g(a);
    }
    else
    {
        for (label k = 0; k < 30 && finite && gb <= 0; ++k)
        {
            b *= 2;
            gb = g(b);
        }
    }
    if (!finite)
    {
        x[3*c + 2] = W0;
        return -1;
    }
    if (!(ga < 0 && gb > 0) || !gasDense)
    {
        x[3*c + 2] = W0;
        return 0;
    }
    label side = 0;
    scalar W = W0;
    for (label k = 0; k < 100; ++k)
    {
        W = (a*gb - b*ga)/(gb - ga);
        const scalar gW = g(W);
        if (!finite)
        {
            x[3*c + 2] = W0;
            return -1;
        }
        if (mag(gW) < tol || b - a < 1e-12*b)
        {
            break;
        }
        if (gW > 0)
        {
            b = W;
            gb = gW;
            if (side == 1)
            {
                ga /= 2;
            }
            side = 1;
        }
        else
        {
            a = W;
            ga = gW;
            if (side == -1)
            {
                gb /= 2;
            }
            side = -1;
        }
    }
    x[3*c + 2] = W;
    return 1;
}


Foam::label Foam::pendularNewton::localWaterSolves
(
    const pendularResidual& res,
    scalarField& x,
    const scalarField& sW,
    label& nNonFinite
) const
{
    const pendularMedium& medium = res.medium();
    const scalarField& phi = medium.porosity().primitiveField();
    const tmp<scalarField> txNbr = res.neighbourStates(x);
    const labelList& phase = res.phases();
    label nLocal = 0;
    nNonFinite = 0;
    for (label c = 0; c < x.size()/3; ++c)
    {
        const scalar Wk = medium.kinkWater(phi[c], x[3*c]);
        if
        (
            phase[c] == pendularResidual::bothPhases
         && Wk > 0 && x[3*c + 2] >= Wk && x[3*c + 2] < nearKink_*Wk
        )
        {
            const label solved =
                solveCellWater(res, c, sW[c]*WTolAbs_, x, txNbr());
            if (solved > 0)
            {
                ++nLocal;
            }
            else if (solved < 0)
            {
                ++nNonFinite;
            }
        }
    }
    reduce(nLocal, sumOp<label>());
    reduce(nNonFinite, sumOp<label>());
    return nLocal;
}


Foam::scalar Foam::pendularNewton::gasRoundOff
(
    const pendularResidual& res,
    const label c,
    const scalarField& x,
    const scalarField& xNbr,
    const scalar sW,
    const scalar sG,
    const scalar pRef
) const
{
    // The storage: S = (a0 M - M^n) V/dt per balance, a0 M V/dt of the
    // water sW W, of the air at most sG p_g (sG p_a); the old storage from
    // their difference with S. The water's terms where the gas residual
    // holds R_w (gasResidual)
    const bool water = withWater(res, c, &x[3*c]);
    scalar S[3];
    res.cellTerm(c, &x[3*c], S);
    const scalar Wnew = sW*x[3*c + 2];
    const scalar Anew = sG*(x[3*c + 1] + pRef);
    scalar sum =
        mag(Anew) + mag(Anew - S[1])
      + (water ? mag(Wnew) + mag(Wnew - S[0]) : 0);

    // The fluxes of its faces (as coupledResidual::cellResidual)
    const labelList& own = res.mesh().faceOwner();
    const labelList& nei = res.mesh().faceNeighbour();
    scalar F[3];
    res.forCellFaces
    (
        c,
        [&](const label facei, const label nbr, const label bFacei)
        {
            if (nbr >= 0)
            {
                res.faceFlux
                (
                    facei, &x[3*own[facei]], &x[3*nei[facei]], F
                );
            }
            else if (bFacei >= 0)
            {
                res.faceFlux(facei, &x[3*c], &xNbr[3*bFacei], F);
            }
            else
            {
                res.boundaryFlux(facei, &x[3*c], F);
            }
            sum += (water ? mag(F[0]) : 0) + mag(F[1]);
        }
    );
    return gasFloorEps_*std::numeric_limits<scalar>::epsilon()*sum;
}


bool Foam::pendularNewton::unknownsRoundOff
(
    const pendularResidual& res,
    const label c,
    scalarField& x,
    scalarField& xNbr,
    const scalar pRef,
    scalar floor[3]
) const
{
    static const scalar eps = std::numeric_limits<scalar>::epsilon();
    static const scalar hRel = Foam::sqrt(eps);
    // The scaled residuals' quantities: water, gas (gasResidual), energy
    auto combine = [&res, c, &x](const scalar* R, scalar* G)
    {
        G[0] = R[0];
        G[1] = gasResidual(res, c, &x[3*c], R);
        G[2] = R[2];
    };
    scalar R0[3], G0[3];
    res.cellResidual(c, x, xNbr, R0);
    combine(R0, G0);
    floor[0] = floor[1] = floor[2] = 0;
    // A residual that is not finite at the iterate or at a perturbed
    // state (a closure out of its range): no floor (tested with
    // std::isfinite before any ordered comparison, which would trap under
    // FOAM_SIGFPE)
    bool finite =
        std::isfinite(G0[0]) && std::isfinite(G0[1]) && std::isfinite(G0[2]);
    if (!finite)
    {
        return false;
    }

    // The unknowns y[0..2] of a cell (in x or in xNbr; celli the cell, or
    // -1 and bFacei across a coupled patch): each perturbed by the
    // Jacobian's step rule (coupledResidual::differenceStep from the
    // forward step sqrt(eps) |y_j|: reversed, towards the dry side, where
    // it would cross S_l = 1 in a two-phase cell, pendularResidual::
    // cellStep), the change of cell c's residual times epsilon |y_j|/|h_j|
    auto addCell = [&](scalar* y, const label celli, const label bFacei)
    {
        for (label j = 0; j < 3; ++j)
        {
            const scalar yj = y[j];
            const scalar magY =
                j == 1 ? max(mag(yj), mag(yj + pRef)) : mag(yj);
            if (magY == 0)
            {
                continue;
            }
            const scalar h =
                res.differenceStep(celli, bFacei, y, j, hRel*magY);
            if (h == 0)
            {
                continue;
            }
            y[j] = yj + h;
            scalar R1[3], G1[3];
            res.cellResidual(c, x, xNbr, R1);
            y[j] = yj;
            combine(R1, G1);
            for (label k = 0; k < 3; ++k)
            {
                finite = finite && std::isfinite(G1[k]);
                if (finite)
                {
                    floor[k] +=
                        gasFloorEps_*mag(G1[k] - G0[k])/mag(h)*eps*magY;
                }
            }
        }
    };
    addCell(&x[3*c], c, -1);
    res.forCellFaces
    (
        c,
        [&](const label, const label nbr, const label bFacei)
        {
            if (nbr >= 0)
            {
                addCell(&x[3*nbr], nbr, -1);
            }
            else if (bFacei >= 0)
            {
                addCell(&xNbr[3*bFacei], -1, bFacei);
            }
        }
    );
    for (label k = 0; k < 3; ++k)
    {
        finite = finite && std::isfinite(floor[k]);
    }
    if (!finite)
    {
        floor[0] = floor[1] = floor[2] = 0;
    }
    return finite;
}


bool Foam::pendularNewton::airLost
(
    const pendularResidual& res,
    const scalarField& x,
    result& out
) const
{
    // (an iterate that passed valid(): rho_g > 0 in every cell with gas,
    // its states cached.) A converged root's p_a = p_g - p_w(T, W) is
    // known to pTol + |dp_w/dT| TTol + |dp_w/dW| WTol (the convergence
    // test bounds the updates of T, p_g and W by their tolerances; p_w up
    // to 3.6 kPa/K at 100 C): refused below minus that, the derivatives by
    // one-sided differences over the tolerances, in the cells below -pTol
    // only
    label n = 0;
    label nBelow = 0;
    scalar paMin = GREAT;
    for (label c = 0; c < x.size()/3; ++c)
    {
        if (res.phases()[c] == pendularResidual::liquidOnly)
        {
            continue;
        }
        const scalar pa = res.state(c, &x[3*c]).pa;
        nBelow += pa < 0;
        if (pa > -pTol_)
        {
            continue;
        }
        const scalar pw = res.state(c, &x[3*c]).pw;
        scalar xc[3] = {x[3*c] + TTol_, x[3*c + 1], x[3*c + 2]};
        const scalar dpwT = mag(res.state(c, xc).pw - pw);
        xc[0] = x[3*c];
        xc[2] += WTolAbs_;
        const scalar dpwW = mag(res.state(c, xc).pw - pw);
        if (pa <= -(pTol_ + dpwT + dpwW))
        {
            ++n;
            paMin = min(paMin, pa);
        }
    }
    reduce(n, sumOp<label>());
    reduce(nBelow, sumOp<label>());
    reduce(paMin, minOp<scalar>());
    out.airLost = n > 0;
    out.nAirBelowZero = nBelow;
    if (n > 0)
    {
        out.category = subStepController::rejection::airLost;
        out.failure =
            "the solution holds less than no air in " + Foam::name(n)
          + " cell(s) with gas (air partial pressure p_g - p_w down to "
          + Foam::name(paMin) + " Pa, below minus its uncertainty pTol +"
            " |dp_w/dT| TTol + |dp_w/dW| WTol: a root outside the model's"
            " range)";
    }
    return n > 0;
}


bool Foam::pendularNewton::fullPores
(
    const pendularResidual& res,
    const scalarField& x,
    result& out
) const
{
    const pendularMedium& medium = res.medium();
    const scalarField& phi = medium.porosity().primitiveField();
    label n = 0;
    for (label c = 0; c < x.size()/3 && !medium.saturatedZone(); ++c)
    {
        if (x[3*c + 2] >= phi[c]*medium.rhoL())
        {
            ++n;
        }
    }
    reduce(n, sumOp<label>());
    if (n > 0)
    {
        out.category = subStepController::rejection::poresFilled;
        out.failure =
            "the solution fills the pores of " + Foam::name(n)
          + " cell(s) with liquid (W >= porosity rho_l, alpha_l = 1: no gas"
            " left; the saturated zone needs the pressure form of the"
            " unknowns, not implemented)";
    }
    return n > 0;
}


bool Foam::pendularNewton::cellValid
(
    const pendularResidual& res,
    const scalarField& x,
    const label c,
    const scalar pRef
)
{
    const scalar T = x[3*c];
    const scalar p = x[3*c + 1] + pRef;
    const scalar W = x[3*c + 2];
    // (liquidOnly: p_l finite, tension allowed; X >= 0; a NaN tested
    // first: an ordered comparison with it traps under FOAM_SIGFPE)
    return
        std::isfinite(T) && std::isfinite(p) && std::isfinite(W)
     && T >= res.medium().minimumTemperature() && T < GREAT
     && (
            res.phases()[c] == pendularResidual::liquidOnly
          ? p > -GREAT : p > 0
        )
     && p < GREAT
     && W >= 0 && W < GREAT;
}


bool Foam::pendularNewton::valid
(
    const pendularResidual& res,
    const scalarField& x,
    const scalar pRef
) const
{
    // Each cell inside the range of its unknowns, and a cell with gas
    // with a positive gas density rho_g = rho_w + M_a p_a/(R T) (the
    // closure's omega = rho_w/rho_g has its pole at rho_g = 0; below it
    // the gas holds less than no air: pendularState::closure). With
    // saturatedZone, whose iterates were not projected onto p_a >= 0
    // before 2026-12-04 (airProjection), Newton passed through such
    // iterates and went on (issue 14). Ending the sub-step there left tutorials/
    // wetHearthCoupled's four saturated-zone runs on 200 cells (written
    // every step) as they were: the same sub-steps and rejections, the
    // fields bit for bit, 11163 -> 11152 Newton iterations (those
    // sub-steps failed later anyway, mostly with an oscillating phase).
    // The projection keeps rho_g > 0 after an update (model A) in the
    // cells it projects (with saturatedZone not those at alpha_l = 1,
    // checked here); the first iterate is checked too. (Test only:
    // pendularNewtonNoAirProjection 2 leaves rho_g <= 0 to airLost; every
    // rank sees the same switch)
    const bool rhoGChecked = nanInjection::pendularNewtonNoAirProjection < 2;
    bool ok = true;
    for (label c = 0; c < x.size()/3 && ok; ++c)
    {
        ok =
            cellValid(res, x, c, pRef)
         && (
                res.phases()[c] == pendularResidual::liquidOnly
             || !rhoGChecked
             || res.state(c, &x[3*c]).rhoG > 0
            );
    }
    reduce(ok, andOp<bool>());
    return ok;
}


Foam::label Foam::pendularNewton::airProjection
(
    const pendularResidual& res,
    scalarField& x,
    const scalar pRef,
    label* nMoved
) const
{
    label n = 0;
    if (nMoved)
    {
        *nMoved = 0;
    }
    if (nanInjection::pendularNewtonNoAirProjection)
    {
        // (test only: every rank sees the same switch)
        return 0;
    }
    // With saturatedZone (since 2026-12-04, issue 14; README.md,
    // pendularFoam, "Air vanishing from the gas") only the two-phase cells
    // with gas room, alpha_l < 1: a bothPhases cell at alpha_l = 1 (pores
    // full, about to turn liquidOnly, held by the switching band) has no
    // gas and no air to project; its p_g carries the liquid's pressure.
    // (Without saturatedZone such a cell is not a root either: fullPores;
    // its iterates are projected as before, bit for bit)
    // valid()'s rho_g check, airLost and pendularFoam's count of cells
    // with p_a < 0 still take such a cell as one with gas. Whether that
    // ever acts was measured (2026-12-04, a debug counter in a scratch
    // build, not kept): on tutorials/wetHearthCoupled's four
    // saturated-zone runs on 100 and 200 cells (with the projection and
    // with pendularNewtonNoAirProjection 1), its saturated pit written
    // every step (tests/pendularGasWithoutAir) and the 22 runs of
    // tests/pendularSaturatedDrying, no such cell had rho_g <= 0 in an
    // iterate, none was counted or refused by airLost, and no written
    // two-phase cell was at alpha_l = 1. The projection skipped one
    // cell once (the flat hearth at K = 1e-16 m2, 200 cells, t = 15379 s:
    // p_a = -21.1 kPa, rho_g = 9.4 kg/m3), in an iterate refused for a
    // neighbour's T < 248.15 K. So the four places are left as they are
    // (README.md, pendularFoam, "Air vanishing from the gas").
    const bool gasRoomOnly = res.medium().saturatedZone();
    for (label c = 0; c < x.size()/3; ++c)
    {
        // (a cell outside the model's range is valid's: its state is not
        // evaluated)
        if
        (
            res.phases()[c] == pendularResidual::liquidOnly
         || !cellValid(res, x, c, pRef)
        )
        {
            continue;
        }
        const pendularResidual::cellState& s = res.state(c, &x[3*c]);
        const scalar pa = s.pa;
        if (!(pa < 0) || (gasRoomOnly && s.alpha >= 1))
        {
            continue;
        }
        // p_g onto p_w(T, W): p_a = 0, not below (up by units of p_w's
        // round-off while x + p_ref rounds below p_w: a few at most. Not
        // by units of x's own: with p_w within round-off of p_ref, x ~ 0
        // and its unit is denormal, a loop without end, measured on the
        // 200-cell pit of tutorials/wetHearthCoupled at alpha_l0 = 0.99)
        const scalar pw = x[3*c + 1] + pRef - pa;
        const scalar ulp = std::nextafter(pw, GREAT) - pw;
        x[3*c + 1] = pw - pRef;
        for (label k = 0; k < 4 && x[3*c + 1] + pRef < pw; ++k)
        {
            x[3*c + 1] += ulp;
        }
        if (-pa >= pTol_)
        {
            ++n;
        }
        if (nMoved)
        {
            ++*nMoved;
        }
    }
    if (nMoved)
    {
        // (the same pointer on every rank: collective as the call)
        reduce(*nMoved, sumOp<label>());
    }
    return returnReduce(n, sumOp<label>());
}


bool Foam::pendularNewton::chordStep
(
    const pendularResidual& res,
    scalarField& x,
    const scalarField& R,
    scalarField& dx,
    const scalar pRef,
    result& out
)
{
    // The system still holds the last Newton step's Jacobian and its
    // factorised preconditioner: only the right-hand side changes
    system_.source() = -R;
    dx = Zero;
    system_.solve(dx, false);
    const pendularMedium& medium = res.medium();
    const scalarField& phi = medium.porosity().primitiveField();
    const label nCells = x.size()/3;
    // Taken only if it leaves every cell's water on its side of the kink
    // and above dryingFactor of its value (no projection, no chop of an
    // update above the water tolerance)
    bool plain =
        system_.failure().empty() && !res.medium().saturatedZone();
    for (label c = 0; c < nCells && plain; ++c)
    {
        const scalar W = x[3*c + 2] + dx[3*c + 2];
        const scalar Wk = medium.kinkWater(phi[c], x[3*c] + dx[3*c]);
        plain =
            std::isfinite(dx[3*c]) && std::isfinite(dx[3*c + 1])
         && std::isfinite(W)
         && (W >= dryingFactor_*x[3*c + 2] || mag(dx[3*c + 2]) < WTolAbs_)
         && !(Wk > 0 && W < Wk && Wk < x[3*c + 2]);
    }
    reduce(plain, andOp<bool>());
    if (!plain)
    {
        return false;
    }
    FixedList<scalar, 3> u(scalar(0));
    for (label c = 0; c < nCells; ++c)
    {
        u[0] = max(u[0], mag(dx[3*c])/TTol_);
        u[1] = max(u[1], mag(dx[3*c + 1])/pTol_);
        u[2] = max(u[2], mag(dx[3*c + 2])/WTolAbs_);
    }
    for (label k = 0; k < 3; ++k)
    {
        reduce(u[k], maxOp<scalar>());
    }
    // The correction itself must be below the tolerances (measured on
    // bench/pendularNewton: at most 1.48 times the largest scaled
    // residual, for the 189 iterates of its backward Euler and BDF2 runs
    // whose scaled residuals were below 1 and whose last update was not)
    if (max(u[0], max(u[1], u[2])) >= 1)
    {
        return false;
    }
    // (a cell's water below dryingFactor of its value only by an update
    // below the tolerance, next to no water: chopped, as in solve)
    const scalarField x0(x);
    for (label c = 0; c < nCells; ++c)
    {
        x[3*c] += dx[3*c];
        x[3*c + 1] += dx[3*c + 1];
        x[3*c + 2] =
            max(x[3*c + 2] + dx[3*c + 2], dryingFactor_*x[3*c + 2]);
    }
    // Nor a cell's air below zero by pTol or more (its projection, as in
    // solve; a projection below pTol is made, as there): the correction
    // moves p_w with T and W, up to dp_w/dT TTol, 3.6 kPa/K at 100 C
    // (0.36 mPa at tutorials/wetHearthCoupled's TTol 1e-7 K, pTol 1e-6
    // Pa). Before, a chord step could end a sub-step at p_a < 0. Measured
    // (2026-12-04): never sent back in any run tried (README.md); the
    // projections it makes are of cells the Newton updates hold at p_a =
    // 0, moved below by round-off (5 to 32 units of p_g's: 128 chord steps
    // of tests/pendularGasWithoutAir's heat pipe, section 6; without them
    // 1502 cells with p_a < 0 in its converged solves)
    if (!valid(res, x, pRef))
    {
        x = x0;
        return false;
    }
    label nAirMoved = 0;
    const label nAirProjected = airProjection(res, x, pRef, &nAirMoved);
    if (nAirProjected > 0)
    {
        ++out.nChordAirGuard;
        if (verbose_)
        {
            Info<< "    Newton " << out.iterations << ": chord step not"
                << " taken, its air projection moves " << nAirProjected
                << " cell(s) by pTol or more" << endl;
        }
        x = x0;
        return false;
    }
    // (valid: x passed valid() above, and a projection by less than pTol
    // only raises p_g onto p_w, which raises rho_g)
    out.nChordAirProjected += nAirMoved > 0;
    out.update = u;
    out.iterations += 1;
    out.valid = true;
    out.converged = true;
    if (verbose_)
    {
        Info<< "    Newton " << out.iterations << ": chord step, update/tol (T "
            << u[0] << ", p " << u[1] << ", W " << u[2] << ")" << endl;
    }
    return true;
}


Foam::label Foam::pendularNewton::frontFirstIterate
(
    const pendularResidual& res,
    scalarField& x,
    const scalarField& Tn,
    const scalarField& Wn,
    const scalarField& rateT,
    const scalarField& rateW,
    const scalar dtLast,
    const scalar dt
) const
{
    const pendularMedium& medium = res.medium();
    const scalarField& phi = medium.porosity().primitiveField();
    const labelList& phase = res.phases();
    const label nCells = x.size()/3;
    const label K = frontHops_;

    // y: per cell (q = W/W_s at the start of the sub-step and q at the
    // start of the last accepted one, -1 where the cell has no kink, and
    // below its hops from the dry side)
    scalarField y(3*nCells, Zero);
    for (label c = 0; c < nCells; ++c)
    {
        const scalar Wk = medium.kinkWater(phi[c], Tn[c]);
        const scalar WkPrev =
            medium.kinkWater(phi[c], Tn[c] - dtLast*rateT[c]);
        const bool kink = phase[c] == pendularResidual::bothPhases && Wk > 0;
        y[3*c] = kink ? Wn[c]/Wk : -1;
        y[3*c + 1] =
            kink && WkPrev > 0 ? (Wn[c] - dtLast*rateW[c])/WkPrev : -1;
    }

    // The hops of each cell from the dry side (q < 1: 0), at most K + 1
    // (Jacobi sweeps, exchanged across the coupled patches); d kept in
    // the third component of y
    for (label c = 0; c < nCells; ++c)
    {
        y[3*c + 2] = y[3*c] >= 0 && y[3*c] < 1 ? 0 : K + 1;
    }
    for (label k = 0; k < K; ++k)
    {
        const tmp<scalarField> tyNbr = res.neighbourStates(y);
        const scalarField& yNbr = tyNbr();
        scalarField d(nCells);
        for (label c = 0; c < nCells; ++c)
        {
            d[c] = y[3*c + 2];
            if (y[3*c] < 0)
            {
                continue;
            }
            res.forCellFaces
            (
                c,
                [&](const label, const label nbr, const label bFacei)
                {
                    const scalar* yn =
                        nbr >= 0 ? &y[3*nbr]
                      : bFacei >= 0 ? &yNbr[3*bFacei] : nullptr;
                    if (yn && yn[0] >= 0)
                    {
                        d[c] = min(d[c], yn[2] + 1);
                    }
                }
            );
        }
        for (label c = 0; c < nCells; ++c)
        {
            y[3*c + 2] = d[c];
        }
    }

    // Each cell's upstream neighbour, the way the front came from: a
    // cell on the dry side, the one with the least q below its own; a
    // wet cell, the one nearer the dry side (the least d below its own,
    // then the least q); an internal cell (up >= 0) or the cell across a
    // coupled boundary face (upFace >= 0)
    labelList up(nCells, -1), upFace(nCells, -1);
    {
        const tmp<scalarField> tyNbr = res.neighbourStates(y);
        const scalarField& yNbr = tyNbr();
        for (label c = 0; c < nCells; ++c)
        {
            if (y[3*c] < 0)
            {
                continue;
            }
            const bool dry = y[3*c + 2] == 0;
            scalar qMin = y[3*c], dMin = y[3*c + 2];
            res.forCellFaces
            (
                c,
                [&](const label, const label nbr, const label bFacei)
                {
                    const scalar* yn =
                        nbr >= 0 ? &y[3*nbr]
                      : bFacei >= 0 ? &yNbr[3*bFacei] : nullptr;
                    if (!yn || yn[0] < 0)
                    {
                        return;
                    }
                    const bool better =
                        dry
                      ? yn[0] < qMin
                      : (
                            yn[2] < dMin
                         || (yn[2] == dMin && up[c] + upFace[c] > -2
                             && yn[0] < qMin)
                        );
                    if (better)
                    {
                        qMin = yn[0];
                        dMin = yn[2];
                        up[c] = nbr;
                        upFace[c] = bFacei;
                    }
                }
            );
        }
    }

    // The chains: visit(k, yk) with yk[3c], yk[3c + 1] the q and the last
    // q of the cell k hops upstream of c (-1: none), k = 0..kMax <= K
    // (Jacobi sweeps, exchanged across the coupled patches at every sweep:
    // independent of the decomposition; no (K + 1) values per cell kept;
    // kMax the same on every rank)
    auto chains =
        [&]
        (
            const label kMax,
            const std::function<void(label, const scalarField&)>& visit
        )
    {
        scalarField yk(y), yNext(3*nCells);
        for (label k = 0; k <= kMax; ++k)
        {
            visit(k, yk);
            if (k == kMax)
            {
                break;
            }
            const tmp<scalarField> tykNbr = res.neighbourStates(yk);
            const scalarField& ykNbr = tykNbr();
            for (label c = 0; c < nCells; ++c)
            {
                const scalar* from =
                    up[c] >= 0 ? &yk[3*up[c]]
                  : upFace[c] >= 0 ? &ykNbr[3*upFace[c]] : nullptr;
                yNext[3*c] = from ? from[0] : -1;
                yNext[3*c + 1] = from ? from[1] : -1;
                yNext[3*c + 2] = 0;
            }
            yk = yNext;
        }
    };

    // The kink's position along each cell's chain [hops], where q crosses
    // 1 (log q linear between hops; the first crossing), at the start of
    // this sub-step (pNow) and of the last one (pLast); -1 if the chain
    // does not cross it within K hops
    scalarField pNow(nCells, -1), pLast(nCells, -1);
    scalarField qBefore(nCells), qpBefore(nCells);
    auto crossing = [](const scalar v0, const scalar v1, const label k)
    {
        const scalar a = Foam::log(v0);
        const scalar b = Foam::log(v1);
        return k + a/(a - b);
    };
    chains
    (
        K,
        [&](const label k, const scalarField& yk)
        {
            for (label c = 0; c < nCells; ++c)
            {
                const scalar qk = yk[3*c], qpk = yk[3*c + 1];
                if (k > 0)
                {
                    if (pNow[c] < 0 && qBefore[c] >= 1 && qk > 0 && qk < 1)
                    {
                        pNow[c] = crossing(qBefore[c], qk, k - 1);
                    }
                    if
                    (
                        pLast[c] < 0 && qpBefore[c] >= 1
                     && qpk > 0 && qpk < 1
                    )
                    {
                        pLast[c] = crossing(qpBefore[c], qpk, k - 1);
                    }
                }
                qBefore[c] = qk;
                qpBefore[c] = qpk;
            }
        }
    );

    // A cell takes the q of the cell S hops upstream, S the hops the
    // kink's position along its chain moved in the last sub-step times
    // dt/dtLast (the front moving at its last pace), interpolated in
    // log q between hops k0 and k0 + 1 (-1: the cell is left alone)
    labelList k0(nCells, -1);
    scalarField f(nCells, Zero), q0(nCells, -1), q1(nCells, -1);
    // (the chains are followed to the largest k0 + 1 only: on
    // bench/pendularNewton's column500_defaults 51 sweeps before, the
    // results bit for bit the same)
    label k0Max = -1;
    for (label c = 0; c < nCells; ++c)
    {
        if (y[3*c] < 0 || pNow[c] < 0 || pLast[c] < 0)
        {
            continue;
        }
        const scalar S = (pLast[c] - pNow[c])*dt/dtLast;
        if (S >= frontMinHops_ && label(S) < K)
        {
            k0[c] = label(S);
            f[c] = S - k0[c];
            k0Max = max(k0Max, k0[c]);
        }
    }
    reduce(k0Max, maxOp<label>());
    chains
    (
        k0Max < 0 ? -1 : k0Max + 1,
        [&](const label k, const scalarField& yk)
        {
            for (label c = 0; c < nCells; ++c)
            {
                if (k == k0[c])
                {
                    q0[c] = yk[3*c];
                }
                else if (k0[c] >= 0 && k == k0[c] + 1)
                {
                    q1[c] = yk[3*c];
                }
            }
        }
    );
    label n = 0;
    for (label c = 0; c < nCells; ++c)
    {
        if (k0[c] < 0 || q0[c] <= 0 || q1[c] <= 0)
        {
            continue;
        }
        const scalar qNew =
            Foam::exp((1 - f[c])*Foam::log(q0[c]) + f[c]*Foam::log(q1[c]));
        const scalar Wk = medium.kinkWater(phi[c], x[3*c]);
        if (Wk > 0 && min(y[3*c], qNew) < frontWindow_)
        {
            x[3*c + 2] = qNew*Wk;
            ++n;
        }
    }
    reduce(n, sumOp<label>());
    if (verbose_)
    {
        Info<< "    Newton: first iterate of " << n << " cell(s) near a"
            << " drying front from the front's last pace" << endl;
    }
    return n;
}


Foam::pendularNewton::result Foam::pendularNewton::solve
(
    pendularResidual& res,
    scalarField& x,
    const scalar pRef,
    const bool limitChopRuns
)
{
    const result r = iterate(res, x, pRef, limitChopRuns);
    airGuardsStep_[0] += r.airLost;
    airGuardsStep_[1] += r.nAirProjected;
    airGuardsStep_[2] += r.nChordAirGuard;
    airGuardsStep_[3] += r.nChordAirProjected;
    airGuardsStep_[4] += r.converged ? r.nAirBelowZero : 0;
    return r;
}


void Foam::pendularNewton::report(const result& r) const
{
    // A sub-step accepted with a scaled residual above 1 as judged
    // (the round-off floor or stall acceptance: updates 100 times below
    // their tolerances)
    const bool acceptedAboveTolerance =
        r.converged
     && max(r.judged[0], max(r.judged[1], r.judged[2])) >= 1;
    // A gas residual judged against its round-off floor where that is
    // above its tolerance (gasRoundOff: cells whose pores are nearly full
    // of liquid), the gas residual then in units of the larger of the two
    const bool gasFloor = r.converged && r.nGasFloor > 0;
    // liquidOnly cells accepted within the round-off floor of their
    // unknowns (unknownsRoundOff), above their tolerances, with the
    // largest floor; the residuals stay in units of the tolerances
    const bool unknownsFloor = r.converged && r.nUnknownsFloor > 0;
    if
    (
        verbose_ || (!r.converged && r.valid) || acceptedAboveTolerance
     || gasFloor || unknownsFloor
    )
    {
        Info<< "    Newton: " << r.iterations << " iterations, "
            << (
                   r.converged
                 ? (
                       acceptedAboveTolerance
                     ? "converged at the residuals' round-off floor"
                       " (updates below 1e-2 of their tolerances)"
                     : "converged"
                   )
                 : "not converged"
               );
        if (gasFloor)
        {
            Info<< ", the gas residual of " << r.nGasFloor << " cell(s) at"
                << " its round-off floor (10 epsilon times the sum of its"
                << " terms, above pTol)";
        }
        if (unknownsFloor)
        {
            Info<< ", the residuals of " << r.nUnknownsFloor << " liquid-"
                << "only cell(s) within the round-off floor of their"
                << " unknowns (10 epsilon sum |dR/dx| |x|, up to "
                << r.unknownsFloorMax << " tolerances)";
        }
        Info<< "; residual/tolerance water " << r.residual[0] << ", gas "
            << r.residual[1] << ", energy " << r.residual[2] << endl;
    }
}


Foam::string Foam::pendularNewton::endStep()
{
    forAll(airGuardsRun_, k)
    {
        airGuardsRun_[k] += airGuardsStep_[k];
    }
    return
        ", refused for less than no air = " + Foam::name(airGuardsStep_[0])
      + ", air projections = " + Foam::name(airGuardsStep_[1]);
}


void Foam::pendularNewton::writeAirGuards(Ostream& os) const
{
    os  << "Air guards of the Newton engine since the start of this run: "
        << airGuardsRun_[0] << " sub-steps refused for less than no air"
        << " (airLost), " << airGuardsRun_[1] << " cell projections onto"
        << " p_a >= 0 by pTol or more; chord steps: " << airGuardsRun_[2]
        << " sent back by their air projection, " << airGuardsRun_[3]
        << " taken with cells projected by less than pTol; "
        << airGuardsRun_[4] << " cells with p_a < 0 in converged solves"
        << " (within airLost's uncertainty)" << nl;
}


Foam::pendularNewton::result Foam::pendularNewton::iterate
(
    pendularResidual& res,
    scalarField& x,
    const scalar pRef,
    const bool limitChopRuns
)
{
    result out;
    out.nGasFloor = 0;
    out.nUnknownsFloor = 0;
    out.iterations = 0;
    out.converged = false;
    out.valid = valid(res, x, pRef);
    out.residual = GREAT;
    out.judged = GREAT;
    out.update = GREAT;
    out.unknownsFloorMax = 0;
    out.nAirProjected = 0;
    out.nChordAirGuard = 0;
    out.nChordAirProjected = 0;
    out.nAirBelowZero = 0;
    out.airLost = false;
    out.category = subStepController::rejection::notConverged;
    if (!out.valid)
    {
        return out;
    }

    const label nCells = x.size()/3;
    scalarField sW, sG, sE;
    scalarField dx(x.size());
    label nChopped = 0;
    label nProjected = 0;
    // Consecutive iterations whose update chopped the water of a cell
    // (limitChopRuns)
    label chopRun = 0;
    const pendularMedium& medium = res.medium();
    const scalarField& phi = medium.porosity().primitiveField();

    // Phase switching (saturatedZone): the cells whose criterion was
    // violated at the last pass (switched, or held by the band: the band
    // holds while they stay in it), the switches of each cell in this
    // solve; a first pass on the first iterate, with the band for every
    // cell: the first iterate is the last accepted sub-step's state, in
    // which a cell held by the band at its last pass stays held (a
    // converged solve ends with a pass that switched nothing: each cell
    // consistent, or inside its band). Without it such a cell was switched
    // at the first pass of the next sub-step, across the band, and
    // oscillated (issue 14: the bubble-point start on 80 cells of
    // bench/pendularSaturatedFine)
    const bool switching = medium.saturatedZone();
    boolList heldLast(nCells, true), switchedNow, heldNow;
    labelList nSwitches(nCells, Zero);
    // (every rank calls it: collective)
    auto switchPass = [&]()
    {
        label nSwitched =
            res.switchPhases
            (
                x, heldLast, switchedNow, heldNow, gasSeed_, hysteresis_
            );
        label nOscillating = 0;
        forAll(switchedNow, c)
        {
            if (switchedNow[c] && ++nSwitches[c] > maxSwitches_)
            {
                ++nOscillating;
            }
        }
        heldLast = heldNow;
        reduce(nSwitched, sumOp<label>());
        reduce(nOscillating, sumOp<label>());
        if (nOscillating > 0)
        {
            out.category = subStepController::rejection::phaseOscillation;
            out.failure =
                "the phase state oscillates in " + Foam::name(nOscillating)
              + " cell(s) (more than " + Foam::name(maxSwitches_)
              + " switches in one sub-step)";
        }
        if (verbose_ && nSwitched > 0)
        {
            Info<< "    Newton: " << nSwitched << " phase switch(es)"
                << endl;
        }
        return nSwitched;
    };
    label nSwitchedLast = 0;
    if (switching)
    {
        nSwitchedLast = switchPass();
        if (!(out.valid = valid(res, x, pRef)))
        {
            return out;
        }
    }

    scalarField R(x.size());
    // The last two updates (in units of the tolerances)
    FixedList<scalar, 3> uPrev(GREAT);
    label nModifiedPrev = 1;
    // The first iterate's largest scaled residual (divergence test)
    scalar rFirst = GREAT;
    // The last iterate's (stall test)
    scalar rPrev = 0;
    // Linear solves stopped short of their tolerance in this solve
    label nShort = 0;
    // (blockSystem's forcing eisenstatWalker, if set: the inexact Newton
    // forcing term restarts from its largest value)
    system_.resetForcing();
    for (label iter = 0; ; ++iter)
    {
        // The residual; its Jacobian only if the iterations go on (the
        // converged iterate of a sub-step needs none: on the column of
        // tests/pendularNewton 1688 Jacobians of 6271 are not assembled,
        // no CPU saving measurable on a loaded machine, 2.24 s and 2.35 s;
        // the states of the cells at x are cached for it). An iterate that
        // cannot end the sub-step, the first or one whose update chopped,
        // projected, solved locally or switched cells (the acceptance
        // tests and the chord step below all require none), gets its
        // Jacobian with its residual (coupledResidual::jacobian returns
        // R(x) from the same evaluation, bit for bit): the residual is not
        // evaluated twice at the same x (issue 13; bench/pendularNewton's
        // column500_newton: 1029 of its 1147 Jacobians; results
        // bit for bit those of the two calls). Not at maxIter_ (no step
        // follows); an iterate that then fails (non-finite residual,
        // divergence) has cost one assembly for nothing
        const bool jacobianNow =
            iter < maxIter_ && (iter == 0 || nChopped + nProjected > 0);
        if (jacobianNow)
        {
            R = res.jacobian(x, system_);
        }
        else
        {
            res.residual(x, R);
        }
        if (nanResidual_.fire() && R.size())
        {
            R[0] = std::numeric_limits<scalar>::quiet_NaN();
        }

        // Residuals in units of the tolerances through the storage
        res.scales(x, sW, sG, sE);

        // A NaN or an infinity in a residual or a scale (a closure out of
        // its range, an overflow), or a zero scale: a failed iteration,
        // before any comparison (which would trap under FOAM_SIGFPE); the
        // sub-step ends unconverged at the last iterate, to be retried
        // shorter
        const label nNonFinite = nonFiniteCells(R, sW, sG, sE);
        if (nNonFinite > 0)
        {
            out.category = subStepController::rejection::nonFinite;
            out.failure =
                "a non-finite residual (NaN or infinity) or a zero scale in "
              + Foam::name(nNonFinite) + " cell(s) at Newton iteration "
              + Foam::name(iter);
            out.iterations = iter;
            if (verbose_)
            {
                Info<< "    Newton " << iter << ": " << out.failure.c_str()
                    << endl;
            }
            return out;
        }
        FixedList<scalar, 3> r(scalar(0));
        for (label c = 0; c < nCells; ++c)
        {
            const scalar Rg = gasResidual(res, c, &x[3*c], &R[3*c]);
            r[0] = max(r[0], mag(R[3*c])/(sW[c]*WTolAbs_));
            r[1] = max(r[1], mag(Rg)/(sG[c]*pTol_));
            r[2] = max(r[2], mag(R[3*c + 2])/(sE[c]*TTol_));
        }
        for (label k = 0; k < 3; ++k)
        {
            reduce(r[k], maxOp<scalar>());
        }
        out.iterations = iter;

        // The gas residual of a cell whose pores are nearly full of liquid
        // (tutorials/wetHearthCoupled, alpha_l0 >= 0.9): its tolerance,
        // pTol of air, V phi (1 - alpha) M_a pTol/(R T dt), falls with
        // 1 - alpha below the round-off of its terms: measured there, with
        // the gas residual R_w + R_a (whose largest term is the stored
        // water, V W/dt), 0.1 to 4.3 times epsilon times the sum of their
        // magnitudes for 30 iterations, updates 1e-5 tolerances. Judged
        // against the floor of its terms (gasRoundOff: the air's, and the
        // water's where it holds R_w) where it is higher, once the water
        // and the energy are converged (the floor costs one flux
        // evaluation per face of those cells)
        out.nGasFloor = 0;
        scalarField gasFloor;
        if (r[0] < 1 && r[2] < 1 && r[1] >= 1)
        {
            gasFloor.setSize(nCells, Zero);
            const tmp<scalarField> txNbr = res.neighbourStates(x);
            scalar rGas = 0;
            for (label c = 0; c < nCells; ++c)
            {
                const bool liquidOnly =
                    res.phases()[c] == pendularResidual::liquidOnly;
                const scalar Rg = mag(gasResidual(res, c, &x[3*c], &R[3*c]));
                const scalar tol = sG[c]*pTol_;
                if (Rg < tol || liquidOnly)
                {
                    rGas = max(rGas, Rg/tol);
                    continue;
                }
                const scalar floor =
                    gasRoundOff(res, c, x, txNbr(), sW[c], sG[c], pRef);
                gasFloor[c] = floor;
                if (Rg < floor)
                {
                    ++out.nGasFloor;
                }
                rGas = max(rGas, Rg/max(tol, floor));
            }
            reduce(rGas, maxOp<scalar>());
            reduce(out.nGasFloor, sumOp<label>());
            r[1] = rGas;
        }

        // The round-off of the unknowns (issue 14): the liquid's Darcy
        // flux takes the difference of two absolute pressures (~1e5 Pa, one
        // unit of round-off 1.5e-11 Pa) over the distance of the cells'
        // centres, so a cell's residuals cannot be brought below epsilon
        // |dR/dp| |p| however exact Newton's step; that floor grows as the
        // cells shrink (as 1/dx^2 against a tolerance through the storage,
        // times dt). Measured on the graded 40-cell column of
        // bench/pendularSaturatedFine (30 um top cell, dt ~ 1 s): one unit
        // of round-off of the absolute p of a liquidOnly top cell changes
        // its water residual by 70-220 tolerances, and the residual
        // stalled at 36-87 tolerances (updates 1e-3 to 2e-2 tolerances)
        // until maxIter. Once the last update is below the tolerances, a
        // liquidOnly cell with a residual above its tolerance whose every
        // such residual is below its floor (unknownsRoundOff: 10 epsilon,
        // gasRoundOff's factor; Kelley, 1995, Iterative Methods for Linear
        // and Nonlinear Equations, ch. 5: Newton's iterates stagnate at
        // the error of the residual's evaluation) is accepted on it: it
        // enters the acceptance tests below at its residual over its floor
        // (below 1), so floorFactor_ and stallFactor_ never multiply the
        // floor. A cell above its floor, or whose floor is above
        // maxUnknownsFloor_ tolerances, is judged against its tolerance as
        // any cell. Only liquidOnly cells (the cells of the measured
        // stalls: p_l with k_rl = 1 and a nearly incompressible storage;
        // for every cell, tests/pendularWaterTable's hydrostatic_open
        // balance reached 1.5e-10, above its 1e-10). out.residual stays in
        // units of the tolerances; out.judged is what the tests below see
        out.nUnknownsFloor = 0;
        out.unknownsFloorMax = 0;
        FixedList<scalar, 3> judged(r);
        if
        (
            switching && iter > 0 && max(r[0], max(r[1], r[2])) >= 1
         && max(out.update[0], max(out.update[1], out.update[2])) < 1
        )
        {
            scalarField xNbr(res.neighbourStates(x));
            FixedList<scalar, 3> rf(scalar(0));
            for (label c = 0; c < nCells; ++c)
            {
                const bool liquidOnly =
                    res.phases()[c] == pendularResidual::liquidOnly;
                const scalar Rc[3] =
                {
                    mag(R[3*c]),
                    mag(gasResidual(res, c, &x[3*c], &R[3*c])),
                    mag(R[3*c + 2])
                };
                scalar tol[3] =
                {
                    sW[c]*WTolAbs_, sG[c]*pTol_, sE[c]*TTol_
                };
                if (gasFloor.size())
                {
                    tol[1] = max(tol[1], gasFloor[c]);
                }
                scalar scale[3] = {tol[0], tol[1], tol[2]};
                if
                (
                    liquidOnly
                 && (Rc[0] >= tol[0] || Rc[1] >= tol[1] || Rc[2] >= tol[2])
                )
                {
                    scalar floor[3];
                    // (a non-finite residual at a perturbed state: no
                    // floor)
                    bool atFloor =
                        unknownsRoundOff(res, c, x, xNbr, pRef, floor);
                    scalar floorTol = 0;
                    for (label k = 0; k < 3 && atFloor; ++k)
                    {
                        if (Rc[k] >= tol[k])
                        {
                            atFloor =
                                Rc[k] < floor[k]
                             && floor[k] <= maxUnknownsFloor_*tol[k];
                            floorTol = max(floorTol, floor[k]/tol[k]);
                        }
                    }
                    if (atFloor)
                    {
                        ++out.nUnknownsFloor;
                        out.unknownsFloorMax =
                            max(out.unknownsFloorMax, floorTol);
                        for (label k = 0; k < 3; ++k)
                        {
                            scale[k] = max(tol[k], floor[k]);
                        }
                    }
                }
                for (label k = 0; k < 3; ++k)
                {
                    rf[k] = max(rf[k], Rc[k]/scale[k]);
                }
            }
            for (label k = 0; k < 3; ++k)
            {
                reduce(rf[k], maxOp<scalar>());
            }
            reduce(out.nUnknownsFloor, sumOp<label>());
            reduce(out.unknownsFloorMax, maxOp<scalar>());
            judged = rf;
        }
        out.residual = r;
        out.judged = judged;

        if (verbose_)
        {
            Info<< "    Newton " << iter << ": residual/tol (water "
                << r[0] << ", gas " << r[1] << ", energy " << r[2]
                << "), update/tol (T " << out.update[0] << ", p "
                << out.update[1] << ", W " << out.update[2] << "), chopped "
                << nChopped << ", projected " << nProjected;
            if (out.nGasFloor)
            {
                Info<< ", gas at its round-off floor in " << out.nGasFloor
                    << " cells";
            }
            if (out.nUnknownsFloor)
            {
                Info<< ", " << out.nUnknownsFloor << " liquid-only cells"
                    << " within the unknowns' round-off floor (up to "
                    << out.unknownsFloorMax << " tolerances; judged: water "
                    << judged[0] << ", gas " << judged[1] << ", energy "
                    << judged[2] << ")";
            }
            Info<< endl;
        }

        // Converged: residuals and update below the tolerances; or the
        // round-off floor of the residuals reached (measured up to 1.6
        // times the water tolerance with WTol 1e-11: the balances' terms
        // cancel to 1e-16 of the stored water) with an update 100 times
        // below the tolerances, whose error the Newton step estimates
        const scalar rMax = max(judged[0], max(judged[1], judged[2]));
        const scalar uMax =
            max(out.update[0], max(out.update[1], out.update[2]));
        // The error of the iterate estimated from the contraction of the
        // last two updates (quadratic phase: |dx_{k+1}| ~ |dx_k|^2/|dx_{k-1}|,
        // Deuflhard, 2004, ch. 2)
        scalar eMax = 0;
        for (label k = 0; k < 3; ++k)
        {
            // (no previous update of that kind, e.g. no two-phase cell's
            // water: no estimate; the quotient would overflow)
            eMax =
                max
                (
                    eMax,
                    uPrev[k] > 0 || out.update[k] <= 0
                  ? sqr(out.update[k])/max(uPrev[k], VSMALL)
                  : GREAT
                );
        }
        if
        (
            iter > 0 && nChopped == 0 && nProjected == 0
         && (
                (rMax < 1 && uMax < 1)
             || (rMax < floorFactor_ && uMax < 1e-2)
             || (
                    rMax < stallFactor_ && rMax > 0.5*rPrev && uMax < 1e-2
                 && max(uPrev[0], max(uPrev[1], uPrev[2])) < 1e-2
                )
             || (iter > 1 && nModifiedPrev == 0 && rMax < 1 && eMax < 1)
            )
        )
        {
            out.converged =
                !fullPores(res, x, out) && !airLost(res, x, out);
            return out;
        }
        if
        (
            iter > 0 && nChopped == 0 && nProjected == 0
         && rMax < 1 && chordStep(res, x, R, dx, pRef, out)
        )
        {
            out.converged =
                out.converged && !fullPores(res, x, out)
             && !airLost(res, x, out);
            return out;
        }
        rPrev = rMax;
        if (iter == 0 || nSwitchedLast > 0)
        {
            // (after a phase switch the reference restarts: a cell the
            // gas appears in has a gas capacity 1 - alpha of its seed, at
            // most gasSeed, its scaled gas residual jumps by orders of
            // magnitude)
            rFirst = rMax;
        }
        else if (rMax > divergenceFactor_*max(rFirst, scalar(1)))
        {
            out.category = subStepController::rejection::diverged;
            out.failure =
                "the Newton iterations diverged: largest scaled residual "
              + Foam::name(rMax) + " tolerances > "
              + Foam::name(divergenceFactor_) + " times the first iterate's "
              + Foam::name(rFirst) + " (or one tolerance)";
            return out;
        }
        if (iter == maxIter_)
        {
            return out;
        }

        // The Newton step (its Jacobian assembled above if jacobianNow)
        if (!jacobianNow)
        {
            res.jacobian(x, system_);
        }
        dx = Zero;
        // (a step short of the linear tolerance, e.g. at the round-off
        // floor near convergence, is still a descent step: the
        // convergence test above judges the iterate, not the step)
        const solverPerformance perf = system_.solve(dx, false);
        if (!system_.failure().empty())
        {
            // No Newton step: the sub-step ends unconverged at the last
            // iterate (still valid), to be rejected and retried shorter
            out.category = subStepController::rejection::linearSolveFailed;
            out.failure =
                "the linear solve of a Newton step broke down: "
              + system_.failure();
            out.iterations = iter + 1;
            if (verbose_)
            {
                Info<< "    Newton " << iter << ": "
                    << out.failure.c_str() << endl;
            }
            return out;
        }
        if (verbose_ && !perf.converged())
        {
            Info<< "    Newton " << iter << ": linear solver stopped at "
                << perf.finalResidual() << " after " << perf.nIterations()
                << " iterations" << endl;
        }
        // Newton slowed by inexact steps: said once (the solve's outcome,
        // the same on every rank)
        nShort += !perf.converged();
        if
        (
            !linearHinted_ && iter + 1 >= slowIterations_
         && 2*nShort > iter + 1
        )
        {
            linearHinted_ = true;
            Info<< "pendularNewton: " << nShort << " of " << iter + 1
                << " linear solves of this sub-step's Newton steps stopped"
                << " short of their tolerance (the last at "
                << perf.finalResidual() << " after " << perf.nIterations()
                << " iterations): inexact steps slow Newton down. Set a"
                << " stronger linear solver in system/fvSolution, e.g."
                << " coupled { preconditioner lu; } (MUMPS on a decomposed"
                << " mesh, where block Jacobi loses the coupling across"
                << " the processor boundaries), or coupled { diagonalScale"
                << " true; } (the balances' rows of one scale for relTol; not"
                << " with cpr);"
                << " said once" << endl;
        }

        FixedList<scalar, 3> u(scalar(0));
        nModifiedPrev = nChopped + nProjected;
        nChopped = 0;
        nProjected = 0;
        for (label c = 0; c < nCells; ++c)
        {
            u[0] = max(u[0], mag(dx[3*c])/TTol_);
            u[1] = max(u[1], mag(dx[3*c + 1])/pTol_);
            x[3*c] += dx[3*c];
            x[3*c + 1] += dx[3*c + 1];
            if (res.phases()[c] == pendularResidual::liquidOnly)
            {
                // The dissolved air: its tolerance the Henry equivalent
                // of pTol on p_a; chopped as the water
                const scalar XTol = medium.dissolvedAir(pTol_, x[3*c]);
                u[1] = max(u[1], mag(dx[3*c + 2])/XTol);
                const scalar X = x[3*c + 2] + dx[3*c + 2];
                if (X < dryingFactor_*x[3*c + 2])
                {
                    if (mag(dx[3*c + 2]) >= XTol)
                    {
                        ++nChopped;
                    }
                    x[3*c + 2] *= dryingFactor_;
                }
                else
                {
                    x[3*c + 2] = X;
                }
                continue;
            }
            u[2] = max(u[2], mag(dx[3*c + 2])/WTolAbs_);
            const scalar W = x[3*c + 2] + dx[3*c + 2];
            // A wet cell's step across its kink (at the new T): to the
            // kink
            const scalar Wk = medium.kinkWater(phi[c], x[3*c]);
            if (Wk > 0 && W < Wk && Wk < x[3*c + 2])
            {
                ++nProjected;
                x[3*c + 2] = Wk;
            }
            else if (W < dryingFactor_*x[3*c + 2])
            {
                // Counted only for an update above the water tolerance: a
                // cell with next to no water (dry soil the vapour has not
                // reached) and a round-off update moves by (1 - f) W_k <
                // |dW| < WTolAbs; counted, such cells kept every sub-step
                // from converging (tests/pendularSemiPermeable: 100
                // sub-steps rejected at maxIter, residuals and updates
                // below 1e-3 tolerances)
                if (mag(dx[3*c + 2]) >= WTolAbs_)
                {
                    ++nChopped;
                }
                x[3*c + 2] *= dryingFactor_;
            }
            else
            {
                x[3*c + 2] = W;
            }
        }
        for (label k = 0; k < 3; ++k)
        {
            reduce(u[k], maxOp<scalar>());
        }
        reduce(nChopped, sumOp<label>());
        reduce(nProjected, sumOp<label>());
        uPrev = out.update;
        out.update = u;

        // Chopped at every iteration (limitChopRuns): the water balance
        // of those cells has no root W >= 0 within reach (nChopped is
        // reduced: every rank returns together)
        chopRun = nChopped > 0 ? chopRun + 1 : 0;
        if (limitChopRuns && chopRun >= maxChopRun_)
        {
            out.category = subStepController::rejection::noWaterRoot;
            out.failure =
                "the water of " + Foam::name(nChopped) + " cell(s) chopped"
                " (an update below dryingFactor of its value) in "
              + Foam::name(chopRun) + " consecutive Newton iterations: no"
                " root W >= 0 of their water balance in reach";
            out.iterations = iter + 1;
            out.valid = valid(res, x, pRef);
            if (verbose_)
            {
                Info<< "    Newton " << iter << ": " << out.failure.c_str()
                    << endl;
            }
            return out;
        }

        // The water of the cells at the kink or near it (the drying
        // front) from their own water balances
        label nLocalNonFinite = 0;
        nProjected += localWaterSolves(res, x, sW, nLocalNonFinite);
        if (nLocalNonFinite > 0)
        {
            out.category = subStepController::rejection::nonFinite;
            out.failure =
                "a non-finite water residual (NaN or infinity) in the local"
                " water solve of " + Foam::name(nLocalNonFinite)
              + " cell(s) at Newton iteration " + Foam::name(iter);
            out.iterations = iter + 1;
            out.valid = valid(res, x, pRef);
            return out;
        }

        // The air of the cells with gas kept non-negative (issue 14): p_g
        // projected onto p_w where the update took it below
        const label nAirProjected = airProjection(res, x, pRef);
        nProjected += nAirProjected;
        out.nAirProjected += nAirProjected;

        // The phase states from the new iterate: a switch is not a
        // converged iteration
        if (switching)
        {
            nSwitchedLast = switchPass();
            nProjected += nSwitchedLast;
            if (!out.failure.empty())
            {
                out.iterations = iter + 1;
                out.valid = valid(res, x, pRef);
                return out;
            }
        }

        if (!(out.valid = valid(res, x, pRef)))
        {
            out.iterations = iter + 1;
            return out;
        }
    }
}


// ************************************************************************* //
