/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "fireTemperatureFvPatchScalarField.H"
#include "addToRunTimeSelectionTable.H"
#include "fvPatchFieldMapper.H"
#include "volFields.H"
#include "checkedRead.H"
#include "fireHistory.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

std::string Foam::fireTemperatureFvPatchScalarField::owner() const
{
    return
        "boundary condition " + type() + " on patch '" + patch().name()
      + "' of field " + internalField().name();
}


void Foam::fireTemperatureFvPatchScalarField::readLaw
(
    const dictionary& dict
)
{
    // Nothing of the file or table form: the law is the whole history
    checkedRead::checkKeywords
    (
        dict,
        wordList({"type", "fire", "cooling", "value", "patchType"}),
        owner() + " with a fire law (fire, cooling); file, table and their"
        " keywords are the other form"
    );
    for (const word& key : wordList({"fire", "cooling"}))
    {
        if (!dict.isDict(key))
        {
            FatalIOErrorInFunction(dict)
                << "Keyword '" << key << "' of boundary condition " << type()
                << " on patch '" << patch().name() << "' is not a"
                << " sub-dictionary: the fire law needs" << nl
                << "    fire    { temperature 700; duration 6; }  // C, h"
                << nl
                << "    cooling { type exponential; Tair 20; tau 1;"
                << " duration 18; }" << nl << exit(FatalIOError);
        }
    }
    fireDict_ = dict.subDict("fire");
    coolingDict_ = dict.subDict("cooling");

    const fireHistory law(fireDict_, coolingDict_, wordList({"duration"}));

    // Duration from ignition to extinction [h], at least the ramp
    const scalar duration =
        checkedRead::get
        (
            fireDict_, "duration", dimless,
            validRange{law.rampTime()/fireHistory::hour, GREAT, false, true}
        ).value()*fireHistory::hour;

    history_ = law.table(duration);

    Info<< "fireTemperature on patch " << patch().name() << " of field "
        << internalField().name() << ": " << law.description().c_str()
        << "; fire duration " << duration/fireHistory::hour << " h; "
        << history_.size() << " points from t = " << history_.times().first()
        << " to " << history_.times().last() << " s" << endl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fireTemperatureFvPatchScalarField::fireTemperatureFvPatchScalarField
(
    const fvPatch& p,
    const DimensionedField<scalar, volMesh>& iF
)
:
    fixedValueFvPatchScalarField(p, iF),
    record_(),
    beforeStart_("hold"),
    afterEnd_("hold"),
    fireDict_(),
    coolingDict_(),
    history_(),
    dictName_(iF.objectPath()),
    dictLine_(-1)
{}


Foam::fireTemperatureFvPatchScalarField::fireTemperatureFvPatchScalarField
(
    const fvPatch& p,
    const DimensionedField<scalar, volMesh>& iF,
    const dictionary& dict
)
:
    fixedValueFvPatchScalarField(p, iF, dict, false),
    record_(),
    beforeStart_("hold"),
    afterEnd_("hold"),
    fireDict_(),
    coolingDict_(),
    history_(),
    dictName_(dict.name()),
    dictLine_(dict.startLineNumber())
{
    if (dict.found("fire", keyType::LITERAL))
    {
        readLaw(dict);
        fvPatchScalarField::operator=(temperature(db().time().value()));
        return;
    }

    // Unknown keywords (a misspelt 'timeUnit' would silently give seconds)
    {
        wordList known({"type"});
        known.append(fireRecord::keywords());
        known.append
        (
            wordList
            ({
                "beforeStart", "afterEnd", "value", "patchType",
                "fire"  // (the other form, read by readLaw: named as a
                        // near miss)
            })
        );
        checkedRead::checkKeywords(dict, known, owner());
    }

    // The record: its keywords, the file or table, every row checked
    record_ = fireRecord(dict, db().time().globalPath(), owner());

    const std::string where(" in the entry of " + owner());
    const wordList holdOrError({"hold", "error"});
    beforeStart_ =
        fireRecord::choice(dict, "beforeStart", "hold", holdOrError, where);
    afterEnd_ =
        fireRecord::choice(dict, "afterEnd", "hold", holdOrError, where);

    history_ = record_.history();

    Info<< "fireTemperature on patch " << patch().name() << " of field "
        << internalField().name() << ": " << record_.summary().c_str()
        << "; before the first time: " << beforeStart_
        << ", after the last: " << afterEnd_ << endl;

    // The value at the current time (beforeStart/afterEnd checked: a start
    // time outside the history with 'error' stops before any time step).
    // A 'value' entry is not used: the history is the reference.
    fvPatchScalarField::operator=(temperature(db().time().value()));
}


Foam::fireTemperatureFvPatchScalarField::fireTemperatureFvPatchScalarField
(
    const fireTemperatureFvPatchScalarField& ptf,
    const fvPatch& p,
    const DimensionedField<scalar, volMesh>& iF,
    const fvPatchFieldMapper& mapper
)
:
    fixedValueFvPatchScalarField(p, iF),    // not mapped: uniform
    record_(ptf.record_),
    beforeStart_(ptf.beforeStart_),
    afterEnd_(ptf.afterEnd_),
    fireDict_(ptf.fireDict_),
    coolingDict_(ptf.coolingDict_),
    history_(ptf.history_),
    dictName_(ptf.dictName_),
    dictLine_(ptf.dictLine_)
{
    fvPatchScalarField::operator=(temperature(db().time().value(), false));
}


Foam::fireTemperatureFvPatchScalarField::fireTemperatureFvPatchScalarField
(
    const fireTemperatureFvPatchScalarField& ptf
)
:
    fixedValueFvPatchScalarField(ptf),
    record_(ptf.record_),
    beforeStart_(ptf.beforeStart_),
    afterEnd_(ptf.afterEnd_),
    fireDict_(ptf.fireDict_),
    coolingDict_(ptf.coolingDict_),
    history_(ptf.history_),
    dictName_(ptf.dictName_),
    dictLine_(ptf.dictLine_)
{}


Foam::fireTemperatureFvPatchScalarField::fireTemperatureFvPatchScalarField
(
    const fireTemperatureFvPatchScalarField& ptf,
    const DimensionedField<scalar, volMesh>& iF
)
:
    fixedValueFvPatchScalarField(ptf, iF),
    record_(ptf.record_),
    beforeStart_(ptf.beforeStart_),
    afterEnd_(ptf.afterEnd_),
    fireDict_(ptf.fireDict_),
    coolingDict_(ptf.coolingDict_),
    history_(ptf.history_),
    dictName_(ptf.dictName_),
    dictLine_(ptf.dictLine_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::fireTemperatureFvPatchScalarField::temperature
(
    const scalar t,
    const bool check
) const
{
    const label n = history_.size();
    const scalarList& times = history_.times();

    if (!n)
    {
        FatalErrorInFunction
            << "No fire history on patch '" << patch().name() << "'"
            << exit(FatalError);
    }

    const bool before = t < times[0];
    const bool after = t > times[n - 1];

    if (check && ((before && beforeStart_ == "error")
                  || (after && afterEnd_ == "error")))
    {
        // (only a record has beforeStart and afterEnd)
        const bool fromFile = record_.file().size();
        const label rowi = before ? 0 : n - 1;
        const string source =
            fromFile ? string(record_.file()) : string(dictName_);
        const label line = fromFile ? history_.line(rowi) : dictLine_;

        FatalIOError(FUNCTION_NAME, __FILE__, __LINE__, source, line)
            << "Time t = " << t << " s is "
            << (before ? "before the start" : "after the end")
            << " of the fire history, whose " << (before ? "first" : "last")
            << ' ' << (fromFile ? "line" : "row") << ' '
            << history_.line(rowi) << " is at "
            << record_.describeTime(rowi).c_str()
            << ", and " << (before ? "beforeStart" : "afterEnd")
            << " is 'error'" << nl
            << "    (set it to 'hold' to keep the "
            << (before ? "first" : "last") << " temperature, "
            << (before ? "or change the startTime or timeOffset"
                       : "extend the history or reduce endTime")
            << ")" << nl
            << "    in " << record_.describeSource().c_str() << nl
            << exit(FatalIOError);
    }

    // Linear between the rows, exact at them, held outside
    return history_.value(t);
}


void Foam::fireTemperatureFvPatchScalarField::updateCoeffs()
{
    if (updated())
    {
        return;
    }

    fvPatchScalarField::operator==(temperature(db().time().value()));

    fixedValueFvPatchScalarField::updateCoeffs();
}


void Foam::fireTemperatureFvPatchScalarField::write(Ostream& os) const
{
    fvPatchScalarField::write(os);

    // Enough digits to read back what was given
    const int oldPrecision = os.precision(max(os.precision(), 15));

    if (fireDict_.size())
    {
        os.beginBlock("fire");
        fireDict_.write(os, false);
        os.endBlock();
        os.beginBlock("cooling");
        coolingDict_.write(os, false);
        os.endBlock();
    }
    else
    {
        record_.write(os);
        os.writeEntryIfDifferent<word>("beforeStart", "hold", beforeStart_);
        os.writeEntryIfDifferent<word>("afterEnd", "hold", afterEnd_);
    }

    os.precision(oldPrecision);

    writeEntry("value", os);
}


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{
    makePatchTypeField
    (
        fvPatchScalarField,
        fireTemperatureFvPatchScalarField
    );
}

// ************************************************************************* //
