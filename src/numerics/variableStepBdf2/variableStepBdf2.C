/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "variableStepBdf2.H"
#include "PstreamReduceOps.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::scalar Foam::variableStepBdf2::maxStepRatio = 1 + Foam::sqrt(2.0);


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::variableStepBdf2::variableStepBdf2
(
    const label nBlock,
    const label component,
    const scalarField& totals
)
:
    nBlock_(nBlock),
    component_(component),
    dt1_(0),
    dt2_(0),
    nAccepted_(0),
    nReduced_(0),
    x1_(),
    x2_(),
    total_(totals),
    change_(totals.size(), Zero),
    correction_(totals.size(), Zero)
{
    if (nBlock < 1 || component < 0 || component >= nBlock)
    {
        FatalErrorInFunction
            << "component " << component << " of " << nBlock
            << " unknowns per cell" << abort(FatalError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::variableStepBdf2::omega(const scalar dt) const
{
    return nAccepted_ > 0 ? dt/dt1_ : 0;
}


Foam::variableStepBdf2::coefficients
Foam::variableStepBdf2::coeffs(const scalar dt) const
{
    const scalar w = order() == 2 ? omega(dt) : 0;
    return coefficients{(1 + 2*w)/(1 + w), 1 + w, sqr(w)/(1 + w)};
}


Foam::scalar Foam::variableStepBdf2::error
(
    const scalarField& x,
    const scalarField& xn,
    const scalar dt,
    const label order
) const
{
    if (order == 1)
    {
        if (nAccepted_ < 1)
        {
            return -1;
        }
        // |le| = h^2/2 |x''|, x'' = 2 f[t_n+1, t_n, t_n-1]
        const scalar h = dt, k1 = dt1_;
        scalar err = 0;
        for (label i = component_; i < x.size(); i += nBlock_)
        {
            const scalar f01 = (x[i] - xn[i])/h;
            const scalar f12 = (xn[i] - x1_[i])/k1;
            err = max(err, sqr(h)*mag((f01 - f12)/(h + k1)));
        }
        return returnReduce(err, maxOp<scalar>());
    }
    if (nAccepted_ < 2)
    {
        return -1;
    }
    const scalar h = dt, k1 = dt1_, k2 = dt2_;
    const scalar w = h/k1;
    // |le| = (1 + w)^2/(6 w (1 + 2 w)) h^3 |x'''|, x''' = 6 f[t_n+1..t_n-2]
    const scalar C = sqr(1 + w)/(w*(1 + 2*w))*pow3(h);
    scalar err = 0;
    for (label i = component_; i < x.size(); i += nBlock_)
    {
        const scalar f01 = (x[i] - xn[i])/h;
        const scalar f12 = (xn[i] - x1_[i])/k1;
        const scalar f23 = (x1_[i] - x2_[i])/k2;
        const scalar f3 =
            ((f01 - f12)/(h + k1) - (f12 - f23)/(k1 + k2))/(h + k1 + k2);
        err = max(err, C*mag(f3));
    }
    return returnReduce(err, maxOp<scalar>());
}


Foam::scalar Foam::variableStepBdf2::stepFactor
(
    const scalar err,
    const scalar tol,
    const scalar growth
)
{
    if (err < 0)
    {
        return growth;
    }
    return min(growth, max(0.2, 0.9*cbrt(tol/max(err, VSMALL))));
}


void Foam::variableStepBdf2::accept
(
    const scalarField& xn,
    const scalar dt,
    const scalarField& totals,
    const scalarField& excluded
)
{
    // The balance correction c_n of this step (0 for backward Euler)
    const scalar w = order() == 2 ? omega(dt) : 0;
    forAll(total_, k)
    {
        const scalar dM = totals[k] - total_[k];
        correction_[k] +=
            w/(1 + w)*(dM - w*change_[k])
          - (excluded.size() ? excluded[k] : 0);
        change_[k] = dM;
        total_[k] = totals[k];
    }

    x2_.transfer(x1_);
    x1_ = xn;
    dt2_ = dt1_;
    dt1_ = dt;
    nAccepted_ = min(nAccepted_ + 1, 2);
    nReduced_ = max(nReduced_ - 1, 0);
}


// ************************************************************************* //
