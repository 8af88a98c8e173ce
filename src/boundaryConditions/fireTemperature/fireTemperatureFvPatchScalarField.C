/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "fireTemperatureFvPatchScalarField.H"
#include "addToRunTimeSelectionTable.H"
#include "fvPatchFieldMapper.H"
#include "volFields.H"
#include "DynamicList.H"
#include "OSspecific.H"
#include "OStringStream.H"
#include "checkedRead.H"
#include "numericTable.H"
#include "fireHistory.H"

#include <algorithm>
#include <cmath>
#include <limits>
#include <fstream>
#include <string>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// Keywords of the patch entry
const char* const knownKeywords[] =
{
    "type", "file", "table", "timeColumn", "temperatureColumn", "separator",
    "headerLines", "timeUnit", "temperatureUnit", "timeOffset",
    "beforeStart", "afterEnd", "value", "patchType",
    "fire"      // (the other form, read by readLaw: named as a near miss)
};

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::fireTemperatureFvPatchScalarField::timeFactor() const
{
    if (timeUnit_ == "min")
    {
        return 60;
    }
    else if (timeUnit_ == "h")
    {
        return 3600;
    }
    return 1;
}


Foam::scalar Foam::fireTemperatureFvPatchScalarField::kelvin
(
    const scalar theta
) const
{
    return temperatureUnit_ == "C" ? theta + 273.15 : theta;
}


Foam::string Foam::fireTemperatureFvPatchScalarField::describeSource() const
{
    OStringStream os;
    os  << "the fire history of boundary condition " << type()
        << " on patch '" << patch().name() << "' of field "
        << internalField().name();
    if (file_.size())
    {
        os  << " (file \"" << fileEntry_.c_str() << "\", read as "
            << file_ << ")";
    }
    else
    {
        os  << " (inline table in " << dictName_ << ")";
    }
    return os.str();
}


std::string Foam::fireTemperatureFvPatchScalarField::separatorName() const
{
    if (separator_ == numericTable::whitespace)
    {
        return "whitespace";
    }
    else if (separator_ == numericTable::automatic)
    {
        return "auto";
    }
    else if (separator_ == '\t')
    {
        return "tab";
    }
    return std::string("'") + separator_ + "'";
}


Foam::string Foam::fireTemperatureFvPatchScalarField::describeTime
(
    const label rowi
) const
{
    OStringStream os;
    const scalar t = history_.times()[rowi];
    os  << "t = " << t << " s";
    if (timeUnit_ != "s" || timeOffset_ != 0)
    {
        os  << " (" << (t + timeOffset_)/timeFactor() << ' '
            << timeUnit_ << " in the " << (file_.size() ? "file" : "table")
            << ")";
    }
    return os.str();
}


void Foam::fireTemperatureFvPatchScalarField::readKeywords
(
    const dictionary& dict
)
{
    // Common tail of the keyword errors
    auto where = [&]() -> string
    {
        return
            " in the entry of boundary condition " + type() + " on patch '"
          + patch().name() + "' of field " + internalField().name();
    };

    // Unknown keywords (a misspelt 'timeUnit' would silently give seconds)
    {
        wordList known;
        for (const char* k : knownKeywords)
        {
            known.append(k);
        }
        checkedRead::checkKeywords
        (
            dict, known,
            "boundary condition " + type() + " on patch '" + patch().name()
          + "' of field " + internalField().name()
        );
    }

    // Columns
    auto readColumn = [&](const word& key, const label deflt) -> label
    {
        // Columns count from 0
        return checkedRead::getLabelOrDefault(dict, key, deflt, 0);
    };
    timeColumn_ = readColumn("timeColumn", 0);
    temperatureColumn_ = readColumn("temperatureColumn", 1);
    if (timeColumn_ == temperatureColumn_)
    {
        FatalIOErrorInFunction(dict)
            << "Keywords 'timeColumn' and 'temperatureColumn' are both "
            << timeColumn_ << where().c_str()
            << ": they must name different columns" << nl
            << exit(FatalIOError);
    }

    // Separator: a character (word, string or punctuation), or whitespace
    separator_ = ',';
    if (dict.found("separator"))
    {
        ITstream& is = dict.lookup("separator");
        token tok;
        is.read(tok);
        std::string s;
        if (tok.isWord())
        {
            s = tok.wordToken();
        }
        else if (tok.isString())
        {
            s = tok.stringToken();
        }
        else if (tok.isPunctuation())
        {
            s = std::string(1, char(tok.pToken()));
        }

        if (s == "whitespace" || s == "space" || s == " ")
        {
            separator_ = numericTable::whitespace;
        }
        else if (s == "auto" || s == "automatic")
        {
            separator_ = numericTable::automatic;
        }
        else if (s == "tab" || s == "\\t" || s == "\t")
        {
            separator_ = '\t';
        }
        else if (s.size() == 1 && s != "#" && s != "\"")
        {
            separator_ = s[0];
        }
        else
        {
            FatalIOErrorInFunction(dict)
                << "Keyword 'separator' = " << tok << where().c_str()
                << " is not valid: give one character in quotes"
                << " (\",\" \";\"), tab, whitespace (runs of spaces and"
                << " tabs), or auto (per line: ',' if it has one, else ';',"
                << " else whitespace)" << nl
                << exit(FatalIOError);
        }
    }

    // Header lines
    headerLines_ = -1;
    if (dict.found("headerLines"))
    {
        // (omit it to skip the non-numeric lines at the top)
        headerLines_ = checkedRead::getLabel(dict, "headerLines", 0);
    }

    // Choices
    auto readChoice = [&]
    (
        const word& key,
        const word& deflt,
        const wordList& choices
    ) -> word
    {
        const word w = dict.getOrDefault<word>(key, deflt);
        if (!choices.found(w))
        {
            FatalIOErrorInFunction(dict)
                << "Keyword '" << key << "' = " << w << where().c_str()
                << " is not one of the valid choices " << choices << nl
                << exit(FatalIOError);
        }
        return w;
    };
    timeUnit_ = readChoice("timeUnit", "s", wordList({"s", "min", "h"}));
    temperatureUnit_ =
        readChoice("temperatureUnit", "C", wordList({"C", "K"}));
    beforeStart_ =
        readChoice("beforeStart", "hold", wordList({"hold", "error"}));
    afterEnd_ = readChoice("afterEnd", "hold", wordList({"hold", "error"}));

    // Offset [s]
    // (a finite number: nan, inf or a word named with the file and line)
    timeOffset_ =
        checkedRead::getOrDefault
        (
            dict, "timeOffset", dimTime, 0,
            validRange{-GREAT, GREAT, true, true}
        ).value();
    // (bounded so that the times in s cannot overflow: see addRow)
    if
    (
        !std::isfinite(timeOffset_)
     || std::abs(timeOffset_) > 0.25*std::numeric_limits<scalar>::max()
    )
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 'timeOffset' = " << timeOffset_ << where().c_str()
            << " is not a finite number of seconds below "
            << 0.25*std::numeric_limits<scalar>::max() << " in magnitude"
            << nl
            << exit(FatalIOError);
    }
}


void Foam::fireTemperatureFvPatchScalarField::addRow
(
    const scalar tau,
    const scalar theta,
    const label line,
    const string& source,
    const label sourceLine
)
{
    // Where: a line of the file, or a row of the inline table
    OStringStream at;
    if (file_.size())
    {
        at  << "Line " << line << " of the fire history file";
    }
    else
    {
        at  << "Row " << line << " of the inline table of the fire history";
    }

    if (!std::isfinite(tau) || !std::isfinite(theta))
    {
        FatalIOError(FUNCTION_NAME, __FILE__, __LINE__, source, sourceLine)
            << at.str().c_str() << " has a time (" << tau
            << ") or temperature (" << theta << ") that is not a finite"
            << " number (nan, inf, or beyond the range of double)" << nl
            << "    in " << describeSource().c_str()
            << nl << exit(FatalIOError);
    }

    // A time whose conversion to s (or differences of times) would
    // overflow, which OpenFOAM traps (a crash instead of this error)
    // (timeOffset is bounded the same way in readKeywords)
    const scalar tMax = 0.25*std::numeric_limits<scalar>::max();
    if (std::abs(tau) > tMax/timeFactor())
    {
        FatalIOError(FUNCTION_NAME, __FILE__, __LINE__, source, sourceLine)
            << at.str().c_str() << " has a time (" << tau << ' '
            << timeUnit_ << ") out of range: times must be below "
            << tMax << " s in magnitude"
            << nl << "    in " << describeSource().c_str()
            << nl << exit(FatalIOError);
    }

    const scalar T = kelvin(theta);
    if (!(T > 0))
    {
        FatalIOError(FUNCTION_NAME, __FILE__, __LINE__, source, sourceLine)
            << at.str().c_str() << ": temperature " << theta << ' '
            << temperatureUnit_ << " = " << T << " K is at or below"
            << " absolute zero (temperatureUnit " << temperatureUnit_
            << "; is that the unit of the file?)" << nl
            << "    in " << describeSource().c_str() << nl
            << exit(FatalIOError);
    }

    const scalar t = timeFactor()*tau - timeOffset_;
    const temperatureHistory::check result = history_.append(t, T, line);

    if
    (
        result == temperatureHistory::check::sameTime
     || result == temperatureHistory::check::timeBefore
    )
    {
        const label n = history_.size();
        const scalar tPrev = history_.times()[n - 1];
        OStringStream prev;
        if (file_.size())
        {
            prev << "line " << history_.line(n - 1);
        }
        else
        {
            prev << "row " << history_.line(n - 1);
        }
        const scalar prevTau = (tPrev + timeOffset_)/timeFactor();

        FatalIOError(FUNCTION_NAME, __FILE__, __LINE__, source, sourceLine)
            << "Times of the fire history do not increase: "
            << at.str().c_str() << " has time " << tau << ' ' << timeUnit_
            << " (t = " << t << " s), "
            << (
                   result == temperatureHistory::check::sameTime
                 ? "the same as" : "before"
               ) << ' '
            << prev.str().c_str() << " with time " << prevTau << ' '
            << timeUnit_ << " (t = " << tPrev << " s)" << nl
            << "    The times must increase strictly (sort the rows,"
            << " remove duplicate times)" << nl
            << "    in " << describeSource().c_str() << nl
            << exit(FatalIOError);
    }
    else if (result != temperatureHistory::check::ok)
    {
        // (finite values above absolute zero checked above)
        FatalIOError(FUNCTION_NAME, __FILE__, __LINE__, source, sourceLine)
            << at.str().c_str() << ": not a valid point of the history"
            << nl << "    in " << describeSource().c_str() << nl
            << exit(FatalIOError);
    }
}


Foam::fileName Foam::fireTemperatureFvPatchScalarField::resolveFile
(
    const fileName& given,
    const fileName& casePath
)
{
    fileName f(given);
    f.expand();
    if (!f.isAbsolute())
    {
        f = casePath/f;
    }
    f.clean();
    return f;
}


void Foam::fireTemperatureFvPatchScalarField::readFile
(
    const dictionary& dict
)
{
    // The name: a word or a string
    {
        ITstream& is = dict.lookup("file");
        token tok;
        is.read(tok);
        if (tok.isWord())
        {
            fileEntry_ = tok.wordToken();
        }
        else if (tok.isString())
        {
            fileEntry_ = tok.stringToken();
        }
        else
        {
            FatalIOErrorInFunction(dict)
                << "Keyword 'file' = " << tok << " of boundary condition "
                << type() << " on patch '" << patch().name()
                << "' is not a file name (give it in quotes: "
                << "file \"<constant>/fire.csv\";)" << nl
                << exit(FatalIOError);
        }
    }

    file_ = resolveFile(fileEntry_, db().time().globalPath());

    // (A std::ifstream that was never opened is good(): is_open() is the
    // test of a missing file)
    std::ifstream is;
    if (isFile(file_))
    {
        is.open(file_.c_str());
    }
    if (!is.is_open() || !is.good())
    {
        FatalIOErrorInFunction(dict)
            << "Cannot open the fire history file " << file_
            << " (keyword 'file' \"" << fileEntry_.c_str() << "\""
            << (
                   isFile(file_) ? ": not readable"
                 : isDir(file_) ? ": a directory, not a file"
                 : ": no such file"
               )
            << ")" << nl
            << "    of boundary condition " << type() << " on patch '"
            << patch().name() << "' of field " << internalField().name()
            << nl << exit(FatalIOError);
    }
    is.close();

    history_.clear();

    // The common table reader (src/general/numericTable): malformed lines,
    // non-finite numbers and a file without data end in a FatalIOError
    // naming the file and line
    numericTable::settings s;
    s.separator = separator_;
    s.headerLines = headerLines_;
    s.numericColumns = labelList({timeColumn_, temperatureColumn_});
    s.roles.resize(max(timeColumn_, temperatureColumn_) + 1);
    s.roles[timeColumn_] = "a time";
    s.roles[temperatureColumn_] = "a temperature";
    s.columnsDescription =
        "timeColumn " + std::to_string(timeColumn_)
      + " and temperatureColumn " + std::to_string(temperatureColumn_);
    s.what = "the fire history file";
    s.context = describeSource();

    const numericTable table(file_, s);

    // Units, absolute zero, increasing times (in s: also for the table)
    forAll(table, rowi)
    {
        const label line = table.line(rowi);
        addRow
        (
            table.value(rowi, timeColumn_),
            table.value(rowi, temperatureColumn_),
            line,
            file_,
            line
        );
    }

    const label nHeader = table.nHeader();
    printSummary(nHeader);
}


void Foam::fireTemperatureFvPatchScalarField::readTable
(
    const dictionary& dict
)
{
    fileEntry_.clear();
    file_.clear();

    const entry& e = dict.lookupEntry("table", keyType::LITERAL);
    const label line = e.startLineNumber();

    checkedRead::checkNumbers
    (
        dict, "table",
        "(time temperature) rows in timeUnit and temperatureUnit, times"
        " increasing, e.g. ((0 20) (600 700))"
    );
    tableEntry_ = dict.get<List<Tuple2<scalar, scalar>>>("table");

    if (tableEntry_.empty())
    {
        FatalIOError(FUNCTION_NAME, __FILE__, __LINE__, dictName_, line)
            << "Empty 'table' of " << describeSource().c_str()
            << ": give at least one (time temperature) row" << nl
            << exit(FatalIOError);
    }

    history_.clear();

    forAll(tableEntry_, rowi)
    {
        addRow
        (
            tableEntry_[rowi].first(),
            tableEntry_[rowi].second(),
            rowi + 1,
            dictName_,
            line
        );
    }

    printSummary(0);
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
        "boundary condition " + type() + " on patch '" + patch().name()
      + "' of field " + internalField().name() + " with a fire law (fire,"
        " cooling); file, table and their keywords are the other form"
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


void Foam::fireTemperatureFvPatchScalarField::printSummary
(
    const label nHeader
) const
{
    const label n = history_.size();
    const scalarList& times = history_.times();
    const scalar Tmin = min(history_.temperatures());
    const scalar Tmax = max(history_.temperatures());
    const scalar off = temperatureUnit_ == "C" ? 273.15 : 0;

    OStringStream os;
    os.precision(10);
    os  << "fireTemperature on patch " << patch().name() << " of field "
        << internalField().name() << ": " << n << " row(s) from ";
    if (file_.size())
    {
        os  << file_ << " (lines " << history_.line(0) << " to "
            << history_.line(n - 1) << ", " << nHeader
            << " header line(s) skipped)";
    }
    else
    {
        os  << "the inline table";
    }
    os  << nl << "    time " << (times.first() + timeOffset_)/timeFactor()
        << " to " << (times.last() + timeOffset_)/timeFactor() << ' '
        << timeUnit_ << " in the " << (file_.size() ? "file" : "table")
        << ", t = " << times.first() << " to " << times.last()
        << " s (timeOffset " << timeOffset_ << " s); T = " << Tmin - off
        << " to " << Tmax - off << ' ' << temperatureUnit_ << " = " << Tmin
        << " to " << Tmax << " K; before the first time: " << beforeStart_
        << ", after the last: " << afterEnd_;

    Info<< os.str().c_str() << endl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fireTemperatureFvPatchScalarField::fireTemperatureFvPatchScalarField
(
    const fvPatch& p,
    const DimensionedField<scalar, volMesh>& iF
)
:
    fixedValueFvPatchScalarField(p, iF),
    fileEntry_(),
    tableEntry_(),
    timeColumn_(0),
    temperatureColumn_(1),
    separator_(','),
    headerLines_(-1),
    timeUnit_("s"),
    temperatureUnit_("C"),
    timeOffset_(0),
    beforeStart_("hold"),
    afterEnd_("hold"),
    fireDict_(),
    coolingDict_(),
    history_(),
    file_(),
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
    fileEntry_(),
    tableEntry_(),
    timeColumn_(0),
    temperatureColumn_(1),
    separator_(','),
    headerLines_(-1),
    timeUnit_("s"),
    temperatureUnit_("C"),
    timeOffset_(0),
    beforeStart_("hold"),
    afterEnd_("hold"),
    fireDict_(),
    coolingDict_(),
    history_(),
    file_(),
    dictName_(dict.name()),
    dictLine_(dict.startLineNumber())
{
    if (dict.found("fire", keyType::LITERAL))
    {
        readLaw(dict);
        fvPatchScalarField::operator=(temperature(db().time().value()));
        return;
    }

    readKeywords(dict);

    const bool hasFile = dict.found("file", keyType::LITERAL);
    const bool hasTable = dict.found("table", keyType::LITERAL);

    if (hasFile == hasTable)
    {
        FatalIOErrorInFunction(dict)
            << (hasFile ? "Both" : "Neither") << " 'file' "
            << (hasFile ? "and" : "nor") << " 'table' given for boundary"
            << " condition " << type() << " on patch '" << p.name()
            << "' of field " << iF.name() << ": give one of them," << nl
            << "    file  \"<constant>/fire.csv\";   // CSV of time,"
            << " temperature" << nl
            << "    table ((0 20) (600 700) ...);   // (time temperature)"
            << nl << exit(FatalIOError);
    }

    if (hasFile)
    {
        readFile(dict);
    }
    else
    {
        readTable(dict);
    }

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
    fileEntry_(ptf.fileEntry_),
    tableEntry_(ptf.tableEntry_),
    timeColumn_(ptf.timeColumn_),
    temperatureColumn_(ptf.temperatureColumn_),
    separator_(ptf.separator_),
    headerLines_(ptf.headerLines_),
    timeUnit_(ptf.timeUnit_),
    temperatureUnit_(ptf.temperatureUnit_),
    timeOffset_(ptf.timeOffset_),
    beforeStart_(ptf.beforeStart_),
    afterEnd_(ptf.afterEnd_),
    fireDict_(ptf.fireDict_),
    coolingDict_(ptf.coolingDict_),
    history_(ptf.history_),
    file_(ptf.file_),
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
    fileEntry_(ptf.fileEntry_),
    tableEntry_(ptf.tableEntry_),
    timeColumn_(ptf.timeColumn_),
    temperatureColumn_(ptf.temperatureColumn_),
    separator_(ptf.separator_),
    headerLines_(ptf.headerLines_),
    timeUnit_(ptf.timeUnit_),
    temperatureUnit_(ptf.temperatureUnit_),
    timeOffset_(ptf.timeOffset_),
    beforeStart_(ptf.beforeStart_),
    afterEnd_(ptf.afterEnd_),
    fireDict_(ptf.fireDict_),
    coolingDict_(ptf.coolingDict_),
    history_(ptf.history_),
    file_(ptf.file_),
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
    fileEntry_(ptf.fileEntry_),
    tableEntry_(ptf.tableEntry_),
    timeColumn_(ptf.timeColumn_),
    temperatureColumn_(ptf.temperatureColumn_),
    separator_(ptf.separator_),
    headerLines_(ptf.headerLines_),
    timeUnit_(ptf.timeUnit_),
    temperatureUnit_(ptf.temperatureUnit_),
    timeOffset_(ptf.timeOffset_),
    beforeStart_(ptf.beforeStart_),
    afterEnd_(ptf.afterEnd_),
    fireDict_(ptf.fireDict_),
    coolingDict_(ptf.coolingDict_),
    history_(ptf.history_),
    file_(ptf.file_),
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
        const label rowi = before ? 0 : n - 1;
        const string source = file_.size() ? string(file_) : string(dictName_);
        const label line = file_.size() ? history_.line(rowi) : dictLine_;

        FatalIOError(FUNCTION_NAME, __FILE__, __LINE__, source, line)
            << "Time t = " << t << " s is "
            << (before ? "before the start" : "after the end")
            << " of the fire history, whose " << (before ? "first" : "last")
            << ' ' << (file_.size() ? "line" : "row") << ' '
            << history_.line(rowi) << " is at " << describeTime(rowi).c_str()
            << ", and " << (before ? "beforeStart" : "afterEnd")
            << " is 'error'" << nl
            << "    (set it to 'hold' to keep the "
            << (before ? "first" : "last") << " temperature, "
            << (before ? "or change the startTime or timeOffset"
                       : "extend the history or reduce endTime")
            << ")" << nl
            << "    in " << describeSource().c_str() << nl
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
        os.precision(oldPrecision);
        writeEntry("value", os);
        return;
    }

    if (file_.size())
    {
        os.writeEntry("file", fileEntry_);
        os.writeEntryIfDifferent<label>("timeColumn", 0, timeColumn_);
        os.writeEntryIfDifferent<label>
        (
            "temperatureColumn", 1, temperatureColumn_
        );
        if (separator_ == numericTable::whitespace)
        {
            os.writeEntry("separator", word("whitespace"));
        }
        else if (separator_ == numericTable::automatic)
        {
            os.writeEntry("separator", word("auto"));
        }
        else if (separator_ == '\t')
        {
            os.writeEntry("separator", word("tab"));
        }
        else if (separator_ != ',')
        {
            os.writeEntry("separator", string(std::string(1, separator_)));
        }
        if (headerLines_ >= 0)
        {
            os.writeEntry("headerLines", headerLines_);
        }
    }
    else
    {
        os.writeEntry("table", tableEntry_);
    }

    os.writeEntry("timeUnit", timeUnit_);
    os.writeEntry("temperatureUnit", temperatureUnit_);
    os.writeEntryIfDifferent<scalar>("timeOffset", 0, timeOffset_);
    os.writeEntryIfDifferent<word>("beforeStart", "hold", beforeStart_);
    os.writeEntryIfDifferent<word>("afterEnd", "hold", afterEnd_);

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
