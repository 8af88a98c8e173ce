/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "balanceMonitor.H"
#include "checkedRead.H"
#include <limits>
#include "Time.H"
#include "OStringStream.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::balanceMonitor::balanceMonitor
(
    const fvMesh& mesh,
    const bool defaultStrict
)
:
    mesh_(mesh),
    tolerance_(1e-6),
    strict_(defaultStrict),
    nMissed_(0),
    firstMissed_()
{
    const dictionary& nonlinearDict =
        mesh.solutionDict().optionalSubDict("nonlinear");
    tolerance_ =
        checkedRead::getOrDefault
        (
            nonlinearDict, "balanceTolerance", dimless, 1e-6,
            checkedRead::positive()
        ).value();
    strict_ = nonlinearDict.getOrDefault<bool>("strictBalance", defaultStrict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::balanceMonitor::check
(
    const word& name,
    const scalar imbalance,
    const scalar scale,
    const scalar held
)
{
    const scalar relative = imbalance/max(scale, VSMALL);
    const bool missed =
        !(mag(imbalance) <= tolerance_*scale)
     && !(mag(imbalance) <= roundOff*mag(held));

    if (missed)
    {
        OStringStream msg;
        msg << name << " balance at t = " << mesh_.time().timeName()
            << " s missed its tolerance: relative imbalance " << relative
            << " > balanceTolerance " << tolerance_
            << " (system/fvSolution, nonlinear)";
        Info<< "--> FOAM Warning : " << msg.str().c_str() << endl;
        if (nMissed_ == 0)
        {
            firstMissed_ = msg.str();
        }
        ++nMissed_;
    }
    return !missed;
}


int Foam::balanceMonitor::exitStatus() const
{
    if (nMissed_ == 0)
    {
        return 0;
    }
    Info<< "--> FOAM Warning : " << nMissed_ << " balance report(s) missed"
        << " balanceTolerance " << tolerance_ << " (system/fvSolution,"
        << " nonlinear), the first: " << firstMissed_.c_str() << nl
        << "    The results are written; exit status "
        << (strict_ ? "1 (strictBalance true)" : "0 (strictBalance false)")
        << ". Tighten the nonlinear and linear-solver tolerances, or"
        << " raise balanceTolerance" << nl << endl;
    return strict_ ? 1 : 0;
}


// ************************************************************************* //
