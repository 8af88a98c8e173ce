/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "checkedRead.H"
#include "PstreamReduceOps.H"
#include "OStringStream.H"
#include "token.H"
#include "HashTable.H"
#include "HashSet.H"
#include "entry.H"
#include "IOdictionary.H"
#include "IFstream.H"
#include "wordRe.H"
#include "dictionaryEntry.H"
#include "primitiveEntry.H"
#include "ISstream.H"
#include "OSspecific.H"
#include "Pstream.H"
#include "stringOps.H"
#include "Time.H"
#include "TableBase.H"

#include <cctype>
#include <cfenv>
#include <cmath>
#include <vector>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

//- The value of an entry as written, for error messages: its tokens, or
//  "a sub-dictionary"
Foam::string entryText(const Foam::entry& e)
{
    using namespace Foam;
    OStringStream os;
    if (e.isDict())
    {
        os  << "a sub-dictionary";
    }
    else
    {
        const tokenList& tokens = static_cast<const tokenList&>(e.stream());
        forAll(tokens, i)
        {
            os  << (i ? " " : "") << tokens[i];
        }
    }
    return os.str();
}


//- Start the FatalIOError of an unknown keyword, e, of dict: the file and
//  line, the function that found it (checkKeywords, checkNearMisses),
//  "Unknown keyword 'key' (line N)"; the caller ends the message
void unknownKeywordHead
(
    const char* function,
    const int sourceLine,
    const Foam::dictionary& dict,
    const Foam::entry& e
)
{
    using namespace Foam;
    const label line = e.startLineNumber();
    FatalIOError
    (
        function, __FILE__, sourceLine, dict.name(), line > 0 ? line : -1, -1
    )   << "Unknown keyword '" << e.keyword() << "'";
    if (line > 0)
    {
        FatalIOError << " (line " << line << ")";
    }
}


//- FatalIOError: keyword missing from dict, with what was expected and a
//  near miss among the keywords given (a misspelt keyword) if there is one
void missingKeyword
(
    const Foam::dictionary& dict,
    const Foam::word& keyword,
    const Foam::string& expected
)
{
    using namespace Foam;
    const word near(checkedRead::nearest(keyword, dict.toc()));
    string nearText;
    if
    (
        near.size() && near != "FoamFile"
     && checkedRead::editDistance(near, keyword)
     <= max(2, label(keyword.size())/4)
    )
    {
        nearText =
            " (found '" + near + "': a misspelling of '" + keyword + "'?)";
    }
    FatalIOErrorInFunction(dict)
        << "Missing keyword '" << keyword << "' in dictionary "
        << dict.name() << ": expected " << expected.c_str()
        << nearText.c_str() << nl << exit(FatalIOError);
}


//- Holds the floating-point environment (traps and flags) and OpenFOAM's
//  global input mode while a file is parsed; restores both when it goes
//  out of scope, also when the parse throws (FatalIOError throws when
//  throwExceptions() is set, as in hearthFit's forward runs). A number
//  that overflows (1e400) raises FE_OVERFLOW in strtod, which OpenFOAM
//  traps (SIGFPE): the traps are held (the inf read is then refused by
//  checkNumbers, or by the reader of the entry). std::feholdexcept/fesetenv
//  rather than OpenFOAM's sigFpe::ignore: they restore the environment as
//  it was (whoever enabled the traps, e.g. a unit test) and clear the
//  parse's overflow flag, which sigFpe::ignore leaves raised when it
//  enables the traps again. An #inputMode directive of the file sets the
//  global input mode: restored, as OpenFOAM's top-level reads do.
class parseGuard
{
    std::fenv_t fenv_;
    const Foam::entry::inputMode mode_;

public:

    parseGuard()
    :
        mode_(Foam::entry::globalInputMode)
    {
        std::feholdexcept(&fenv_);
    }

    ~parseGuard()
    {
        Foam::entry::globalInputMode = mode_;
        std::fesetenv(&fenv_);
    }

    parseGuard(const parseGuard&) = delete;
    void operator=(const parseGuard&) = delete;
};


void readScope
(
    Foam::dictionary& d,
    Foam::ISstream& is,
    const bool sub,
    const Foam::fileName& file,
    const Foam::string& scope
);


//- #include "file" (mandatory) or #includeIfPresent "file" read from is
//  into d: the file named as OpenFOAM's includeEntry names it ($variables
//  and environment expanded, relative to the including file's directory)
//  and read by readScope, so that a keyword given twice in the included
//  file is refused in that file's name (recursively: its own #includes
//  likewise)
void includeFile
(
    Foam::dictionary& d,
    Foam::ISstream& is,
    const bool mandatory,
    const Foam::string& scope
)
{
    using namespace Foam;
    fileName name(is);
    stringOps::inplaceExpand(name, d, true, true);
    if (!name.empty() && !name.isAbsolute())
    {
        name = is.name().path()/name;
    }
    IFstream ifs(name);
    if (!ifs.good())
    {
        if (mandatory)
        {
            FatalIOErrorInFunction(is)
                << "Cannot open include file " << name
                << " while reading dictionary " << d.name()
                << exit(FatalIOError);
        }
        return;
    }
    // An included file's FoamFile header is not an entry (as in OpenFOAM)
    const bool header = d.found("FoamFile", keyType::LITERAL);
    readScope(d, ifs, false, ifs.name(), scope);
    if (!header)
    {
        d.remove("FoamFile");
    }
}


//- Read the entries of d from is, up to its closing '}' (sub) or the end
//  of the file, as dictionary::read does (entry::New for the directives
//  and the $substitutions; #include and #includeIfPresent by includeFile)
//  but refusing a keyword written twice in one scope: FatalIOError naming
//  the file, the keyword, the scope and both lines. An entry brought in by
//  #include or $sub may be overridden, as in OpenFOAM (only the lines of
//  one file are compared), and a keyword removed by #remove may be set
//  again
void readScope
(
    Foam::dictionary& d,
    Foam::ISstream& is,
    const bool sub,
    const Foam::fileName& file,
    const Foam::string& scope
)
{
    using namespace Foam;
    HashTable<label> lines;     // the line of each keyword of this scope

    while (true)
    {
        // The next token, spurious ';' skipped (as entry::getKeyword)
        token tok;
        do
        {
            if (is.read(tok).bad() || is.eof() || !tok.good())
            {
                if (sub)
                {
                    FatalIOErrorInFunction(is)
                        << "Unexpected end of file in sub-dictionary '"
                        << scope.c_str() << "' of " << file
                        << ": a '}' is missing" << exit(FatalIOError);
                }
                return;
            }
        }
        while (tok == token::END_STATEMENT);

        if (tok == token::END_BLOCK)
        {
            if (!sub)
            {
                FatalIOErrorInFunction(is)
                    << "Unexpected '}' in " << file << exit(FatalIOError);
            }
            return;
        }

        // A plain keyword (a word not a #directive, or a quoted pattern);
        // scoped keywords (a/b) as OpenFOAM reads them
        const bool plain =
        (
            (tok.isWord() && tok.wordToken()[0] != token::HASH)
         || tok.type() == token::tokenType::STRING
        );
        keyType key;
        if (tok.isWord())
        {
            key = tok.wordToken();
        }
        else if (plain)
        {
            key = tok.stringToken();
        }
        if
        (
            tok.isWord()
         && (
                tok.wordToken() == "#include"
             || tok.wordToken() == "#includeIfPresent"
            )
        )
        {
            includeFile(d, is, tok.wordToken() == "#include", scope);
            continue;
        }
        if (!plain || key.find('/') != std::string::npos)
        {
            is.putBack(tok);
            if
            (
                !entry::New
                (
                    d, is, entry::inputMode::MERGE, sub ? token::END_BLOCK : 0
                )
            )
            {
                return;
            }
            // A keyword the directive removed (#remove) may be set again
            for (const word& k : lines.toc())
            {
                if (!d.found(k, keyType::LITERAL))
                {
                    lines.erase(k);
                }
            }
            continue;
        }

        const label line = tok.lineNumber();
        const auto first = lines.cfind(key);
        if (first.found())
        {
            FatalIOError
            (
                FUNCTION_NAME, __FILE__, __LINE__, file, line, -1
            )   << "Keyword '" << key << "' given twice in "
                << (
                       scope.empty()
                     ? string("the top level")
                     : string("sub-dictionary '" + scope + "'")
                   ).c_str()
                << " of " << file << ": at line " << *first
                << " and again at line " << line
                << " (duplicate entry: OpenFOAM would keep the last one"
                << " silently); give it once" << nl << exit(FatalIOError);
        }
        lines.insert(key, line);

        token next(is);
        if (next == token::BEGIN_BLOCK)
        {
            entry* e =
                d.add(new dictionaryEntry(key, d, dictionary()), true);
            readScope
            (
                e->dict(), is, true, file,
                scope.empty() ? string(key) : string(scope + '/' + key)
            );
            // A binary file: its FoamFile header says so
            if (!sub && key == "FoamFile" && e->dict().found("format"))
            {
                is.format(e->dict().get<word>("format"));
            }
        }
        else
        {
            is.putBack(next);
            d.add(new primitiveEntry(key, d, is), true);
        }
    }
}

//- The keywords the Function1 types of OpenFOAM (v1912) read from the
//  dictionary they are given besides the entry itself (TableBase:
//  outOfBounds, interpolationScheme; the others their coefficients)
const Foam::HashTable<Foam::wordList>& function1TypeKeywords()
{
    static const Foam::HashTable<Foam::wordList> typeKeys
    {
        {"table", {"outOfBounds", "interpolationScheme"}},
        {"tableFile", {"file", "outOfBounds", "interpolationScheme"}},
        {
            "csvFile",
            {
                "nHeaderLine", "refColumn", "componentColumns", "separator",
                "mergeSeparators", "file", "outOfBounds",
                "interpolationScheme"
            }
        },
        {"sine", {"t0", "amplitude", "frequency", "scale", "level"}},
        {
            "square",
            {"t0", "markSpace", "amplitude", "frequency", "scale", "level"}
        },
        {"scale", {"scale", "value"}},
        {"linearRamp", {"start", "duration"}},
        {"quadraticRamp", {"start", "duration"}},
        {"halfCosineRamp", {"start", "duration"}},
        {"quarterSineRamp", {"start", "duration"}},
        {"quarterCosineRamp", {"start", "duration"}}
    };
    return typeKeys;
}


//- The Function1 types of OpenFOAM that read their value from the entry
//  named as the Function1 in the dictionary they are given (Constant,
//  Uniform, Table, Polynomial: 'dict.lookup(entryName)')
bool function1ReadsEntry(const Foam::word& type)
{
    return
        type == "constant" || type == "uniform" || type == "table"
     || type == "polynomial";
}


} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

Foam::string Foam::validRange::str() const
{
    OStringStream os;
    os  << (lowerOpen ? "(" : "[");
    if (lower <= -GREAT) os << "-inf"; else os << lower;
    os  << ", ";
    if (upper >= GREAT) os << "inf"; else os << upper;
    os  << (upperOpen ? ")" : "]");
    return os.str();
}


Foam::validRange Foam::checkedRead::closed(const scalar l, const scalar u)
{
    return validRange{l, u, false, false};
}


Foam::validRange Foam::checkedRead::closedOpen(const scalar l, const scalar u)
{
    return validRange{l, u, false, true};
}


Foam::validRange Foam::checkedRead::positive()
{
    return validRange{0, GREAT, true, true};
}


Foam::validRange Foam::checkedRead::nonNegative()
{
    return validRange{0, GREAT, false, true};
}


void Foam::checkedRead::check
(
    const dictionary& dict,
    const word& keyword,
    const scalar value,
    const validRange& range
)
{
    if (!range.contains(value))
    {
        FatalIOErrorInFunction(dict)
            << "Keyword '" << keyword << "' = " << value
            << " is outside its valid range " << range.str().c_str()
            << " in dictionary " << dict.name() << nl
            << exit(FatalIOError);
    }
}


void Foam::checkedRead::checkNumbers
(
    const dictionary& dict,
    const word& keyword,
    const string& expected
)
{
    const entry* eptr = dict.findEntry(keyword, keyType::LITERAL);
    if (!eptr)
    {
        missingKeyword(dict, keyword, expected);
    }

    const label line = eptr->startLineNumber();
    auto bad = [&](const string& found)
    {
        FatalIOError
        (
            FUNCTION_NAME, __FILE__, __LINE__, dict.name(),
            line > 0 ? line : -1, -1
        )   << "Keyword '" << keyword << "' in dictionary " << dict.name()
            << " holds " << found.c_str() << ", not a finite number"
            << " (nan and inf are not accepted): expected "
            << expected.c_str() << nl << exit(FatalIOError);
    };

    if (eptr->isDict())
    {
        bad("a sub-dictionary");
    }
    for (const token& tok : static_cast<const tokenList&>(eptr->stream()))
    {
        if (tok.isNumber())
        {
            if (!std::isfinite(tok.number()))
            {
                OStringStream os;
                os  << tok.number();
                bad("'" + os.str() + "'");
            }
        }
        else if (!tok.isPunctuation())
        {
            OStringStream os;
            os  << tok;
            bad("'" + os.str() + "'");
        }
    }
}


Foam::scalarList Foam::checkedRead::getList
(
    const dictionary& dict,
    const word& keyword,
    const validRange& range,
    const string& expected
)
{
    checkNumbers(dict, keyword, expected);
    const scalarList values(dict.get<scalarList>(keyword));
    for (const scalar x : values)
    {
        check(dict, keyword, x, range);
    }
    return values;
}


Foam::label Foam::checkedRead::editDistance
(
    const std::string& a,
    const std::string& b
)
{
    const size_t n = a.size();
    const size_t m = b.size();
    auto eq = [&](const size_t i, const size_t j)
    {
        return
            std::tolower(static_cast<unsigned char>(a[i]))
         == std::tolower(static_cast<unsigned char>(b[j]));
    };

    std::vector<std::vector<label>> d(n + 1, std::vector<label>(m + 1, 0));
    for (size_t i = 0; i <= n; ++i) d[i][0] = i;
    for (size_t j = 0; j <= m; ++j) d[0][j] = j;
    for (size_t i = 1; i <= n; ++i)
    {
        for (size_t j = 1; j <= m; ++j)
        {
            const label cost = eq(i - 1, j - 1) ? 0 : 1;
            d[i][j] =
                min
                (
                    min(d[i - 1][j] + 1, d[i][j - 1] + 1),
                    d[i - 1][j - 1] + cost
                );
            if
            (
                i > 1 && j > 1 && eq(i - 1, j - 2) && eq(i - 2, j - 1)
            )
            {
                d[i][j] = min(d[i][j], d[i - 2][j - 2] + 1);
            }
        }
    }
    return d[n][m];
}


Foam::word Foam::checkedRead::nearest
(
    const word& key,
    const wordList& candidates
)
{
    word best;
    label bestDist = labelMax;
    label bestCase = labelMax;
    for (const word& c : candidates)
    {
        const label dist = editDistance(key, c);
        label caseDiffs = 0;
        for (size_t i = 0; i < min(key.size(), c.size()); ++i)
        {
            caseDiffs += (key[i] != c[i]);
        }
        if (dist < bestDist || (dist == bestDist && caseDiffs < bestCase))
        {
            best = c;
            bestDist = dist;
            bestCase = caseDiffs;
        }
    }
    return best;
}


namespace Foam
{
namespace checkedRead
{
    //- The sub-dictionaries of dict named after it, at any depth
    static void nameSubDicts(const dictionary& dict)
    {
        for (const entry& e : dict)
        {
            if (e.isDict())
            {
                // (a name is metadata; the dictionary was not created
                // const)
                const_cast<dictionary&>(e.dict()).name() =
                    dict.name() + '.' + e.keyword();
                nameSubDicts(e.dict());
            }
        }
    }
}
}


void Foam::checkedRead::nameAfterFile(const IOdictionary& dict)
{
    // The file, looked up on every rank (with a master-slave file handler
    // the lookup is collective); IOstream::staticName_ is the name of a
    // stream without a file
    const fileName file(dict.globalFilePath(dict.type()));
    if (file.size() && dict.dictionary::name() == "IOstream")
    {
        const_cast<IOdictionary&>(dict).dictionary::name() = file;
        nameSubDicts(dict);
    }
}


void Foam::checkedRead::checkKeywords
(
    const dictionary& dict,
    const wordList& allowed,
    const string& where
)
{
    // A keyword given twice: OpenFOAM kept the last one silently
    checkDuplicates(dict);

    for (const entry& e : dict)
    {
        const keyType& key = e.keyword();
        if (key == "FoamFile" || allowed.found(key))
        {
            continue;
        }
        if (key.isPattern())
        {
            // A regular expression: valid if it names a valid keyword
            const wordRe re(key, wordRe::REGEX);
            bool matches = false;
            for (const word& k : allowed)
            {
                matches = matches || re.match(k);
            }
            if (matches)
            {
                continue;
            }
        }

        const word near(nearest(key, allowed));
        unknownKeywordHead(FUNCTION_NAME, __LINE__, dict, e);
        FatalIOError << " in dictionary " << dict.name();
        if (where.size())
        {
            FatalIOError << " (" << where.c_str() << ")";
        }
        if (near.size())
        {
            FatalIOError << ": did you mean '" << near << "'?";
        }
        // The valid keywords once each, in their order
        wordHashSet seen;
        OStringStream valid;
        for (const word& k : allowed)
        {
            if (seen.insert(k))
            {
                valid << ' ' << k;
            }
        }
        FatalIOError
            << nl << "    Valid keywords:" << valid.str().c_str() << nl
            << exit(FatalIOError);
    }
}


void Foam::checkedRead::checkNearMisses
(
    const dictionary& dict,
    const wordList& ours,
    const wordList& others
)
{
    for (const entry& e : dict)
    {
        const keyType& key = e.keyword();
        if
        (
            key.isPattern() || key == "FoamFile"
         || ours.found(key) || others.found(key)
        )
        {
            continue;
        }
        word near(nearest(key, ours));
        if (near.size() && editDistance(key, near) > nearMissDistance)
        {
            // Or a truncation of one of ours ('maxDeltaTemp' for
            // maxDeltaTemperature): at least 8 characters, letter case
            // ignored
            near.clear();
            for (const word& k : ours)
            {
                if
                (
                    key.size() >= 8 && key.size() < k.size()
                 && editDistance(key, k.substr(0, key.size())) == 0
                )
                {
                    near = k;
                    break;
                }
            }
        }
        if (near.empty())
        {
            // Far from all of ours: the user's own entry
            continue;
        }
        unknownKeywordHead(FUNCTION_NAME, __LINE__, dict, e);
        FatalIOError
            << " in " << dict.name() << ": did you mean '" << near << "'?"
            << " (OpenFOAM ignores an unknown entry, the default of '"
            << near << "' would be used)" << nl << exit(FatalIOError);
    }
}


Foam::wordList Foam::checkedRead::controlDictKeywords()
{
    return wordList
    ({
        "application", "startFrom", "startTime", "stopAt", "endTime",
        "deltaT", "writeControl", "writeInterval", "writeFrequency",
        "purgeWrite", "writeFormat", "writePrecision", "writeCompression",
        "writeVersion", "timeFormat", "timePrecision", "graphFormat",
        "runTimeModifiable", "adjustTimeStep", "maxCo", "maxAlphaCo",
        "maxDi", "maxDeltaT", "functions", "libs", "DebugSwitches",
        "InfoSwitches", "OptimisationSwitches", "DimensionedConstants",
        "DimensionSets", "Documentation", "profiling", "fileHandler",
        "cacheTemporaryObjects"
    });
}


Foam::wordList Foam::checkedRead::fvSolutionKeywords()
{
    return wordList
    ({
        "solvers", "relaxationFactors", "cache", "select", "PIMPLE",
        "SIMPLE", "PISO", "potentialFlow", "stressAnalysis"
    });
}


Foam::wordList Foam::checkedRead::function1Keywords
(
    const dictionary& dict,
    const word& key
)
{
    const word coeffsName(key + "Coeffs");
    wordList keys({key, coeffsName});

    const entry* eptr = dict.findEntry(key, keyType::LITERAL);
    if (!eptr || eptr->isDict() || dict.isDict(coeffsName))
    {
        return keys;
    }

    // Inline form 'key <type> ...': the type reads its coefficients from
    // dict itself (Function1<Type>::New: dict.optionalSubDict(keyCoeffs))
    const tokenList& tokens = static_cast<const tokenList&>(eptr->stream());
    if (tokens.empty() || !tokens.first().isWord())
    {
        return keys;
    }
    const word type(tokens.first().wordToken());

    const HashTable<wordList>& typeKeys = function1TypeKeywords();
    const auto iter = typeKeys.cfind(type);
    if (iter.found())
    {
        keys.append(iter.val());
    }
    return keys;
}


void Foam::checkedRead::checkFunction1Coeffs
(
    const dictionary& dict,
    const word& key,
    const string& where
)
{
    const word coeffsName(key + "Coeffs");
    const entry* eptr = dict.findEntry(key, keyType::LITERAL);
    if (!eptr || eptr->isDict() || !dict.isDict(coeffsName))
    {
        return;
    }
    const dictionary& coeffs = dict.subDict(coeffsName);
    const tokenList& tokens = static_cast<const tokenList&>(eptr->stream());
    const string context
    (
        (where.empty() ? string() : where + ": ")
      + "the coefficients " + coeffsName + " of '" + key + " "
      + (
            tokens.size() && tokens.first().isWord()
          ? tokens.first().wordToken() : word("<value>")
        )
      + " ...'"
    );
    if (tokens.empty() || !tokens.first().isWord())
    {
        // 'key <value>': a constant read from the line, keyCoeffs unread
        FatalIOErrorInFunction(coeffs)
            << "Sub-dictionary " << coeffsName << " in " << dict.name()
            << " is not read: '" << key << "' is given as a value on its"
            << " line (a constant); remove " << coeffsName << " ("
            << context.c_str() << ")" << exit(FatalIOError);
    }
    const word type(tokens.first().wordToken());
    const HashTable<wordList>& typeKeys = function1TypeKeywords();
    if (!typeKeys.found(type) && !function1ReadsEntry(type))
    {
        // A type without coefficients (zero, one) or one this list does
        // not know: left to OpenFOAM
        return;
    }
    wordList valid;
    if (function1ReadsEntry(type))
    {
        // Given keyCoeffs, OpenFOAM reads the whole entry again from it
        // ('key type value;' inside keyCoeffs), not from the line
        valid.append(key);
        if (!coeffs.found(key, keyType::LITERAL))
        {
            FatalIOErrorInFunction(coeffs)
                << "Missing keyword '" << key << "' in " << coeffs.name()
                << ": with " << coeffsName << " given, Function1 type "
                << type << " reads '" << key << " " << type << " ...;'"
                << " from it, not from the line in " << dict.name()
                << "; remove " << coeffsName << " (" << context.c_str()
                << ")" << exit(FatalIOError);
        }
    }
    if (typeKeys.found(type))
    {
        valid.append(typeKeys[type]);
    }
    checkKeywords(coeffs, valid, context);
}


void Foam::checkedRead::checkAirTemperature
(
    const fileName& file,
    const word& keyword,
    const scalar T,
    const scalar t,
    const string& where
)
{
    if (T > 0 && T >= minAirTemperature)
    {
        return;
    }
    FatalIOError(FUNCTION_NAME, __FILE__, __LINE__, file, -1, -1)
        << "Keyword '" << keyword << "' = " << T << " K (time " << t
        << ") of " << where.c_str();
    if (!(T > 0))
    {
        FatalIOError
            << " is outside its valid range (0, inf) K";
    }
    else
    {
        FatalIOError
            << " is below " << minAirTemperature << " K: temperatures are"
            << " in kelvin; was it typed in degrees Celsius (" << T
            << " C = " << T + 273.15 << " K)? Valid range ["
            << minAirTemperature << ", inf) K";
    }
    FatalIOError << nl << exit(FatalIOError);
}


Foam::scalarList Foam::checkedRead::function1CheckTimes
(
    const Function1<scalar>& f,
    const Time& runTime,
    const label nSamples
)
{
    const scalar t0 = runTime.timeToUserTime(runTime.startTime().value());
    const scalar t1 =
        max(t0, runTime.timeToUserTime(runTime.endTime().value()));

    DynamicList<scalar> times;
    times.append(t0);
    const auto* table =
        dynamic_cast<const Function1Types::TableBase<scalar>*>(&f);
    if (table)
    {
        times.append(table->x());
    }
    else
    {
        for (label i = 1; i < nSamples; ++i)
        {
            times.append(t0 + (t1 - t0)*i/nSamples);
        }
    }
    times.append(t1);
    return scalarList(std::move(times));
}


Foam::dictionary Foam::checkedRead::readDictionary(const fileName& file)
{
    if (!isFile(file))
    {
        FatalErrorInFunction
            << "Cannot read the dictionary " << file << nl
            << exit(FatalError);
    }
    IFstream is(file);
    return dictionary(is);
}


Foam::dictionary Foam::checkedRead::readWithoutDuplicates(const fileName& file)
{
    IFstream is(file);
    if (!is.good())
    {
        FatalErrorInFunction
            << "Cannot open the file " << file << nl << exit(FatalError);
    }
    dictionary dict;
    dict.name() = is.name();

    {
        const parseGuard guard;     // traps and input mode, restored
        readScope(dict, is, false, dict.name(), "");
    }

    dict.remove("FoamFile");
    return dict;
}


bool Foam::checkedRead::presentOnEveryRank
(
    regIOobject& io,
    const string& what,
    const string& remedy
)
{
    const bool present = io.headerOk();
    if
    (
        returnReduce(present, orOp<bool>())
     != returnReduce(present, andOp<bool>())
    )
    {
        FatalErrorInFunction
            << "The " << what.c_str() << " " << io.objectPath() << " is "
            << (present ? "here" : "missing") << " but not on every"
            << " processor: restore it from the run's copy, or "
            << remedy.c_str() << exit(FatalError);
    }
    return present;
}


void Foam::checkedRead::checkDuplicates(const dictionary& dict)
{
    // The file of dict: its name, or the name of its top-level dictionary
    // (a sub-dictionary is named file.sub.subsub); in a parallel run a
    // dictionary of constant/ or system/ is named in processorN/ but read
    // from the case
    fileName file(dict.name());
    auto fileOf = [](fileName name)
    {
        while (name.size() && !isFile(name))
        {
            const auto dot = name.rfind('.');
            const auto slash = name.rfind('/');
            if
            (
                dot == std::string::npos
             || (slash != std::string::npos && dot < slash)
            )
            {
                return fileName();
            }
            name.resize(dot);
        }
        return name;
    };
    fileName found(fileOf(file));
    if (found.empty() && Pstream::parRun())
    {
        const string proc
        (
            "/processor" + Foam::name(Pstream::myProcNo()) + "/"
        );
        const auto pos = file.find(proc);
        if (pos != std::string::npos)
        {
            file.replace(pos, proc.size(), "/");
            found = fileOf(file);
        }
    }
    if (found.empty())
    {
        return;     // not read from a file
    }

    // Each file once while it is unchanged (checkKeywords checks every
    // sub-dictionary of it)
    static HashTable<double, fileName> checked;
    const double modified = highResLastModified(found);
    const auto iter = checked.cfind(found);
    if (iter.found() && *iter == modified)
    {
        return;
    }
    checked.set(found, modified);
    readWithoutDuplicates(found);
}


Foam::wordList Foam::checkedRead::patchFieldKeywords()
{
    return wordList({"type", "value", "patchType"});
}


Foam::wordList Foam::checkedRead::functionObjectKeywords()
{
    return wordList
    ({
        "type", "libs", "functionObjectLibs", "region", "subRegion",
        "enabled", "log", "timeStart", "timeEnd", "controlMode",
        "triggerStart", "triggerEnd", "executeControl", "executeInterval",
        "writeControl", "writeInterval", "outputControl", "outputInterval",
        "deltaTCoeff", "nStepsToStartTimeChange"
    });
}


void Foam::checkedRead::check
(
    const fileName& fieldFile,
    const word& fieldName,
    const scalarField& values,
    const validRange& range
)
{
    forAll(values, celli)
    {
        if (!range.contains(values[celli]))
        {
            dictionary fieldDict;
            fieldDict.name() = fieldFile;
            FatalIOErrorInFunction(fieldDict)
                << "Field '" << fieldName << "' (keyword 'internalField')"
                << " = " << values[celli] << " in cell " << celli
                << " is outside its valid range " << range.str().c_str()
                << " in file " << fieldFile << nl
                << exit(FatalIOError);
        }
    }
}


void Foam::checkedRead::checkDimensions
(
    const fileName& fieldFile,
    const word& fieldName,
    const dimensionSet& found,
    const dimensionSet& expected
)
{
    if (found != expected)
    {
        dictionary fieldDict;
        fieldDict.name() = fieldFile;
        FatalIOErrorInFunction(fieldDict)
            << "Field '" << fieldName << "' (keyword 'dimensions') = "
            << found << " in file " << fieldFile << ": expected "
            << expected << nl << exit(FatalIOError);
    }
}


Foam::dimensionedScalar Foam::checkedRead::get
(
    const dictionary& dict,
    const word& keyword,
    const dimensionSet& dims,
    const validRange& range
)
{
    if (!dict.found(keyword))
    {
        OStringStream expected;
        expected
            << "a value with dimensions " << dims << " in the range "
            << range.str().c_str();
        missingKeyword(dict, keyword, expected.str());
    }

    // The value must be a finite number: 'nan' or 'inf' are words to the
    // tokeniser, which dimensioned<scalar> would take for a name and then
    // fail with 'attempt to read beyond EOF'
    {
        const entry& e = *dict.findEntry(keyword, keyType::REGEX);
        tokenList tokens;
        if (e.isStream())
        {
            tokens = static_cast<const tokenList&>(e.stream());
        }
        if
        (
            e.isDict() || tokens.empty()
         || !tokens.last().isNumber()
         || !std::isfinite(tokens.last().number())
        )
        {
            FatalIOError
            (
                FUNCTION_NAME, __FILE__, __LINE__, dict.name(),
                e.startLineNumber(), -1
            )   << "Keyword '" << keyword << "' = " << entryText(e).c_str()
                << " in dictionary " << dict.name()
                << " is not a finite number (nan and inf are not accepted):"
                << " expected a value"
                << (dims.dimensionless() ? "" : " (dimensions optional)")
                << " in the range " << range.str().c_str() << nl
                << exit(FatalIOError);
        }
    }

    // Dimensions are optional in the file. Read them unchecked, so that a
    // mismatch ends in a FatalIOError naming the keyword and the valid
    // range rather than in the abort of dimensioned<Type>::initialize
    bool hasDims = false;
    for (const token& tok : dict.lookup(keyword))
    {
        if (tok == token::BEGIN_SQR)
        {
            hasDims = true;
            break;
        }
    }

    dimensionedScalar value(keyword, dict);

    if (hasDims && value.dimensions() != dims)
    {
        FatalIOErrorInFunction(dict)
            << "Keyword '" << keyword << "' has dimensions "
            << value.dimensions() << " in dictionary " << dict.name()
            << ": expected dimensions " << dims
            << " (or none) and a value in the range "
            << range.str().c_str() << nl
            << exit(FatalIOError);
    }
    value.dimensions().reset(dims);

    check(dict, keyword, value.value(), range);
    return value;
}


Foam::dimensionedScalar Foam::checkedRead::getOrDefault
(
    const dictionary& dict,
    const word& keyword,
    const dimensionSet& dims,
    const scalar deflt,
    const validRange& range
)
{
    if (!dict.found(keyword))
    {
        return dimensionedScalar(keyword, dims, deflt);
    }
    return get(dict, keyword, dims, range);
}

Foam::label Foam::checkedRead::getLabel
(
    const dictionary& dict,
    const word& keyword,
    const label lower,
    const label upper
)
{
    OStringStream rangeOs;
    rangeOs << "[" << lower << ", ";
    if (upper == labelMax) rangeOs << "inf)"; else rangeOs << upper << "]";
    const string range(rangeOs.str());

    const entry* eptr = dict.findEntry(keyword, keyType::REGEX);
    if (!eptr)
    {
        missingKeyword(dict, keyword, "a whole number in the range " + range);
    }

    tokenList tokens;
    if (eptr->isStream())
    {
        tokens = static_cast<const tokenList&>(eptr->stream());
    }

    // A whole number: a label token, or a finite number without fraction
    // (1e3) within the range of label
    bool whole = !eptr->isDict() && tokens.size() == 1;
    label value = 0;
    if (whole && tokens[0].isLabel())
    {
        value = tokens[0].labelToken();
    }
    else if (whole && tokens[0].isNumber())
    {
        const scalar x = tokens[0].number();
        whole =
            std::isfinite(x) && x == std::floor(x)
         && x >= scalar(labelMin) && x <= scalar(labelMax);
        value = whole ? label(x) : 0;
    }
    else
    {
        whole = false;
    }

    const label line = eptr->startLineNumber();
    if (!whole)
    {
        FatalIOError
        (
            FUNCTION_NAME, __FILE__, __LINE__, dict.name(),
            line > 0 ? line : -1, -1
        )   << "Keyword '" << keyword << "' = " << entryText(*eptr).c_str()
            << " in dictionary " << dict.name()
            << " is not a whole number: expected a whole number in the range "
            << range.c_str() << nl << exit(FatalIOError);
    }
    if (value < lower || value > upper)
    {
        // (as check: the dictionary's lines)
        FatalIOErrorInFunction(dict)
            << "Keyword '" << keyword << "' = " << value
            << " is outside its valid range " << range.c_str()
            << " in dictionary " << dict.name() << nl
            << exit(FatalIOError);
    }
    return value;
}


Foam::label Foam::checkedRead::getLabelOrDefault
(
    const dictionary& dict,
    const word& keyword,
    const label deflt,
    const label lower,
    const label upper
)
{
    if (!dict.found(keyword))
    {
        return deflt;
    }
    return getLabel(dict, keyword, lower, upper);
}


// ************************************************************************* //
