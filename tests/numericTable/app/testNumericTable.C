/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
-------------------------------------------------------------------------------
Application
    testNumericTable

Description
    Unit tests of Foam::numericTable (src/general/numericTable), the reader
    of every numeric table of hearthFoam. Each case writes a small file in
    the current directory and reads it:
    - formats: ',' ';' tab and whitespace separators, explicit and
      automatic (per line); double-quoted fields (with the separator, '#'
      and "" inside); '#' comment lines and trailing comments; header lines
      automatic (title, names, units) and explicit, the names from the
      last; a UTF-8 BOM; CRLF line ends; empty lines; no end of line at the
      end; text columns beside numeric ones; numbers with signs, exponents,
      '.5', '5.', an underflow (1e-400 reads as 0);
    - every error: its FatalIOError (thrown) must name the file ('file:'),
      the line, and contain the reason and the column; missing file,
      directory, not a number, empty field, nan, inf, -inf, 1e400, -1e400,
      hex, too few columns, wrong column count (exact, and as many as the
      names), duplicate names, a time equal to or before the previous one
      (both lines named), a decrease of a non-decreasing column, an
      unterminated quote, text after a quote, no data row (empty file,
      header only, comments only), no header when names are required;
      collect mode (all errors listed, bad rows skipped).
    The floating-point traps are enabled as in OpenFOAM's solvers
    (FOAM_SIGFPE): reading 1e400 must not raise SIGFPE.

    Also the fire history shared by fireTemperature and hearthDuration
    (Foam::temperatureHistory, src/general/temperatureHistory): its checks
    (nan, 0 K, a repeated or earlier time), exact values at the points,
    linear in between (against the formula), held outside, and its table
    file read back by the table reader.

    testNumericTable -fatal: one uncaught error (1e400 on line 3), for the
    run script to check the real exit path.

\*---------------------------------------------------------------------------*/

#include "numericTable.H"
#include "temperatureHistory.H"
#include "error.H"
#include "OSspecific.H"
#include "unitChecks.H"

#include <cfenv>
#include <fstream>
#include <iterator>
#include <limits>

using namespace Foam;

namespace
{

//- Write a file (exact bytes)
fileName write(const std::string& name, const std::string& content)
{
    const fileName f(cwd()/name);
    std::ofstream os(f.c_str(), std::ios::binary);
    os << content;
    return f;
}


//- A check that is true or false
void check(const std::string& name, const bool pass, const std::string& got = "")
{
    ++nChecks;
    if (!pass) ++nFailed;
    Info<< (pass ? "ok   " : "FAIL ") << name.c_str()
        << (got.size() && !pass ? " | got: " + got : std::string()).c_str()
        << endl;
}


//- Read 'content' with settings s, expecting a FatalIOError naming the
//  file at 'line' (-1: no line) whose message contains every needle
void expectError
(
    const std::string& name,
    const std::string& content,
    const numericTable::settings& s,
    const label line,
    std::initializer_list<const char*> needles,
    const fileName& given = fileName()
)
{
    const fileName f = given.size() ? given : write("t_" + name, content);
    std::string message, file;
    label at = -2;
    bool thrown = false;
    try
    {
        numericTable t(f, s);
    }
    catch (const Foam::IOerror& err)
    {
        thrown = true;
        message = err.message();
        file = err.ioFileName();
        at = err.ioStartLineNumber();
    }

    std::string missing;
    if (thrown && file != f) missing += " file '" + file + "'";
    if (thrown && at != line)
    {
        missing += " line " + std::to_string(at) + " not "
            + std::to_string(line);
    }
    checkErrorMessage(name, thrown, message, needles, missing);
    if (missing.size())
    {
        Info<< "    message: " << message.c_str() << endl;
    }
}


numericTable::settings csv()
{
    numericTable::settings s;
    s.what = "the test file";
    return s;
}


void testFormats()
{
    section("formats");

    // Comma, BOM, CRLF, title + names + units header, comments, blank
    // lines, trailing comment, quoted names, no final end of line
    {
        const fileName f = write
        (
            "comma.csv",
            "\xEF\xBB\xBF" "Logger 12, fire of 14 June\r\n"
            "\"time, s\",T1,\"T \"\"2\"\"\"\r\n"
            "# units: s, C, C\r\n"
            "\r\n"
            "0, 20.5, 18\r\n"
            "  60 ,  +1.5e2,-3.  # a comment, with a comma\r\n"
            "   \r\n"
            "120,.5,1e-400"
        );
        numericTable t(f, csv());
        checkAbs("comma: rows", t.size(), 3, 0);
        checkAbs("comma: header lines (title, names)", t.nHeader(), 2, 0);
        check("comma: names from the last header line, quotes removed",
            t.names().size() == 3 && t.names()[0] == "time, s"
         && t.names()[1] == "T1" && t.names()[2] == "T \"2\"",
            t.names().size() ? t.names()[0] : "");
        checkAbs("comma: line of row 0 (after BOM, comment, blank)",
            t.line(0), 5, 0);
        checkAbs("comma: line of the last row", t.line(2), 8, 0);
        checkAbs("comma: 20.5", t.value(0, 1), 20.5, 0);
        checkAbs("comma: +1.5e2", t.value(1, 1), 150, 0);
        checkAbs("comma: -3.", t.value(1, 2), -3, 0);
        checkAbs("comma: .5", t.value(2, 1), 0.5, 0);
        checkAbs("comma: 1e-400 (underflow) reads as 0", t.value(2, 2), 0,
            1e-300);
        checkAbs("comma: find(\"T1\")", t.find("T1"), 1, 0);
        checkAbs("comma: find(\"none\")", t.find("none"), -1, 0);
        checkAbs("comma: lines", t.nLines(), 8, 0);
        const scalarList c(t.column(0));
        checkAbs("comma: column(0)[2]", c[2], 120, 0);
    }

    // Semicolon (explicit and automatic)
    for (const char sep : {';', numericTable::automatic})
    {
        const fileName f = write("semicolon.csv",
            "t;a;b\n1;2;3\n2; 4 ;\"5\"\n");
        numericTable::settings s(csv());
        s.separator = sep;
        numericTable t(f, s);
        const std::string n(sep == ';' ? "semicolon" : "semicolon (auto)");
        checkAbs(n + ": rows", t.size(), 2, 0);
        checkAbs(n + ": quoted \"5\"", t.value(1, 2), 5, 0);
        check(n + ": names", t.names().size() == 3 && t.names()[2] == "b");
    }

    // Whitespace: runs of spaces and tabs, a quoted name with a blank
    {
        const fileName f = write("blanks.dat",
            "time\t \"T fire\"   T2\n  0\t\t1   2\n1 3\t 4  \n");
        numericTable::settings s(csv());
        s.separator = numericTable::whitespace;
        numericTable t(f, s);
        checkAbs("whitespace: rows", t.size(), 2, 0);
        checkAbs("whitespace: 3 columns", t.nColumns(1), 3, 0);
        checkAbs("whitespace: value", t.value(1, 2), 4, 0);
        check("whitespace: quoted name with a blank",
            t.names().size() == 3 && t.names()[1] == "T fire");
        // automatic: the same
        numericTable a(f, csv());
        checkAbs("whitespace (auto): value", a.value(0, 2), 2, 0);
    }

    // Tab: empty fields are fields; a text column not numeric
    {
        const fileName f = write("tab.tsv",
            "t\tnote\tT\n0\t\t20\n1\tfire lit\t300\n\t\t\n"
            "2\tx\t301\t\n");
        numericTable::settings s(csv());
        s.separator = '\t';
        s.numericColumns = {0, 2};
        numericTable t(f, s);
        checkAbs("tab: rows (a line of tabs is blank)", t.size(), 3, 0);
        checkAbs("tab: a trailing tab is an empty last field",
            t.nColumns(2), 4, 0);
        numericTable::settings s1(s);
        s1.numericColumns = {1, 2};
        numericTable t1(write("tab1.tsv", "a\tb\tc\n\t1\t2\n"), s1);
        check("tab: a leading tab is an empty first field",
            t1.size() == 1 && t1.field(0, 0).empty() && t1.value(0, 2) == 2);
        check("tab: empty text field kept", t.field(0, 1).empty());
        check("tab: text with a blank", t.field(1, 1) == "fire lit");
        checkAbs("tab: value", t.value(1, 2), 300, 0);
    }

    // Automatic per line: a sensor file mixing separators, quotes, '#'
    // in quotes, a header of names
    {
        const fileName f = write("sensors.csv",
            "# sensors\nname, x, y, z\n"
            "TC1, 0.04, 0.025, -0.005   # under the fire\n"
            "TC2  0.04  0.025  -0.02\n"
            "TC3;0.15;0.07;-0.01\n"
            "\"TC#4, a\", 1, 2, 3\n");
        numericTable::settings s(csv());
        s.numericColumns = {1, 2, 3};
        s.nColumns = 4;
        numericTable t(f, s);
        checkAbs("mixed: rows", t.size(), 4, 0);
        checkAbs("mixed: header lines", t.nHeader(), 1, 0);
        check("mixed: names", t.field(1, 0) == "TC2"
            && t.field(2, 0) == "TC3" && t.field(3, 0) == "TC#4, a",
            t.field(3, 0));
        checkAbs("mixed: whitespace line", t.value(1, 3), -0.02, 0);
        checkAbs("mixed: semicolon line", t.value(2, 1), 0.15, 0);
        checkAbs("mixed: line of the quoted name", t.line(3), 6, 0);
    }

    // Explicit header lines: exactly n lines, names from the last
    // non-blank one, even if numeric
    {
        const fileName f = write("explicit.csv",
            "1,2\n3,4\n\n5,6\n7,8\n");
        numericTable::settings s(csv());
        s.headerLines = 3;
        numericTable t(f, s);
        checkAbs("headerLines 3: rows", t.size(), 2, 0);
        checkAbs("headerLines 3: first row's line", t.line(0), 4, 0);
        check("headerLines 3: names from line 2",
            t.names().size() == 2 && t.names()[0] == "3");
        s.headerLines = 0;
        numericTable t0(f, s);
        checkAbs("headerLines 0: rows", t0.size(), 4, 0);
    }

    // Non-decreasing column (a repeated time is a jump), strict order
    {
        const fileName f = write("jumps.csv", "0,1\n10,1\n10,5\n20,5\n");
        numericTable::settings s(csv());
        s.orderedColumn = 0;
        s.ordering = numericTable::order::nonDecreasing;
        numericTable t(f, s);
        checkAbs("non-decreasing: a repeated time accepted", t.size(), 4, 0);
    }

    // Exact columns as many as the names, unique names
    {
        const fileName f = write("obs.csv",
            "time_s,z1,z2\n60,20,20\n120,25.5,21\n");
        numericTable::settings s(csv());
        s.nColumns = -2;
        s.uniqueNames = true;
        s.orderedColumn = 0;
        numericTable t(f, s);
        checkAbs("observations: rows", t.size(), 2, 0);
        checkAbs("observations: value", t.value(1, 1), 25.5, 0);
    }

    // Static parse: numbers and non-numbers
    {
        double x = 0;
        numericTable::errorKind k;
        const bool a = numericTable::parse(" 1.25e+3 ", x, k);
        checkAbs("parse ' 1.25e+3 '", a ? x : -1, 1250, 0);
        check("parse '1e308' (finite)", numericTable::parse("1e308", x, k));
        check("parse '-1e400': overflow",
            !numericTable::parse("-1e400", x, k)
         && k == numericTable::errorKind::overflow);
        check("parse 'NaN': not finite",
            !numericTable::parse("NaN", x, k)
         && k == numericTable::errorKind::notFinite);
        check("parse '-Infinity': not finite",
            !numericTable::parse("-Infinity", x, k)
         && k == numericTable::errorKind::notFinite);
        check("parse '0x1p3': not a number",
            !numericTable::parse("0x1p3", x, k)
         && k == numericTable::errorKind::notNumber);
        check("parse '1,5': not a number",
            !numericTable::parse("1,5", x, k)
         && k == numericTable::errorKind::notNumber);
        check("parse '.': not a number", !numericTable::parse(".", x, k));
        check("parse '1e': not a number", !numericTable::parse("1e", x, k));
        check("parse '': empty",
            !numericTable::parse("", x, k)
         && k == numericTable::errorKind::empty);
    }
}


void testErrors()
{
    section("errors: FatalIOError naming file, line, column and reason");

    FatalIOError.throwExceptions();
    FatalError.throwExceptions();

    const numericTable::settings s(csv());
    numericTable::settings time(csv());
    time.orderedColumn = 0;
    time.roles = {"a time"};

    expectError("missingFile", "", s, -1,
        {"cannot open the test file", "noSuchFile.csv", "no such file"},
        cwd()/"noSuchFile.csv");
    mkDir(cwd()/"aDirectory.csv");
    expectError("directory", "", s, -1,
        {"cannot open", "a directory, not a file"}, cwd()/"aDirectory.csv");

    expectError("notANumber", "t,T\n0,1\n1,2\n2,abc\n", s, 4,
        {"Line 4 of the test file", "(column 1, 'T')", "'abc'",
         "not a number", "2,abc"});
    expectError("notANumberRole", "0,1\n1,2x\n", time, 2,
        {"Line 2 of the test file has a value (column 1) '2x' that is not"
         " a number"});
    expectError("emptyField", "0,1\n,2\n", time, 2,
        {"Line 2", "a time (column 0) '' that is empty"});
    expectError("nan", "0,1\n1,nan\n", s, 2,
        {"Line 2", "(column 1) 'nan'", "not a finite number"});
    expectError("inf", "0,1\ninf,1\n", time, 2,
        {"Line 2", "a time (column 0) 'inf'", "not a finite number"});
    expectError("minusInf", "0,1\n1,-inf\n", s, 2,
        {"Line 2", "'-inf'", "not a finite number"});
    expectError("overflow", "0,1\n1,1e400\n", s, 2,
        {"Line 2", "(column 1) '1e400'", "beyond the range of double"});
    expectError("negativeOverflow", "0,1\n-1e400,1\n", s, 2,
        {"Line 2", "(column 0) '-1e400'", "beyond the range of double"});
    expectError("hex", "0,1\n0x10,1\n", s, 2,
        {"Line 2", "'0x10'", "not a number"});
    expectError("decimalComma", "0;1\n1;2,5\n", s, 2,
        {"Line 2", "'1;2'", "not a number"});

    numericTable::settings two(csv());
    two.numericColumns = {0, 1};
    two.columnsDescription = "timeColumn 0 and temperatureColumn 1";
    expectError("tooFewColumns", "0,1\n5\n", two, 2,
        {"Line 2 of the test file has 1 column(s), but timeColumn 0 and"
         " temperatureColumn 1 need at least 2", "separator automatic"});

    numericTable::settings four(csv());
    four.numericColumns = {1, 2, 3};
    four.nColumns = 4;
    expectError("fiveColumns", "a,1,2,3\nb,1,2,3,4\n", four, 2,
        {"Line 2", "has 5 column(s)", "exactly 4"});
    expectError("threeColumns", "a,1,2,3\nb,1,2\n", four, 2,
        {"Line 2", "has 3 column(s)", "4"});

    numericTable::settings named(csv());
    named.nColumns = -2;
    named.uniqueNames = true;
    expectError("columnsOfTheHeader", "time_s,z1,z2\n0,1,2\n1,2\n", named,
        3, {"Line 3", "has 2 column(s)", "3", "header, line 1"});
    expectError("duplicateName", "time_s,z1,z2,z1\n0,1,2,3\n", named, 1,
        {"Line 1", "'z1'", "columns 1 and 3", "must be unique"});
    expectError("noHeader", "0,1,2\n1,2,3\n", named, 1,
        {"Line 1", "no header line"});

    expectError("timeBackwards", "t,T\n0,1\n10,2\n5,3\n", time, 4,
        {"Line 4 of the test file has a time (column 0) 5, before line 3"
         " with 10", "increase strictly"});
    expectError("timeRepeated", "0,1\n10,2\n# c\n10,3\n", time, 4,
        {"Line 4", "the same as line 2 with 10", "increase strictly"});
    numericTable::settings nd(time);
    nd.ordering = numericTable::order::nonDecreasing;
    expectError("nonDecreasing", "0,1\n10,2\n10,3\n9,1\n", nd, 4,
        {"Line 4", "before line 3 with 10", "must not decrease"});

    expectError("unterminatedQuote", "0,1\n\"1,2\n", s, 2,
        {"Line 2", "quote", "not closed"});
    expectError("textAfterQuote", "0,1\n\"1\"x,2\n", s, 2,
        {"Line 2", "text after the closing quote"});

    expectError("emptyFile", "", two, -1,
        {"No data row in the test file: 0 line(s)"});
    expectError("headerOnly", "time,T\n", two, -1,
        {"No data row", "1 line(s), 1 header line(s) (non-numeric at the"
         " top) skipped", "timeColumn 0 and temperatureColumn 1"});
    expectError("commentsOnly", "# 0,1\n\n  # 2,3\n", two, -1,
        {"No data row", "3 line(s), 0 header line(s)"});
    numericTable::settings semi(two);
    semi.separator = ';';
    expectError("wrongSeparator", "0,1\n2,3\n", semi, -1,
        {"No data row", "separator ';'"});

    // With explicit header lines, a bad first row is an error
    numericTable::settings h0(two);
    h0.headerLines = 0;
    expectError("headerLinesZero", "time,T\n0,1\n", h0, 1,
        {"Line 1", "'time'", "not a number", "headerLines 0"});

    // A bad row after data, where a header would be skipped at the top
    expectError("headerAfterData", "0,1\ntime,T\n", two, 2,
        {"Line 2", "'time'", "not a number"});

    // Context line
    numericTable::settings ctx(two);
    ctx.context = "boundary condition X";
    expectError("context", "0,1\n1,x\n", ctx, 2,
        {"Line 2", "in boundary condition X"});

    FatalIOError.dontThrowExceptions();
    FatalError.dontThrowExceptions();
}


void testCollect()
{
    section("collect: every error listed, bad rows skipped");

    const fileName f = write("collect.csv",
        "name,x,y,z\nA,1,2,3\nB,1,2\nC,1,zz,3\nD,4,5,6\nE,1,2,3,4\n");
    numericTable::settings s(csv());
    s.numericColumns = {1, 2, 3};
    s.nColumns = 4;
    s.collect = true;
    numericTable t(f, s);
    checkAbs("collect: good rows", t.size(), 2, 0);
    checkAbs("collect: errors", t.errors().size(), 3, 0);
    if (t.errors().size() == 3)
    {
        const auto& e = t.errors();
        check("collect: line 3 too few columns",
            e[0].line == 3
         && e[0].kind == numericTable::errorKind::tooFewColumns
         && e[0].fields.size() == 3 && e[0].fields[0] == "B");
        check("collect: line 4 column 2 not a number",
            e[1].line == 4 && e[1].column == 2 && e[1].field == "zz"
         && e[1].kind == numericTable::errorKind::notNumber
         && e[1].text == "C,1,zz,3");
        check("collect: line 6 wrong columns",
            e[2].line == 6
         && e[2].kind == numericTable::errorKind::wrongColumns);
    }
    checkAbs("collect: rows D after the errors", t.value(1, 1), 4, 0);

    // A missing file, no data: errors, not fatal
    numericTable m(cwd()/"noSuchFile.csv", s);
    check("collect: missing file",
        m.errors().size() == 1
     && m.errors()[0].kind == numericTable::errorKind::open);
    numericTable n(write("collectEmpty.csv", "# nothing\n"), s);
    check("collect: no data",
        n.errors().size() == 1
     && n.errors()[0].kind == numericTable::errorKind::noData);
}

void testTemperatureHistory()
{
    section("temperatureHistory: the fire history of fireTemperature and"
        " hearthDuration");

    typedef temperatureHistory::check check_t;
    temperatureHistory h;
    check("append (0 s, 293.15 K)", h.append(0, 293.15, 2) == check_t::ok);
    check("append (60 s, 973.15 K)", h.append(60, 973.15, 3) == check_t::ok);
    check("append (61.5 s, 973.15 K)",
        h.append(61.5, 973.15, 5) == check_t::ok);
    check("append (200 s, 0.1 K)", h.append(200, 0.1, 6) == check_t::ok);
    // (a quiet NaN made without an FP operation: the traps are on)
    const double qnan = std::numeric_limits<double>::quiet_NaN();
    check("reject a nan time",
        h.append(qnan, 300, 7) == check_t::notFinite);
    check("reject 0 K", h.append(300, 0, 7) == check_t::notAboveZero);
    check("reject -1 K", h.append(300, -1, 7) == check_t::notAboveZero);
    check("reject a repeated time",
        h.append(200, 300, 7) == check_t::sameTime);
    check("reject an earlier time",
        h.append(100, 300, 7) == check_t::timeBefore);
    checkAbs("rejected points not appended", h.size(), 4, 0);
    checkAbs("line of point 2", h.line(2), 5, 0);

    checkAbs("exact at a point (60 s)", h.value(60), 973.15, 0);
    checkAbs("exact at the last point", h.value(200), 0.1, 0);
    checkAbs("held before the first point", h.value(-1e9), 293.15, 0);
    checkAbs("held after the last point", h.value(1e9), 0.1, 0);
    const scalar t = 17.25;
    checkRel("linear between (17.25 s)", h.value(t),
        293.15 + (t - 0)/(60 - 0)*(973.15 - 293.15), 1e-15);
    checkAbs("constant segment (61 s)", h.value(61), 973.15, 1e-12);
    const scalar t2 = 123.4;
    checkRel("linear between (123.4 s)", h.value(t2),
        973.15 + (t2 - 61.5)/(200 - 61.5)*(0.1 - 973.15), 1e-14);

    // The table file (hearthDuration's constant/fireHistory), as text
    const fileName f(cwd()/"history.table");
    h.writeTableFile(f, "a comment\nsecond line", 1000, 15);
    std::ifstream is(f.c_str());
    std::string all((std::istreambuf_iterator<char>(is)),
        std::istreambuf_iterator<char>());
    check("table file: comment lines",
        all.compare(0, 27, "// a comment\n// second line") == 0, all);
    check("table file: count and first point shifted by 1000 s",
        all.find("\n4\n(\n    (1000 293.15)\n") != std::string::npos, all);
    check("table file: last point", all.find("    (1200 0.1)\n)\n")
        != std::string::npos, all);
}

} // End anonymous namespace


int main(int argc, char* argv[])
{
    // Trap floating-point exceptions as OpenFOAM solvers do (FOAM_SIGFPE)
    feenableexcept(FE_DIVBYZERO | FE_INVALID | FE_OVERFLOW);

    if (argc == 2 && std::string(argv[1]) == "-fatal")
    {
        numericTable::settings s;
        s.what = "the fatal test file";
        numericTable t(write("fatal.csv", "t,T\n0,1\n1,1e400\n"), s);
        Info<< "no error" << endl;
        return 0;
    }

    testFormats();
    testErrors();
    testCollect();
    testTemperatureHistory();

    Info<< nl << nChecks - nFailed << " of " << nChecks << " checks passed"
        << endl;

    return nFailed ? 1 : 0;
}

// ************************************************************************* //
