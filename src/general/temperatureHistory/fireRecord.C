/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "fireRecord.H"
#include "checkedRead.H"
#include "numericTable.H"
#include "OSspecific.H"
#include "OStringStream.H"
#include "Ostream.H"

#include <cmath>
#include <fstream>
#include <limits>

// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::wordList Foam::fireRecord::keywords()
{
    return wordList
    ({
        "file", "table", "timeColumn", "temperatureColumn", "separator",
        "headerLines", "timeUnit", "temperatureUnit", "timeOffset"
    });
}


Foam::word Foam::fireRecord::choice
(
    const dictionary& dict,
    const word& key,
    const word& deflt,
    const wordList& choices,
    const std::string& what
)
{
    const word w = dict.getOrDefault<word>(key, deflt);
    if (!choices.found(w))
    {
        FatalIOErrorInFunction(dict)
            << "Keyword '" << key << "' = " << w << what.c_str()
            << " is not one of the valid choices " << choices << nl
            << exit(FatalIOError);
    }
    return w;
}


Foam::fileName Foam::fireRecord::resolveFile
(
    const fileName& given,
    const fileName& directory
)
{
    fileName f(given);
    f.expand();
    if (!f.isAbsolute())
    {
        f = directory/f;
    }
    f.clean();
    return f;
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::fireRecord::readKeywords(const dictionary& dict)
{
    // Common tail of the keyword errors
    const std::string where(" in the entry of " + owner_);

    // Columns (count from 0)
    timeColumn_ = checkedRead::getLabelOrDefault(dict, "timeColumn", 0, 0);
    temperatureColumn_ =
        checkedRead::getLabelOrDefault(dict, "temperatureColumn", 1, 0);
    if (timeColumn_ == temperatureColumn_)
    {
        FatalIOErrorInFunction(dict)
            << "Keywords 'timeColumn' and 'temperatureColumn' are both "
            << timeColumn_ << where.c_str()
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
                << "Keyword 'separator' = " << tok << where.c_str()
                << " is not valid: give one character in quotes"
                << " (\",\" \";\"), tab, whitespace (runs of spaces and"
                << " tabs), or auto (per line: ',' if it has one, else ';',"
                << " else whitespace)" << nl
                << exit(FatalIOError);
        }
    }

    // Header lines (omit it to skip the non-numeric lines at the top)
    headerLines_ = -1;
    if (dict.found("headerLines"))
    {
        headerLines_ = checkedRead::getLabel(dict, "headerLines", 0);
    }

    timeUnit_ = choice(dict, "timeUnit", "s", wordList({"s", "min", "h"}), where);
    temperatureUnit_ =
        choice(dict, "temperatureUnit", "C", wordList({"C", "K"}), where);

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
            << "Keyword 'timeOffset' = " << timeOffset_ << where.c_str()
            << " is not a finite number of seconds below "
            << 0.25*std::numeric_limits<scalar>::max() << " in magnitude"
            << nl
            << exit(FatalIOError);
    }
}


void Foam::fireRecord::addRow
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


void Foam::fireRecord::readFile
(
    const dictionary& dict,
    const fileName& directory
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
                << "Keyword 'file' = " << tok << " of " << owner_.c_str()
                << " is not a file name (give it in quotes: "
                << "file \"<constant>/fire.csv\";)" << nl
                << exit(FatalIOError);
        }
    }

    file_ = resolveFile(fileEntry_, directory);

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
            << "    of " << owner_.c_str()
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
    s.twoColumns
    (
        "timeColumn", timeColumn_, "a time",
        "temperatureColumn", temperatureColumn_, "a temperature"
    );
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

    nHeader_ = table.nHeader();
}


void Foam::fireRecord::readTable(const dictionary& dict)
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

    nHeader_ = 0;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fireRecord::fireRecord()
:
    fileEntry_(),
    tableEntry_(),
    timeColumn_(0),
    temperatureColumn_(1),
    separator_(','),
    headerLines_(-1),
    timeUnit_("s"),
    temperatureUnit_("C"),
    timeOffset_(0),
    history_(),
    nHeader_(0),
    owner_(),
    file_(),
    dictName_()
{}


Foam::fireRecord::fireRecord
(
    const dictionary& dict,
    const fileName& directory,
    const std::string& owner
)
:
    fireRecord()
{
    owner_ = owner;
    dictName_ = dict.name();

    readKeywords(dict);

    const bool hasFile = dict.found("file", keyType::LITERAL);
    const bool hasTable = dict.found("table", keyType::LITERAL);

    if (hasFile == hasTable)
    {
        FatalIOErrorInFunction(dict)
            << (hasFile ? "Both" : "Neither") << " 'file' "
            << (hasFile ? "and" : "nor") << " 'table' given for "
            << owner_.c_str() << ": give one of them," << nl
            << "    file  \"<constant>/fire.csv\";   // CSV of time,"
            << " temperature" << nl
            << "    table ((0 20) (600 700) ...);   // (time temperature)"
            << nl << exit(FatalIOError);
    }

    if (hasFile)
    {
        readFile(dict, directory);
    }
    else
    {
        readTable(dict);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::fireRecord::timeFactor() const
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


Foam::scalar Foam::fireRecord::kelvin(const scalar theta) const
{
    return temperatureUnit_ == "C" ? theta + 273.15 : theta;
}


Foam::string Foam::fireRecord::describeSource() const
{
    OStringStream os;
    os  << "the fire history of " << owner_.c_str();
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


Foam::string Foam::fireRecord::describeTime(const label rowi) const
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


Foam::string Foam::fireRecord::summary() const
{
    const label n = history_.size();
    const scalarList& times = history_.times();
    const scalar Tmin = min(history_.temperatures());
    const scalar Tmax = max(history_.temperatures());
    const scalar off = kelvin(0);

    OStringStream os;
    os.precision(10);
    os  << n << " row(s) from ";
    if (file_.size())
    {
        os  << file_ << " (lines " << history_.line(0) << " to "
            << history_.line(n - 1) << ", " << nHeader_
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
        << " to " << Tmax << " K";
    return os.str();
}


void Foam::fireRecord::write(Ostream& os) const
{
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
}


// ************************************************************************* //
