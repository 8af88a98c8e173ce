/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "subStepController.H"
#include "checkedRead.H"
#include "OStringStream.H"
#include "PstreamReduceOps.H"
#include <limits>

// * * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(subStepController, 0);
}

const Foam::Enum<Foam::subStepController::rejection>
Foam::subStepController::rejectionNames
({
    { rejection::notConverged, "notConverged" },
    { rejection::nonFinite, "nonFinite" },
    { rejection::linearSolveFailed, "linearSolveFailed" },
    { rejection::diverged, "diverged" },
    { rejection::leftModel, "leftModel" },
    { rejection::noWaterRoot, "noWaterRoot" },
    { rejection::phaseOscillation, "phaseOscillation" },
    { rejection::airLost, "airLost" },
    { rejection::poresFilled, "poresFilled" },
    { rejection::nearCritical, "nearCritical" },
    { rejection::localError, "localError" },
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::subStepController::subStepController
(
    const word& solverName,
    const adaptiveTimeStepControls& controls,
    const scalar deltaT0
)
:
    regIOobject
    (
        IOobject
        (
            typeName,
            controls.mesh().time().timeName(),
            "uniform",
            controls.mesh().time(),
            IOobject::READ_IF_PRESENT,
            IOobject::AUTO_WRITE
        )
    ),
    solverName_(solverName),
    controls_(controls),
    lastDeltaT_(deltaT0),
    lastMaxChange_(0),
    lastIterations_(0),
    nextStepFactor_(GREAT),
    restored_(false),
    DeltaT_(deltaT0),
    elapsed_(0),
    dtNominal_(deltaT0),
    dt_(deltaT0),
    nAcceptedSinceRejection_(0),
    grown_(false),
    grownSinceRejection_(false),
    nGrownRejected_(0),
    nRejected_(0),
    nSubSteps_(0),
    lastRejection_(),
    lastCategory_(rejection::notConverged),
    totalIter_(0),
    maxChange_(0)
{
    // A restarted run: the state its last write saved (writeData), on
    // every rank or on none (a case copied in part: the ranks would take
    // different steps, then wait for each other at the next write)
    const bool present = checkedRead::presentOnEveryRank
    (
        *this, "sub-step state",
        "remove every processor*/" + time().timeName() + "/uniform/"
      + typeName + " to start from controlDict's deltaT"
    );
    if (present)
    {
        const dictionary dict(readStream(typeName));
        close();
        checkedRead::checkKeywords
        (
            dict,
            {"lastDeltaT", "lastMaxChange", "lastIterations", "nextStepFactor"}
        );
        lastDeltaT_ =
            checkedRead::get
            (
                dict, "lastDeltaT", dimTime, checkedRead::positive()
            ).value();
        lastMaxChange_ =
            checkedRead::get
            (
                dict, "lastMaxChange", dimTemperature,
                checkedRead::nonNegative()
            ).value();
        lastIterations_ = checkedRead::getLabel(dict, "lastIterations", 0);
        if (dict.found("nextStepFactor"))
        {
            nextStepFactor_ =
                checkedRead::get
                (
                    dict, "nextStepFactor", dimless, checkedRead::positive()
                ).value();
        }
        restored_ = true;
        Info<< "Restart: the first step sized as the run's next one would"
            << " have been, from " << time().timeName() << "/uniform/"
            << typeName << " (the last sub-step: " << lastDeltaT_
            << " s, " << lastIterations_ << " iterations, max |dT| "
            << lastMaxChange_ << " K); remove that file to start from"
            << " controlDict's deltaT" << endl;
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::label Foam::subStepController::hold() const
{
    return holdSubSteps*(label(1) << min(nGrownRejected_, label(20)));
}


void Foam::subStepController::belowMinDeltaTHead
(
    const char* function,
    const int sourceLine,
    const char* what,
    const scalar deltaT
) const
{
    FatalError(function, __FILE__, sourceLine)
        << what << " deltaT = " << deltaT << " < minDeltaT = "
        << controls_.minDeltaT();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::subStepController::setDeltaT(Time& runTime) const
{
    // The next step below minDeltaT (the next-step rule shrinks it, e.g. by
    // 0.7 after every sub-step of more than max(maxIter/2, 2) iterations,
    // adaptiveTimeStepControls::shrinkIterations): stopped
    // before it is set (Time::adjustDeltaT divides by it)
    // The first step of a run keeps its deltaT (controlDict's, or
    // uniform/time's on a restart) unless the state of the last accepted
    // sub-step was read (restored_)
    if
    (
        !controls_.adjustTimeStep()
     || (runTime.timeIndex() <= runTime.startTimeIndex() && !restored_)
    )
    {
        return;
    }

    scalar next =
        controls_.nextDeltaT
        (
            lastDeltaT_, lastMaxChange_, lastIterations_
        );
    if (nextStepFactor_ < GREAT)
    {
        next = min(next, nextStepFactor_*lastDeltaT_);
    }
    if (!(next >= controls_.minDeltaT()))
    {
        OStringStream when;
        when<< "at time " << runTime.timeName();
        shrunkBelowMinDeltaT(next, when.str());
    }

    // As before the restart's state was kept (2026-12-05): the step of the
    // rule, fitted to the write times by Time, then limitNextStep's limit
    // if that step is above it
    runTime.setDeltaT
    (
        controls_.nextDeltaT(lastDeltaT_, lastMaxChange_, lastIterations_)
    );
    if
    (
        nextStepFactor_ < GREAT
     && runTime.deltaTValue() > nextStepFactor_*lastDeltaT_
    )
    {
        runTime.setDeltaT(nextStepFactor_*lastDeltaT_);
    }
}


void Foam::subStepController::shrunkBelowMinDeltaT
(
    const scalar deltaT,
    const string& when
) const
{
    const bool shrunk = lastIterations_ > controls_.shrinkIterations();
    belowMinDeltaTHead(FUNCTION_NAME, __LINE__, "Time step shrunk to", deltaT);
    FatalError
        << " " << when.c_str()
        << " by the next-step rule (no rejection): the last accepted"
        << " sub-step of " << lastDeltaT_ << " s took " << lastIterations_
        << " nonlinear iterations ("
        << (
               shrunk
             ? "more than max(maxIter/2, 2) = "
             : "not limiting: at most max(maxIter/2, 2) = "
           )
        << controls_.shrinkIterations()
        << (shrunk ? ": the next step at most 0.7 of it)" : ")")
        << " and changed T by up to " << lastMaxChange_
        << " K (maxDeltaTemperature " << controls_.maxDeltaTemperature()
        << " K)";
    if (nextStepFactor_ < GREAT)
    {
        FatalError
            << "; the local error estimate limits the next step to "
            << nextStepFactor_ << " of it";
    }
    FatalError
        << nl << "    Raise nonlinear { maxIter; } in system/fvSolution"
        << " (now " << controls_.maxIter() << ") if the iterations shrank"
        << " it, maxDeltaTemperature in system/controlDict if the change"
        << " of T did, or lower minDeltaT there if such steps are meant"
        << exit(FatalError);
}


void Foam::subStepController::start(const scalar DeltaT)
{
    DeltaT_ = DeltaT;
    elapsed_ = 0;
    dtNominal_ = DeltaT;
    dt_ = DeltaT;
    nAcceptedSinceRejection_ = 0;
    grown_ = false;
    grownSinceRejection_ = false;
    nGrownRejected_ = 0;
    nRejected_ = 0;
    nSubSteps_ = 0;
    totalIter_ = 0;
    maxChange_ = 0;
}


bool Foam::subStepController::loop()
{
    if (elapsed_ < DeltaT_*(1 - 1e-10))
    {
        // Below minDeltaT by limitNextStep (a local error estimate), not by
        // a rejection (reject: the solver's failedBelowMinDeltaT)
        if (!(dtNominal_ >= controls_.minDeltaT()))
        {
            OStringStream when;
            when<< elapsed_ << " s into the time step of " << DeltaT_ << " s";
            shrunkBelowMinDeltaT(dtNominal_, when.str());
        }
        dt_ = min(dtNominal_, DeltaT_ - elapsed_);
        return true;
    }
    return false;
}


void Foam::subStepController::accept
(
    const label iter,
    const scalar maxChange
)
{
    totalIter_ += iter;
    maxChange_ = max(maxChange_, maxChange);
    elapsed_ += dt_;
    ++nSubSteps_;
    // Once grown in this step, the controller's sub-step, not the remainder it was cut
    // to at the step's end (any fraction of it): the next step is sized
    // from it. Else the sub-step itself (halved ones add up to the step;
    // a local error estimate, limitNextStep, was made on it)
    lastDeltaT_ = grown_ ? dtNominal_ : dt_;
    lastIterations_ = iter;

    if (nRejected_ > 0 && ++nAcceptedSinceRejection_ >= hold())
    {
        const scalar factor = controls_.stepFactor(maxChange, iter);
        if (factor > 1)
        {
            dtNominal_ = min(DeltaT_, factor*dtNominal_);
            grown_ = true;
            grownSinceRejection_ = true;
        }
    }
}


void Foam::subStepController::limitNextStep(const scalar factor)
{
    nextStepFactor_ = factor;
    // The remaining sub-steps of this step too
    dtNominal_ = min(dtNominal_, factor*lastDeltaT_);
}


bool Foam::subStepController::reject
(
    const label iter,
    const rejection category,
    const string& reason
)
{
    totalIter_ += iter;
    dtNominal_ = 0.5*dt_;
    dt_ = dtNominal_;
    nAcceptedSinceRejection_ = 0;
    if (grownSinceRejection_)
    {
        // A grown sub-step failed: hold the next one twice as long
        ++nGrownRejected_;
        grownSinceRejection_ = false;
    }
    ++nRejected_;
    lastRejection_ = reason;
    lastCategory_ = category;

    Info<< "    step rejected after " << iter << " iterations";
    if (!reason.empty())
    {
        Info<< " (" << reason.c_str() << ")";
    }
    Info<< ": retry with deltaT = " << dt_ << " ["
        << rejectionNames[category] << "]" << endl;

    return dt_ < controls_.minDeltaT();
}


void Foam::subStepController::failedBelowMinDeltaT
(
    const Time& runTime,
    const string& advice
) const
{
    belowMinDeltaTHead
    (
        FUNCTION_NAME, __LINE__, "Nonlinear iterations failed with", dt_
    );
    FatalError << " at time " << runTime.timeName() << nl;
    FatalError << "    Last rejection: ";
    if (!lastRejection_.empty())
    {
        FatalError << lastRejection_.c_str() << " ";
    }
    FatalError
        << "[" << rejectionNames[lastCategory_] << "]" << nl
        << "    " << advice.c_str() << exit(FatalError);
}


void Foam::subStepController::retry
(
    const label iter,
    const rejection category,
    const string& reason,
    const string& how
)
{
    totalIter_ += iter;
    Info<< "    step retried after " << iter << " iterations ("
        << reason.c_str() << "): " << how.c_str() << " ["
        << rejectionNames[category] << "]" << endl;
}


void Foam::subStepController::end()
{
    lastMaxChange_ =
        maxChange_*DeltaT_/max(lastDeltaT_, SMALL)/max(nSubSteps_, 1);
}


bool Foam::subStepController::writeData(Ostream& os) const
{
    // Every digit: the restarted run's steps are sized from these
    const int precision =
        os.precision(std::numeric_limits<scalar>::max_digits10);
    os.writeEntry("lastDeltaT", lastDeltaT_);
    os.writeEntry("lastMaxChange", lastMaxChange_);
    os.writeEntry("lastIterations", lastIterations_);
    if (nextStepFactor_ < GREAT)
    {
        os.writeEntry("nextStepFactor", nextStepFactor_);
    }
    os.precision(precision);
    return os.good();
}


Foam::string Foam::subStepController::summary() const
{
    OStringStream os;
    os  << solverName_ << ": deltaT = " << DeltaT_ << ", iterations = "
        << totalIter_ << ", sub-steps = " << nSubSteps_ << ", rejected = "
        << nRejected_ << ", max |dT| = " << maxChange_;
    return os.str();
}

// ************************************************************************* //
