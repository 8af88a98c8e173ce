/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "numericTable.H"
#include "error.H"
#include "OSspecific.H"

#include <algorithm>
#include <cerrno>
#include <cfenv>
#include <cmath>
#include <cstdlib>
#include <fstream>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

inline bool isBlank(const char c, const char sep)
{
    return (c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f')
        && c != sep;
}


// Trim blanks (not the separator) at both ends
std::string trim(const std::string& s, const char sep)
{
    std::size_t b = 0, e = s.size();
    while (b < e && isBlank(s[b], sep)) ++b;
    while (e > b && isBlank(s[e - 1], sep)) --e;
    return s.substr(b, e - b);
}


std::string lower(std::string s)
{
    for (char& c : s)
    {
        if (c >= 'A' && c <= 'Z') c = c - 'A' + 'a';
    }
    return s;
}


// [+-]? (d+ (. d*)? | . d+) ([eE] [+-]? d+)?  (the whole string)
bool decimalSyntax(const std::string& s)
{
    std::size_t i = 0;
    const std::size_t n = s.size();
    auto digits = [&]() -> std::size_t
    {
        const std::size_t b = i;
        while (i < n && s[i] >= '0' && s[i] <= '9') ++i;
        return i - b;
    };

    if (i < n && (s[i] == '+' || s[i] == '-')) ++i;
    std::size_t nd = digits();
    if (i < n && s[i] == '.')
    {
        ++i;
        nd += digits();
    }
    if (!nd)
    {
        return false;
    }
    if (i < n && (s[i] == 'e' || s[i] == 'E'))
    {
        ++i;
        if (i < n && (s[i] == '+' || s[i] == '-')) ++i;
        if (!digits())
        {
            return false;
        }
    }
    return i == n;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

constexpr char Foam::numericTable::automatic;
constexpr char Foam::numericTable::whitespace;


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

bool Foam::numericTable::split
(
    const std::string& line,
    const char sep,
    std::vector<std::string>& fields,
    std::string& text,
    char& usedSep,
    std::string& why
)
{
    fields.clear();
    why.clear();

    // The comment: from a '#' outside quotes
    std::size_t end = line.size();
    {
        bool inQuotes = false;
        for (std::size_t i = 0; i < line.size(); ++i)
        {
            if (line[i] == '"')
            {
                inQuotes = !inQuotes;
            }
            else if (line[i] == '#' && !inQuotes)
            {
                end = i;
                break;
            }
        }
    }
    // (a line of blanks, tabs included, is empty; with tab separators a
    // leading or trailing tab separates an empty field)
    text = trim(line.substr(0, end), '\0');
    usedSep = sep;
    if (text.empty())
    {
        return true;
    }
    if (sep == '\t')
    {
        text = trim(line.substr(0, end), '\t');
    }

    // The separator of this line
    if (sep == automatic)
    {
        bool inQuotes = false, comma = false, semicolon = false;
        for (const char c : text)
        {
            if (c == '"') inQuotes = !inQuotes;
            else if (!inQuotes && c == ',') comma = true;
            else if (!inQuotes && c == ';') semicolon = true;
        }
        usedSep = comma ? ',' : semicolon ? ';' : whitespace;
    }
    const char s = usedSep == whitespace ? '\0' : usedSep;

    const std::size_t n = text.size();
    std::size_t i = 0;

    // A quoted field from text[i] == '"'; i after the closing quote
    auto quoted = [&](std::string& out) -> bool
    {
        ++i;
        while (i < n)
        {
            if (text[i] == '"')
            {
                if (i + 1 < n && text[i + 1] == '"')
                {
                    out += '"';
                    i += 2;
                    continue;
                }
                ++i;
                return true;
            }
            out += text[i++];
        }
        why = "a quote (\") is not closed";
        return false;
    };

    while (true)
    {
        // Leading blanks
        while (i < n && isBlank(text[i], s)) ++i;

        if (usedSep == whitespace && i == n)
        {
            break;
        }

        std::string field;
        if (i < n && text[i] == '"')
        {
            if (!quoted(field))
            {
                return false;
            }
            while (i < n && isBlank(text[i], s)) ++i;
            const bool atEnd =
                i == n || (usedSep != whitespace && text[i] == s)
             || (usedSep == whitespace && isBlank(text[i - 1], s));
            if (!atEnd)
            {
                why = "text after the closing quote of field \""
                    + field + "\"";
                return false;
            }
        }
        else if (usedSep == whitespace)
        {
            const std::size_t b = i;
            while (i < n && !isBlank(text[i], s)) ++i;
            field = text.substr(b, i - b);
        }
        else
        {
            const std::size_t b = i;
            while (i < n && text[i] != s) ++i;
            field = trim(text.substr(b, i - b), s);
        }
        fields.push_back(field);

        if (usedSep == whitespace)
        {
            continue;
        }
        if (i < n && text[i] == s)
        {
            ++i;        // a separator at the end: an empty last field
            continue;
        }
        break;
    }

    return true;
}


bool Foam::numericTable::parse
(
    const std::string& field,
    double& x,
    errorKind& kind
)
{
    const std::string s(trim(field, '\0'));
    if (s.empty())
    {
        kind = errorKind::empty;
        return false;
    }

    if (!decimalSyntax(s))
    {
        std::string l(lower(s));
        if (l.size() && (l[0] == '+' || l[0] == '-'))
        {
            l.erase(0, 1);
        }
        const bool nonFinite =
            l == "inf" || l == "infinity" || l.compare(0, 3, "nan") == 0;
        kind = nonFinite ? errorKind::notFinite : errorKind::notNumber;
        return false;
    }

    // strtod raises FE_OVERFLOW for 1e400, which OpenFOAM traps (SIGFPE):
    // the traps are held while it reads, and the flags it raised dropped
    const char* begin = s.c_str();
    char* end = nullptr;
    std::fenv_t fenv;
    std::feholdexcept(&fenv);
    errno = 0;
    const double v = std::strtod(begin, &end);
    const int err = errno;
    std::fesetenv(&fenv);

    if (end != begin + s.size())
    {
        kind = errorKind::notNumber;
        return false;
    }
    if (std::isinf(v) || (err == ERANGE && std::fabs(v) > 1))
    {
        kind = errorKind::overflow;
        return false;
    }
    // (an underflow, 1e-400, reads as 0 or a denormal: accepted)
    x = v;
    return true;
}


std::string Foam::numericTable::describe(const errorKind kind)
{
    switch (kind)
    {
        case errorKind::empty: return "empty";
        case errorKind::notNumber: return "not a number";
        case errorKind::notFinite:
            return "not a finite number (nan and inf are not accepted)";
        case errorKind::overflow:
            return "not a finite number: beyond the range of double"
                " (overflow)";
        default: return "not valid";
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

std::string Foam::numericTable::role(const label c) const
{
    if (c < label(settings_.roles.size()) && settings_.roles[c].size())
    {
        return settings_.roles[c] + " (column " + std::to_string(c) + ")";
    }
    std::string r("a value (column " + std::to_string(c));
    if (c < label(names_.size()))
    {
        r += ", '" + names_[c] + "'";
    }
    return r + ")";
}


std::string Foam::numericTable::separatorName(const char sep) const
{
    auto name = [](const char c) -> std::string
    {
        if (c == whitespace) return "whitespace";
        if (c == '\t') return "tab";
        return std::string("'") + c + "'";
    };
    if (settings_.separator == automatic)
    {
        return "automatic" + (sep == automatic ? "" : ": " + name(sep));
    }
    return name(settings_.separator);
}


void Foam::numericTable::fail(error&& err)
{
    if (settings_.collect)
    {
        errors_.push_back(std::move(err));
        return;
    }

    FatalIOError
    (
        "numericTable::read", __FILE__, __LINE__, file_, err.line
    )   << err.message.c_str();
    if (err.text.size())
    {
        FatalIOError << nl << "    " << err.text.c_str();
    }
    if (settings_.context.size())
    {
        FatalIOError << nl << "    in " << settings_.context.c_str();
    }
    FatalIOError << nl << exit(FatalIOError);
}


void Foam::numericTable::read()
{
    const settings& s = settings_;

    const std::string where0(s.what + " \"" + file_ + "\"");

    if (isDir(file_) || !isFile(file_))
    {
        error e;
        e.kind = errorKind::open;
        e.message =
            "cannot open " + where0
          + (isDir(file_) ? ": a directory, not a file" : ": no such file");
        fail(std::move(e));
        return;
    }
    std::ifstream is(file_.c_str());
    if (!is.is_open() || !is.good())
    {
        error e;
        e.kind = errorKind::open;
        e.message = "cannot open " + where0 + ": not readable";
        fail(std::move(e));
        return;
    }

    const bool autoHeader = s.headerLines < 0;
    std::string line, text, why;
    std::vector<std::string> fields;
    char usedSep = s.separator;
    char lastSep = s.separator;
    label lineNo = 0;
    bool inData = false;
    bool namesChecked = false;
    double prevValue = 0;
    std::string prevField;

    auto lineOf = [&](const label n) -> std::string
    {
        return "Line " + std::to_string(n) + " of " + s.what;
    };
    auto headerNote = [&]() -> std::string
    {
        return
            " (separator " + separatorName(lastSep)
          + (autoHeader ? ", header lines detected: " : ", headerLines ")
          + std::to_string(nHeader_) + ")";
    };

    while (std::getline(is, line))
    {
        ++lineNo;
        if (lineNo == 1 && line.compare(0, 3, "\xEF\xBB\xBF") == 0)
        {
            line.erase(0, 3);
        }

        const bool ok = split(line, s.separator, fields, text, usedSep, why);

        if (!autoHeader && lineNo <= s.headerLines)
        {
            ++nHeader_;
            if (ok && fields.size())
            {
                names_ = fields;
                namesLine_ = lineNo;
            }
            continue;
        }
        if (!ok)
        {
            error e;
            e.line = lineNo;
            e.kind = errorKind::quote;
            e.text = text;
            e.message = lineOf(lineNo) + ": " + why;
            inData = true;
            fail(std::move(e));
            continue;
        }
        if (fields.empty())
        {
            continue;
        }
        lastSep = usedSep;

        // The numeric columns of this line
        labelList cols(s.numericColumns);
        if (cols.empty())
        {
            cols.setSize(fields.size());
            forAll(cols, i) cols[i] = i;
        }
        label nNeeded = 0;
        for (const label c : cols)
        {
            nNeeded = max(nNeeded, c + 1);
        }

        std::vector<double> vals(fields.size(), 0.0);
        label firstBad = -1;
        errorKind badKind = errorKind::notNumber;
        bool anyNumber = false;
        for (const label c : cols)
        {
            if (c >= label(fields.size()))
            {
                continue;
            }
            double v = 0;
            errorKind k;
            if (parse(fields[c], v, k))
            {
                vals[c] = v;
                anyNumber = true;
            }
            else if (firstBad < 0)
            {
                firstBad = c;
                badKind = k;
            }
        }

        // A header line at the top: no number in its numeric columns
        if (autoHeader && !inData && !anyNumber)
        {
            ++nHeader_;
            names_ = fields;
            namesLine_ = lineNo;
            continue;
        }
        inData = true;

        // The names, once, at the first data line
        if (!namesChecked)
        {
            namesChecked = true;
            if ((s.needNames || s.nColumns == -2) && names_.empty())
            {
                error e;
                e.line = lineNo;
                e.kind = errorKind::noHeader;
                e.text = text;
                e.message =
                    lineOf(lineNo) + " is a data row, but no header line"
                    " gives the names of the columns before it";
                fail(std::move(e));
            }
            if (s.uniqueNames)
            {
                for (std::size_t j = 1; j < names_.size(); ++j)
                {
                    for (std::size_t i = 0; i < j; ++i)
                    {
                        if (names_[i] == names_[j])
                        {
                            error e;
                            e.line = namesLine_;
                            e.column = j;
                            e.kind = errorKind::duplicateName;
                            e.field = names_[j];
                            e.message =
                                lineOf(namesLine_) + " (the header) names"
                                " two columns '" + names_[j] + "' (columns "
                              + std::to_string(i) + " and "
                              + std::to_string(j) + "): the column names"
                                " must be unique";
                            fail(std::move(e));
                        }
                    }
                }
            }
        }

        error e;
        e.line = lineNo;
        e.text = text;
        e.fields = fields;
        const label nHave = fields.size();

        const label nExact =
            s.nColumns >= 0 ? s.nColumns
          : (s.nColumns == -2 && names_.size()) ? label(names_.size())
          : -1;

        if (nHave < nNeeded || (nExact >= 0 && nHave < nExact))
        {
            const label need = max(nNeeded, nExact);
            e.kind = errorKind::tooFewColumns;
            e.message =
                lineOf(lineNo) + " has " + std::to_string(nHave)
              + " column(s), but "
              + (
                    s.columnsDescription.size()
                  ? s.columnsDescription + " need"
                  : std::string("the table needs")
                )
              + (nExact >= 0 ? " " : " at least ") + std::to_string(need)
              + (
                    s.nColumns == -2 && nExact >= 0
                  ? " (the names of the header, line "
                    + std::to_string(namesLine_) + ")"
                  : std::string()
                );
        }
        else if (nExact >= 0 && nHave != nExact)
        {
            e.kind = errorKind::wrongColumns;
            e.message =
                lineOf(lineNo) + " has " + std::to_string(nHave)
              + " column(s), but "
              + (
                    s.columnsDescription.size()
                  ? s.columnsDescription + " need"
                  : std::string("the table needs")
                )
              + " exactly " + std::to_string(nExact)
              + (
                    s.nColumns == -2
                  ? " (the names of the header, line "
                    + std::to_string(namesLine_) + ")"
                  : std::string()
                );
        }
        else if (firstBad >= 0)
        {
            e.kind = badKind;
            e.column = firstBad;
            e.field = fields[firstBad];
            e.message =
                lineOf(lineNo) + " has " + role(firstBad) + " '"
              + fields[firstBad] + "' that is " + describe(badKind);
        }
        else if (s.orderedColumn >= 0 && !lines_.empty())
        {
            const label c = s.orderedColumn;
            const double v = vals[c];
            const bool strict = s.ordering == order::strictlyIncreasing;
            const bool back =
                s.ordering != order::none
             && (strict ? !(v > prevValue) : v < prevValue);
            if (back)
            {
                e.kind = errorKind::notIncreasing;
                e.column = c;
                e.field = fields[c];
                e.message =
                    lineOf(lineNo) + " has " + role(c) + " " + fields[c]
                  + ", " + (v == prevValue ? "the same as" : "before")
                  + " line " + std::to_string(lines_.back()) + " with "
                  + prevField + ": the values of column "
                  + std::to_string(c)
                  + (
                        strict
                      ? " must increase strictly (sort the rows, remove"
                        " repeated ones)"
                      : " must not decrease (sort the rows)"
                    );
            }
        }

        if (e.message.size())
        {
            if (e.kind != errorKind::notIncreasing)
            {
                e.message += headerNote() + ":";
            }
            fail(std::move(e));
            continue;
        }

        if (s.orderedColumn >= 0)
        {
            prevValue = vals[s.orderedColumn];
            prevField = fields[s.orderedColumn];
        }
        lines_.push_back(lineNo);
        fields_.push_back(fields);
        values_.push_back(std::move(vals));
        texts_.push_back(text);
    }
    nLines_ = lineNo;

    if (is.bad())
    {
        error e;
        e.line = lineNo;
        e.kind = errorKind::read;
        e.message = "error reading " + where0 + " after line "
          + std::to_string(lineNo);
        fail(std::move(e));
        return;
    }

    if (lines_.empty() && (!s.collect || errors_.empty()))
    {
        error e;
        e.kind = errorKind::noData;
        e.message =
            "No data row in " + s.what + ": " + std::to_string(lineNo)
          + " line(s), " + std::to_string(nHeader_) + " header line(s) "
          + (autoHeader ? "(non-numeric at the top) " : "")
          + "skipped; a row needs numbers in "
          + (
                s.columnsDescription.size()
              ? s.columnsDescription
              : std::string("its columns")
            )
          + " (separator " + separatorName(lastSep) + ")";
        fail(std::move(e));
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::numericTable::numericTable(const fileName& file, const settings& s)
:
    file_(file),
    settings_(s),
    lines_(),
    fields_(),
    values_(),
    texts_(),
    names_(),
    namesLine_(0),
    nHeader_(0),
    nLines_(0),
    errors_()
{
    read();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalarList Foam::numericTable::column(const label c) const
{
    scalarList col(size());
    forAll(col, rowi)
    {
        col[rowi] = values_[rowi][c];
    }
    return col;
}


Foam::label Foam::numericTable::find(const std::string& name) const
{
    for (std::size_t i = 0; i < names_.size(); ++i)
    {
        if (names_[i] == name)
        {
            return label(i);
        }
    }
    return -1;
}


// ************************************************************************* //
