/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "andersonAcceleration.H"
#include "scalarMatrices.H"
#include "PstreamReduceOps.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::andersonAcceleration::andersonAcceleration(const label depth)
:
    depth_(max(depth, label(0))),
    dF_(),
    dG_(),
    fPrev_(),
    gPrev_(),
    hasPrevious_(false)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::andersonAcceleration::reset()
{
    dF_.clear();
    dG_.clear();
    hasPrevious_ = false;
}


void Foam::andersonAcceleration::update
(
    scalarField& x,
    const scalarField& g
)
{
    const scalarField f(g - x);

    if (depth_ == 0)
    {
        x = g;
        return;
    }

    if (hasPrevious_)
    {
        if (dF_.size() == depth_)
        {
            // Drop the oldest difference
            for (label i = 1; i < depth_; ++i)
            {
                dF_.set(i - 1, dF_.release(i));
                dG_.set(i - 1, dG_.release(i));
            }
            dF_.set(depth_ - 1, new scalarField(f - fPrev_));
            dG_.set(depth_ - 1, new scalarField(g - gPrev_));
        }
        else
        {
            dF_.append(new scalarField(f - fPrev_));
            dG_.append(new scalarField(g - gPrev_));
        }
    }

    fPrev_ = f;
    gPrev_ = g;
    hasPrevious_ = true;

    x = g;

    const label m = dF_.size();
    if (m == 0)
    {
        return;
    }

    // Normal equations (dF^T dF) gamma = dF^T f, with a relative Tikhonov
    // term against nearly parallel differences
    scalarSquareMatrix A(m, Zero);
    List<scalar> gamma(m, Zero);
    for (label i = 0; i < m; ++i)
    {
        for (label j = 0; j <= i; ++j)
        {
            A(i, j) = A(j, i) = gSum(dF_[i]*dF_[j]);
        }
        gamma[i] = gSum(dF_[i]*f);
    }

    scalar trace = 0;
    for (label i = 0; i < m; ++i)
    {
        trace += A(i, i);
    }
    if (trace <= VSMALL)
    {
        return;
    }
    for (label i = 0; i < m; ++i)
    {
        A(i, i) += 1e-10*trace;
    }

    LUsolve(A, gamma);

    for (label i = 0; i < m; ++i)
    {
        x -= gamma[i]*dG_[i];
    }
}


// ************************************************************************* //
