/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "forwardModel.H"
#include "volFields.H"
#include "fvPatchFields.H"
#include "interpolationCellPoint.H"
#include "meshSearch.H"
#include "OFstream.H"
#include "IFstream.H"

// * * * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * //

void Foam::forwardModel::writeControlDict(const scalar endTime) const
{
    dictionary dict(controlDict_);
    dict.set("startFrom", "startTime");
    dict.set("startTime", startTime_);
    dict.set("stopAt", "endTime");
    dict.set("endTime", endTime);
    // The end as the only write time: adjustable time steps land on it
    dict.set("writeControl", "adjustableRunTime");
    dict.set("writeInterval", endTime - startTime_);
    dict.set("purgeWrite", 0);
    dict.set("timePrecision", 12);
    dict.set("runTimeModifiable", false);

    scratchCase::writeDictionary
    (
        scratch_/"system"/"controlDict",
        dict,
        "The case's controlDict, run by hearthDuration: functions removed,"
        " start, end and write times set"
    );
}


Foam::scalarField Foam::forwardModel::sample(const word& fieldName) const
{
    volScalarField field
    (
        IOobject
        (
            fieldName,
            time_->timeName(),
            mesh_(),
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        ),
        mesh_()
    );

    volScalarField::Boundary& bf = field.boundaryFieldRef();
    forAll(bf, patchi)
    {
        if (!bf[patchi].coupled() && bf[patchi].size())
        {
            bf[patchi] == max(bf[patchi], bf[patchi].patchInternalField());
        }
    }

    interpolationCellPoint<scalar> interpolator(field);

    scalarField values(points_.size());
    forAll(points_, i)
    {
        values[i] = interpolator.interpolate(points_[i], cells_[i]);
    }
    return values;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::forwardModel::forwardModel
(
    const Time& runTime,
    const word& firePatch,
    const fireHistory& fire,
    const pointField& points,
    const word& solver,
    const label nProcs,
    const string& mpirun,
    const fileName& workDir
)
:
    solver_(solver),
    nProcs_(nProcs),
    mpirun_(mpirun),
    fire_(fire),
    scratch_(workDir/"scratchCase"),
    copy_(),
    startTime_(runTime.value()),
    startTimeName_(runTime.timeName()),
    controlDict_(runTime.controlDict()),
    points_(points),
    cells_(),
    startT_(),
    time_(),
    mesh_()
{
    const fileName casePath(runTime.path());

    if
    (
        scratch_.find('\'') != string::npos
     || casePath == scratch_
     || casePath.find(scratch_ + "/") == 0
    )
    {
        FatalErrorInFunction
            << "Cannot use " << scratch_ << " as the scratch case of "
            << casePath << exit(FatalError);
    }

    controlDict_.remove("functions");

    // The copy: system, constant and the start time
    copy_.reset
    (
        new scratchCase
        (
            casePath, startTimeName_, startTime_, scratch_, nProcs_, mpirun_
        )
    );
    rm(scratch_/"constant"/"fireHistory");

    Info<< "Scratch copy of the case: " << scratch_ << endl;

    // Files needed to read the copy: a fire history, a controlDict
    const fileName fireFile(scratch_/"constant"/"fireHistory");
    fire_.write(fireFile, max(fire_.rampTime(), fireHistory::hour), startTime_);
    writeControlDict(startTime_ + fireHistory::hour);

    time_.reset
    (
        new Time
        (
            Time::controlDictName,
            fileName(scratch_.path()),
            fileName(scratch_.name()),
            word("system"),
            word("constant"),
            false               // no function objects
        )
    );

    mesh_.reset
    (
        new fvMesh
        (
            IOobject
            (
                fvMesh::defaultRegion,
                time_->timeName(),
                time_(),
                IOobject::MUST_READ
            )
        )
    );

    // The fire patch of T reads the fire history file
    {
        volScalarField T
        (
            IOobject
            (
                "T",
                time_->timeName(),
                mesh_(),
                IOobject::MUST_READ,
                IOobject::NO_WRITE,
                false
            ),
            mesh_()
        );

        const label patchi = mesh_->boundary().findPatchID(firePatch);

        dictionary coeffs;
        coeffs.add("file", fireFile);
        coeffs.add("outOfBounds", word("clamp"));
        coeffs.add("interpolationScheme", word("linear"));

        dictionary bc;
        bc.add("type", word("uniformFixedValue"));
        bc.add("uniformValue", word("tableFile"));
        bc.add("uniformValueCoeffs", coeffs);

        T.boundaryFieldRef().set
        (
            patchi,
            fvPatchScalarField::New(mesh_->boundary()[patchi], T, bc)
        );
        T.write();
    }

    // The cells of the points and T there at the start
    meshSearch searchEngine(mesh_());
    cells_.setSize(points_.size());
    forAll(points_, i)
    {
        cells_[i] = searchEngine.findCell(points_[i]);
    }
    startT_ = sample("T");

    if (nProcs_ > 1)
    {
        const fileName log(scratch_/"log.decomposePar");
        if (!copy_->decompose())
        {
            FatalErrorInFunction
                << "decomposePar failed on the scratch case: see " << log
                << exit(FatalError);
        }
        Info<< "Decomposed on " << nProcs_ << " ranks (" << log << ")"
            << endl;
    }
    Info<< endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalarField Foam::forwardModel::run
(
    const scalar duration,
    const label runIndex,
    fileName& log,
    boolList& stillRising
)
{
    return run(fire_, duration, runIndex, log, stillRising);
}


Foam::scalarField Foam::forwardModel::run
(
    const fireHistory& fire,
    const scalar duration,
    const label runIndex,
    fileName& log,
    boolList& stillRising
)
{
    const scalar endTime = startTime_ + duration + fire.coolingTime();

    fire.write(scratch_/"constant"/"fireHistory", duration, startTime_);
    writeControlDict(endTime);
    copy_->removeResults();

    log = scratch_/word("log." + solver_ + "." + Foam::name(runIndex));

    const std::string command(copy_->solverCommand(solver_, log));
    const std::string why
    (
        scratchCase::failure
        (
            copy_->execute(command, copy_->launcherLog(log)), log
        )
    );

    if (scratchCase::interrupted())
    {
        // Exit status 128 + signal, as hearthFit's and a shell's (130 for
        // Ctrl-C)
        const int sig = scratchCase::interrupted();
        FatalErrorInFunction
            << "Interrupted (signal " << sig << ") during forward run "
            << runIndex << ": the solver was killed"
            << exit(FatalError, 128 + sig);
    }
    if (why.size())
    {
        FatalErrorInFunction
            << "Forward run " << runIndex << " (fire of "
            << duration/fireHistory::hour << " h) failed: " << solver_
            << ": " << why.c_str() << nl
            << "    command: " << command.c_str() << nl
            << "    see the log " << log << nl
            << exit(FatalError);
    }

    if (nProcs_ > 1)
    {
        const fileName reconstructLog
        (
            scratch_/word("log.reconstructPar." + Foam::name(runIndex))
        );
        if
        (
            copy_->execute
            (
                "reconstructPar -latestTime -fields '(TMax T)' -case "
              + scratchCase::quoted(scratch_),
                reconstructLog
            )
        )
        {
            FatalErrorInFunction
                << "reconstructPar failed after forward run " << runIndex
                << ": see " << reconstructLog << exit(FatalError);
        }
    }

    // The end time
    const instantList times(Time::findTimes(scratch_));
    if
    (
        times.empty()
     || times.last().value() < endTime - 1e-6*max(mag(endTime), 1)
    )
    {
        FatalErrorInFunction
            << "Forward run " << runIndex << " did not write its end time "
            << endTime << " (latest: "
            << (times.size() ? times.last().name() : word("none")) << ")"
            << nl << "    see the log " << log << nl
            << exit(FatalError);
    }
    time_->setTime(times.last(), times.size() - 1);

    const scalarField TMax(sample("TMax"));
    const scalarField T(sample("T"));

    stillRising.setSize(points_.size());
    forAll(points_, i)
    {
        stillRising[i] =
            T[i] >= TMax[i] - 0.01 && TMax[i] > startT_[i] + 0.01;
    }

    return TMax;
}


// ************************************************************************* //
