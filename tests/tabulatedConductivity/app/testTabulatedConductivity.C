/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
-------------------------------------------------------------------------------
Application
    testTabulatedConductivity

Description
    Unit test of conductivityModel tabulated (k_e(alpha_l) from a table),
    selected by name as porousMedium and pendularMedium select it:

    1. the table is returned exactly at its rows and interpolated linearly
       between them. The rows are binary fractions, so the linear
       interpolant at the chosen points is a binary fraction too and the
       check is exact (tolerance 0), for the inline table and for the same
       table read from a file (numericTable: header, comment, blanks);
    2. outOfBounds clamp gives the first/last k_e; error (the default) is
       a FatalError naming the value and the range;
    3. bad tables are refused with a message naming the file or keyword:
       alpha_l not increasing, k_e <= 0, alpha_l > 1, a single row, file
       and table both or neither, an unknown keyword, a bad outOfBounds,
       a missing file; tabulated is not a two-component law k_e(k_s, k_f, phi);
    4. the other laws' kappaPartiallySaturated is unchanged:
       k_e(k_s, alpha_l k_l + (1 - alpha_l) k_g, phi).

Usage
    testTabulatedConductivity   (in a scratch directory: writes files)

\*---------------------------------------------------------------------------*/

#include "dictionary.H"
#include "IStringStream.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "unitChecks.H"
#include "twoComponentConductivityModel.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * Checks  * * * * * * * * * * * * * * * * //

namespace
{

dictionary parse(const std::string& text)
{
    IStringStream is(text);
    is.name() = cwd()/"porousProperties";
    return dictionary(is);
}


autoPtr<effectiveConductivityModel> select(const std::string& coeffs)
{
    return effectiveConductivityModel::New
    (
        parse
        (
            "conductivityModel tabulated; tabulatedCoeffs {" + coeffs + "}"
        )
    );
}


scalar ke(const effectiveConductivityModel& m, const scalar alphaL)
{
    // Phase conductivities and porosity must not matter
    return m.kappaPartiallySaturated(1.52, 0.61, 0.024, alphaL, 0.4);
}


//- The construction (or evaluation) throws an error whose message holds
//  every needle
template<class Action>
void expectError
(
    const std::string& name,
    const Action& action,
    std::initializer_list<const char*> needles
)
{
    std::string message;
    bool thrown = false;
    try
    {
        action();
    }
    catch (const Foam::error& err)
    {
        thrown = true;
        message = err.message() + " file: " + err.functionName();
        if (const IOerror* io = dynamic_cast<const IOerror*>(&err))
        {
            message += " " + io->ioFileName();
        }
    }

    checkErrorMessage(name, thrown, message, needles);
}


void write(const fileName& f, const std::string& content)
{
    OFstream os(f);
    os.stdStream() << content;
}


// The table: binary fractions, so that the linear interpolant at the
// points below is exact in double precision
const std::string inlineRows =
    "table ((0 0.25) (0.125 0.5) (0.5 1.5) (0.75 1.75));";

const std::string fileRows =
    "# k_e of a test table\n"
    "alphaL, k_e [W/(m K)]\n"
    "0,     0.25\n"
    "\n"
    "0.125, 0.5   # a comment\n"
    "0.5,   1.5\n"
    "0.75,  1.75\n";


//- Rows exact, between rows linear (exact: binary fractions)
void checkTable(const effectiveConductivityModel& m, const char* what)
{
    // Rows
    const scalar x[] = {0, 0.125, 0.5, 0.75};
    const scalar y[] = {0.25, 0.5, 1.5, 1.75};
    for (label i = 0; i < 4; ++i)
    {
        checkAbs(fmt("%s: row alpha_l = %g", what, x[i]), ke(m, x[i]), y[i], 0);
    }

    // Between rows: (alpha_l, ((x1 - a) y0 + (a - x0) y1)/(x1 - x0))
    checkAbs(fmt("%s: alpha_l = 0.0625 (midpoint)", what),
        ke(m, 0.0625), 0.375, 0);
    checkAbs(fmt("%s: alpha_l = 0.15625 (1/12 of 0.125-0.5)", what),
        ke(m, 0.15625), (0.34375*0.5 + 0.03125*1.5)/0.375, 1e-15);
    checkAbs(fmt("%s: alpha_l = 0.3125 (midpoint)", what),
        ke(m, 0.3125), 1.0, 0);
    checkAbs(fmt("%s: alpha_l = 0.6875 (3/4 of 0.5-0.75)", what),
        ke(m, 0.6875), 1.6875, 0);

    // A wrong law (nearest row, or linear in the other variable) fails the
    // midpoints; print what a nearest-row lookup would give
    Info<< "     (a nearest-row lookup would give 0.25 or 0.5 at 0.0625)"
        << endl;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    FatalIOError.throwExceptions();
    FatalError.throwExceptions();

    const fileName dir(cwd());
    write(dir/"table.csv", fileRows);

    section("tabulated: rows exact, linear between rows");
    {
        checkTable(*select(inlineRows), "inline");
        checkTable(*select("file \"" + dir/"table.csv" + "\";"), "file");

        // Columns chosen in a wider file (the grainScale output)
        write
        (
            dir/"wide.csv",
            "eps,theta,alphaL,k_e\n"
            "0.1,30,0,0.25\n0.1,30,0.125,0.5\n0.1,30,0.5,1.5\n"
            "0.1,30,0.75,1.75\n"
        );
        checkTable
        (
            *select
            (
                "file \"" + dir/"wide.csv" + "\";"
                " alphaLColumn 2; kappaColumn 3;"
            ),
            "columns 2, 3"
        );
    }

    section("outside the table");
    {
        const auto clamped = select(inlineRows + " outOfBounds clamp;");
        checkAbs("clamp below: first k_e", ke(*clamped, -0.1), 0.25, 0);
        checkAbs("clamp above: last k_e", ke(*clamped, 0.9), 1.75, 0);

        const auto strict = select(inlineRows);
        expectError("above the table (default error)",
            [&]{ ke(*strict, 0.9); },
            {"alpha_l = 0.9 is outside", "[0, 0.75]", "outOfBounds clamp"});
        expectError("below the table", [&]{ ke(*strict, -1e-3); },
            {"is outside", "[0, 0.75]"});
        checkTrue("tabulated is a law of alpha_l, not k_e(k_s, k_f, phi)",
            !isA<twoComponentConductivityModel>(*strict), 0, 0, "type");
    }

    section("bad tables refused");
    {
        expectError("inline alpha_l not increasing",
            [&]{ select("table ((0 0.3) (0.2 0.5) (0.2 0.6));"); },
            {"row 2", "strictly increase", "porousProperties"});
        expectError("inline k_e <= 0",
            [&]{ select("table ((0 0.3) (0.2 0));"); },
            {"row 1", "k_e <= 0"});
        expectError("inline alpha_l > 1",
            [&]{ select("table ((0 0.3) (1.5 0.6));"); },
            {"row 1", "outside [0, 1]"});
        expectError("a single row",
            [&]{ select("table ((0 0.3));"); }, {"1 row(s)", "at least 2"});
        expectError("file and table",
            [&]{ select(inlineRows + " file \"table.csv\";"); },
            {"exactly one of", "both are given"});
        expectError("neither file nor table",
            [&]{ select("outOfBounds clamp;"); },
            {"exactly one of", "neither is given"});
        expectError("unknown keyword",
            [&]{ select(inlineRows + " outOfBound clamp;"); },
            {"outOfBound", "outOfBounds"});
        expectError("bad outOfBounds",
            [&]{ select(inlineRows + " outOfBounds extrapolate;"); },
            {"outOfBounds", "extrapolate", "error or clamp"});
        expectError("columns for an inline table",
            [&]{ select(inlineRows + " kappaColumn 1;"); },
            {"kappaColumn", "table 'file'"});
        expectError("missing file",
            [&]{ select("file \"" + dir/"noSuchTable.csv" + "\";"); },
            {"Cannot open the conductivity table", "no such file"});

        write(dir/"decreasing.csv", "0, 0.3\n0.1, 0.5\n0.05, 0.6\n");
        expectError("file alpha_l not increasing",
            [&]{ select("file \"" + dir/"decreasing.csv" + "\";"); },
            {"decreasing.csv", "Line 3"});
        write(dir/"negative.csv", "0, 0.3\n0.1, -0.5\n");
        expectError("file k_e <= 0",
            [&]{ select("file \"" + dir/"negative.csv" + "\";"); },
            {"negative.csv", "Line 2", "k_e <= 0"});
        write(dir/"text.csv", "0, 0.3\n0.1, abc\n");
        expectError("file not a number",
            [&]{ select("file \"" + dir/"text.csv" + "\";"); },
            {"text.csv", "Line 2", "not a number"});
    }

    section("other laws: kappaPartiallySaturated unchanged");
    {
        const auto h = effectiveConductivityModel::New
        (
            parse("conductivityModel harmonic;")
        );
        const scalar a = 0.3, kl = 0.61, kg = 0.024;
        checkRel("harmonic: k_e(k_s, a k_l + (1 - a) k_g, phi)",
            h->kappaPartiallySaturated(1.52, kl, kg, a, 0.4),
            refCast<const twoComponentConductivityModel>(*h)
                .kappa(1.52, a*kl + (1 - a)*kg, 0.4), 1e-15);
    }

    Info<< nl << nChecks << " checks, " << nFailed << " failed" << endl;
    return nFailed ? 1 : 0;
}

// ************************************************************************* //
