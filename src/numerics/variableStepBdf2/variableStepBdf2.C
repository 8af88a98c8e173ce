/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "variableStepBdf2.H"
#include "PstreamReduceOps.H"
#include "Time.H"
#include "checkedRead.H"
#include "dimensionSets.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(variableStepBdf2, 0);
}

const Foam::scalar Foam::variableStepBdf2::maxStepRatio = 1 + Foam::sqrt(2.0);


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::variableStepBdf2::variableStepBdf2
(
    const Time& runTime,
    const label nBlock,
    const label component,
    const scalarField& totals
)
:
    regIOobject
    (
        IOobject
        (
            typeName,
            runTime.timeName(),
            "uniform",
            runTime,
            IOobject::READ_IF_PRESENT,
            IOobject::AUTO_WRITE
        )
    ),
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
    correction_(totals.size(), Zero),
    savedAccepted_(-1)
{
    if (nBlock < 1 || component < 0 || component >= nBlock)
    {
        FatalErrorInFunction
            << "component " << component << " of " << nBlock
            << " unknowns per cell" << abort(FatalError);
    }

    // A restarted run: the state its last write saved (writeData), on
    // every rank or on none (the ranks would take different steps)
    const bool present = checkedRead::presentOnEveryRank
    (
        *this, "BDF2 state",
        "remove every processor*/" + time().timeName() + "/uniform/"
      + typeName + " to start by backward Euler"
    );
    if (present)
    {
        const dictionary dict(readStream(typeName));
        close();
        checkedRead::checkKeywords
        (
            dict, {"deltaT1", "deltaT2", "nAccepted", "nReduced"}
        );
        savedAccepted_ = checkedRead::getLabel(dict, "nAccepted", 0, 2);
        dt1_ =
            checkedRead::get
            (
                dict, "deltaT1", dimTime,
                savedAccepted_ > 0
              ? checkedRead::positive() : checkedRead::nonNegative()
            ).value();
        dt2_ =
            checkedRead::get
            (
                dict, "deltaT2", dimTime,
                savedAccepted_ > 1
              ? checkedRead::positive() : checkedRead::nonNegative()
            ).value();
        nReduced_ = checkedRead::getLabel(dict, "nReduced", 0, reducedSteps);
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
        const scalar f23 = (x1_[i] - x2_[i/nBlock_])/k2;
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

    // (of x^{n-1} the monitored unknown only: the error estimate's)
    x2_.setSize(x1_.size()/nBlock_);
    forAll(x2_, celli)
    {
        x2_[celli] = x1_[nBlock_*celli + component_];
    }
    x1_ = xn;
    dt2_ = dt1_;
    dt1_ = dt;
    nAccepted_ = min(nAccepted_ + 1, 2);
    nReduced_ = max(nReduced_ - 1, 0);
}


void Foam::variableStepBdf2::restore
(
    const scalarField& x1,
    const scalarField& x2,
    const scalarField& totalsBefore
)
{
    if
    (
        savedLevels() < 1 || x1.size() % nBlock_ != 0
     || totalsBefore.size() != total_.size()
    )
    {
        FatalErrorInFunction
            << "No state read (" << savedAccepted_ << " levels) or "
            << x1.size() << " values, not " << nBlock_ << " per cell, or "
            << totalsBefore.size() << " totals for " << total_.size()
            << " balances" << abort(FatalError);
    }
    if (savedAccepted_ > 1 && x2.size() != x1.size()/nBlock_)
    {
        FatalErrorInFunction
            << x2.size() << " values of the monitored unknown at t_{n-2}"
            << " for " << x1.size()/nBlock_ << " cells"
            << abort(FatalError);
    }
    x1_ = x1;
    x2_ = savedAccepted_ > 1 ? x2 : scalarField();
    // The balances' last changes from the amounts of the fields as read
    // (both levels rounded alike at writePrecision; a change written at
    // full precision against totals recomputed from rounded fields would
    // leave their difference in the first step's correction: review
    // 2026-12-05e)
    change_ = total_ - totalsBefore;
    nAccepted_ = savedAccepted_;
    savedAccepted_ = 0;
}


bool Foam::variableStepBdf2::writeData(Ostream& os) const
{
    // Every digit: the restarted run's coefficients are computed from these
    const int precision =
        os.precision(std::numeric_limits<scalar>::max_digits10);
    os.writeEntry("deltaT1", dt1_);
    os.writeEntry("deltaT2", dt2_);
    os.writeEntry("nAccepted", nAccepted_);
    os.writeEntry("nReduced", nReduced_);
    os.precision(precision);
    return os.good();
}


// ************************************************************************* //
