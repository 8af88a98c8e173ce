/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "richardsNewton.H"
#include <cmath>
#include <limits>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::richardsNewton::richardsNewton
(
    const fvMesh& mesh,
    const dictionary& linearDict,
    const scalar STol,
    const scalar dryingFactor,
    const label maxIter
)
:
    system_(mesh, 1, linearDict),
    STol_(STol),
    dryingFactor_(dryingFactor),
    maxIter_(maxIter),
    nanResidual_("richardsNewtonNaN", nanInjection::richardsNewtonResidual)
{
    if (!(STol > 0 && dryingFactor > 0 && dryingFactor < 1 && maxIter > 0))
    {
        FatalErrorInFunction
            << "STol = " << STol << " (> 0), dryingFactor = " << dryingFactor
            << " ((0, 1)), maxIter = " << maxIter << " (> 0)"
            << exit(FatalError);
    }
    nanResidual_.report
    (
        "richardsNewton: the residual of the first cell (master)"
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::richardsNewton::result Foam::richardsNewton::solve
(
    const richardsResidual& res,
    scalarField& S
)
{
    result out{0, false, GREAT, GREAT};
    const scalar Swr = res.minSaturation();
    scalarField R(S.size()), dS(S.size());
    label nChopped = 0;
    for (label iter = 0; ; ++iter)
    {
        res.residual(S, R);
        if (nanResidual_.fire() && R.size())
        {
            R[0] = std::numeric_limits<scalar>::quiet_NaN();
        }
        // A NaN or an infinity in a residual (on any rank): unconverged,
        // before any comparison (which would trap under FOAM_SIGFPE)
        if (!blockSystem::allFinite(R))
        {
            out.iterations = iter;
            return out;
        }
        scalar r = 0;
        forAll(R, c)
        {
            r = max(r, mag(R[c])/res.storage(c));
        }
        reduce(r, maxOp<scalar>());
        out.residual = r/STol_;
        out.iterations = iter;
        if
        (
            iter > 0 && nChopped == 0
         && (
                (out.residual < 1 && out.update < 1)
             || (out.residual < floorFactor_ && out.update < 1e-2)
            )
        )
        {
            out.converged = true;
            return out;
        }
        if (iter == maxIter_ || !std::isfinite(r))
        {
            return out;
        }

        res.jacobian(S, system_);
        dS = Zero;
        system_.solve(dS, false);
        if (!system_.failure().empty())
        {
            // No Newton step (e.g. a failed factorisation): unconverged
            out.iterations = iter + 1;
            return out;
        }

        scalar u = 0;
        nChopped = 0;
        forAll(S, c)
        {
            u = max(u, mag(dS[c]));
            const scalar Sn = S[c] + dS[c];
            if (!(Sn > Swr))
            {
                ++nChopped;
                S[c] = Swr + dryingFactor_*(S[c] - Swr);
            }
            else
            {
                S[c] = min(Sn, scalar(1));
            }
        }
        reduce(u, maxOp<scalar>());
        reduce(nChopped, sumOp<label>());
        out.update = u/STol_;
    }
}


// ************************************************************************* //
