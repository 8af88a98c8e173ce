/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
-------------------------------------------------------------------------------
Application
    testSubStepGrowth

Description
    Unit test of subStepController (src/numerics/subStepController), the
    step control of ahcFoam and pendularFoam: a step's sub-steps, driven by
    a scripted sequence of rejections and acceptances, against their closed
    forms. The controls of case/ (maxDeltaTemperature 10 K, maxDeltaTGrowth
    g = 1.25, maxIter 30, minDeltaT 1e-3 s):

    A. a 60 s step rejected 5 times (sub-step 60/32 = 1.875 s), then every
       sub-step accepted (3 iterations, 0.1 K: the next-step rule's factor
       is g): 16 sub-steps of 1.875 s (30 s), then 1.875 g^j for
       j = 1..6 (26.388 s), then the remainder 3.612 s: 23 sub-steps (32
       without the growth: every sub-step 1.875 s); the next step
       g x 1.875 g^7 (the grown sub-step, not the remainder);
    B. a rejection while growing: the halved sub-step held again, for
       twice as many (32) accepted sub-steps, then grown by g;
    C. no growth where the rule would shrink: more than maxIter/2
       iterations (factor 0.7) or 20 K a sub-step (factor 0.5): a 60 s
       step rejected 6 times ends in 64 equal sub-steps;
    D. a step without rejection: one sub-step, the next step from it;
    E. the rejection that halves below minDeltaT is reported (the 16th
       from 60 s: 60/2^16 < 1e-3 s), and failedBelowMinDeltaT's FatalError
       names its category without a reason, 'Last rejection:
       [notConverged]';
    F. the rejection categories (subStepController::rejection): every
       name read back to its category; 15 rejections as nonFinite, the
       16th as leftModel with a reason: the last rejection is leftModel
       and the FatalError names it after the reason, 'Last rejection:
       <reason> [leftModel]', not nonFinite; a retry logs its category
       (the log lines' tokens: checked by the run script);
    and no sub-step beyond the rest of its step, each step's sub-steps
    adding up to it.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "subStepController.H"
#include "unitChecks.H"

#include <functional>

using namespace Foam;

// The sub-steps of one step of DeltaT: decide(k, dt) for the k-th attempt
// (from 0) returns the iterations and T change of an accepted sub-step, or
// iterations < 0 to reject it. Returns the accepted sub-steps' sizes;
// rejectedBelowMin is set when reject() reports minDeltaT
DynamicList<scalar> runStep
(
    subStepController& control,
    const scalar DeltaT,
    const std::function<std::pair<label, scalar>(label, scalar)>& decide,
    bool& beyondStep,
    label& rejectedBelowMin
)
{
    DynamicList<scalar> accepted;
    control.start(DeltaT);
    scalar elapsed = 0;
    label attempt = 0;
    rejectedBelowMin = -1;
    beyondStep = false;
    while (control.loop())
    {
        const scalar dt = control.deltaT();
        if (dt > DeltaT - elapsed + 1e-12*DeltaT)
        {
            beyondStep = true;
        }
        const std::pair<label, scalar> d = decide(attempt, dt);
        if (d.first < 0)
        {
            if (control.reject(30, subStepController::rejection::notConverged) && rejectedBelowMin < 0)
            {
                rejectedBelowMin = attempt;
                break;
            }
        }
        else
        {
            control.accept(d.first, d.second);
            accepted.append(dt);
            elapsed += dt;
        }
        ++attempt;
    }
    control.end();
    return accepted;
}


scalar maxRelDeviation
(
    const UList<scalar>& values,
    const label start,
    const label end,
    const std::function<scalar(label)>& expected
)
{
    scalar dev = 0;
    for (label i = start; i < end; ++i)
    {
        dev = max(dev, mag(values[i] - expected(i))/expected(i));
    }
    return dev;
}


int main(int argc, char *argv[])
{
    argList::noParallel();
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    const adaptiveTimeStepControls controls(mesh, 10, 1.25, 30);
    const scalar g = controls.maxDeltaTGrowth();
    const label hold = subStepController::holdSubSteps;
    checkAbs("the case's maxDeltaTGrowth", g, 1.25, 0);
    checkAbs("subStepController::holdSubSteps", hold, 16, 0);

    // A step after the first: setDeltaT sizes the next one
    ++runTime;
    bool beyond = false;
    label belowMin = -1;

    // A. 5 rejections, then every sub-step accepted (3 iterations, 0.1 K)
    {
        subStepController control("A", controls, 60);
        const DynamicList<scalar> dts = runStep
        (
            control, 60,
            [](label k, scalar) -> std::pair<label, scalar>
            {
                return k < 5 ? std::make_pair(label(-1), 0.0)
                             : std::make_pair(label(3), 0.1);
            },
            beyond, belowMin
        );
        const scalar dt0 = 60.0/32;
        // 30 + dt0 (g + ... + g^n) >= 60: g (g^n - 1)/(g - 1) >= 16, n = 7
        const label nGrown = 7;
        checkAbs("A: accepted sub-steps (32 without growth)", dts.size(), hold + nGrown, 0);
        checkAbs
        (
            "A: the 16 held sub-steps are 60/32 s (max rel dev)",
            maxRelDeviation(dts, 0, min(hold, dts.size()),
                [&](label){ return dt0; }),
            0, 1e-15
        );
        checkAbs
        (
            "A: then 1.875 g^j, j = 1..6 (max rel dev)",
            dts.size() == hold + nGrown
          ? maxRelDeviation(dts, hold, hold + nGrown - 1,
                [&](label i){ return dt0*pow(g, i - hold + 1); })
          : GREAT,
            0, 1e-14
        );
        const scalar remainder =
            60 - 30 - dt0*g*(pow(g, nGrown - 1) - 1)/(g - 1);
        checkAbs
        (
            "A: the last sub-step is the rest of the step [s]",
            dts.size() ? dts.last() : GREAT, remainder, 1e-12
        );
        checkAbs("A: sub-steps add up to the step [s]", sum(dts), 60, 1e-12);
        checkTrue("A: no sub-step beyond the rest of the step", !beyond, 0, 0, "bool");
        // The next step: g times the grown sub-step 1.875 g^7 (the
        // remainder would give 4.5 s; no growth 2.34375 s)
        control.setDeltaT(runTime);
        checkAbs
        (
            "A: next step g x 1.875 g^7 [s]",
            runTime.deltaTValue(), dt0*pow(g, nGrown + 1), 1e-12
        );
    }

    // B. 600 s: 6 rejections (9.375 s), 16 + 3 accepted, the 4th grown one
    // rejected (halved: 9.375 g^4/2), then all accepted
    {
        subStepController control("B", controls, 600);
        label nAccepted = 0;
        bool rejectedOnce = false;
        const DynamicList<scalar> dts = runStep
        (
            control, 600,
            [&](label k, scalar) -> std::pair<label, scalar>
            {
                if (k < 6) return std::make_pair(label(-1), 0.0);
                if (nAccepted == hold + 3 && !rejectedOnce)
                {
                    rejectedOnce = true;
                    return std::make_pair(label(-1), 0.0);
                }
                ++nAccepted;
                return std::make_pair(label(3), 0.1);
            },
            beyond, belowMin
        );
        // A grown sub-step rejected: the hold doubles for the step
        const scalar dtHalf = 0.5*600.0/64*pow(g, 4);
        const label first = hold + 3;
        const label hold2 = 2*hold;
        checkAbs
        (
            "B: a grown sub-step rejected: 32 held at half (max rel dev)",
            dts.size() > first + hold2
          ? maxRelDeviation(dts, first, first + hold2,
                [&](label){ return dtHalf; })
          : GREAT,
            0, 1e-14
        );
        checkAbs
        (
            "B: then grown by g [s]",
            dts.size() > first + hold2 ? dts[first + hold2] : GREAT,
            g*dtHalf, 1e-12
        );
        checkAbs("B: sub-steps add up to the step [s]", sum(dts), 600, 1e-10);
        checkTrue("B: no sub-step beyond the rest of the step", !beyond, 0, 0, "bool");
    }

    // C. No growth where the rule would shrink the step
    {
        subStepController control("C1", controls, 60);
        const DynamicList<scalar> many = runStep
        (
            control, 60,
            [](label k, scalar) -> std::pair<label, scalar>
            {
                return k < 6 ? std::make_pair(label(-1), 0.0)
                             : std::make_pair(label(20), 0.1);
            },
            beyond, belowMin
        );
        checkAbs("C: 20 > maxIter/2 iterations: 64 equal sub-steps", many.size(), 64, 0);
        const DynamicList<scalar> hot = runStep
        (
            control, 60,
            [](label k, scalar) -> std::pair<label, scalar>
            {
                return k < 6 ? std::make_pair(label(-1), 0.0)
                             : std::make_pair(label(3), 20.0);
            },
            beyond, belowMin
        );
        checkAbs("C: 20 K a sub-step: 64 equal sub-steps", hot.size(), 64, 0);
    }

    // D. No rejection: one sub-step; the next step from it (4 K: factor g)
    {
        subStepController control("D", controls, 60);
        const DynamicList<scalar> dts = runStep
        (
            control, 60,
            [](label, scalar) { return std::make_pair(label(3), 4.0); },
            beyond, belowMin
        );
        checkAbs("D: no rejection: one sub-step", dts.size(), 1, 0);
        control.setDeltaT(runTime);
        checkAbs("D: next step 60 g [s]", runTime.deltaTValue(), 60*g, 1e-12);
    }

    // E. minDeltaT: the 16th rejection from 60 s (60/2^16 < 1e-3)
    {
        subStepController control("E", controls, 60);
        runStep
        (
            control, 60,
            [](label, scalar) { return std::make_pair(label(-1), 0.0); },
            beyond, belowMin
        );
        checkAbs("E: rejection reported below minDeltaT (attempt, from 0)", belowMin, 15, 0);
        checkThrows
        (
            "E: minDeltaT FatalError names the category",
            [&]() { control.failedBelowMinDeltaT(runTime, "the advice"); },
            {
                "Nonlinear iterations failed with deltaT = ",
                "< minDeltaT = 0.001",
                "Last rejection: [notConverged]",
                "the advice"
            }
        );
    }

    // F. The categories: names, the last one, the FatalError, a retry
    {
        typedef subStepController::rejection rejection;
        const Enum<rejection>& names = subStepController::rejectionNames;
        label nRead = 0;
        for (const word& name : names.names())
        {
            nRead += (names[names[name]] == name);
        }
        checkAbs("F: categories named and read back", nRead, 11, 0);

        subStepController control("F", controls, 60);
        control.start(60);
        label belowAt = -1;
        for (label k = 0; k < 16 && control.loop(); ++k)
        {
            const bool below =
                k < 15
              ? control.reject(30, rejection::nonFinite)
              : control.reject
                (
                    30, rejection::leftModel, "an iterate left the range"
                );
            if (below && belowAt < 0)
            {
                belowAt = k;
            }
        }
        checkAbs("F: below minDeltaT at the 16th rejection", belowAt, 15, 0);
        checkAbs
        (
            "F: the last rejection's category is leftModel",
            label(control.lastRejection()), label(rejection::leftModel), 0
        );
        checkThrows
        (
            "F: minDeltaT FatalError names the last category",
            [&]() { control.failedBelowMinDeltaT(runTime, "the advice"); },
            {
                "Last rejection: an iterate left the range [leftModel]\n",
                "the advice"
            }
        );
        control.retry(3, rejection::localError, "too inaccurate", "again");
    }

    Info<< nChecks - nFailed << " of " << nChecks << " checks passed" << endl;
    // Not a return from main: in v1912 argList's destructor ends the
    // process with Pstream::exit(0), which would hide failed checks
    Pstream::exit(nFailed > 0 ? 1 : 0);
    return 0;
}
