/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
-------------------------------------------------------------------------------
Application
    hearthFireRecord

Description
    Reads a fire record, the logger file of a thermocouple in the fire (or
    an inline table), as the fireTemperature boundary condition reads it,
    and prints its rows in seconds and kelvin; or stops with the
    condition's error. The reader is the condition's own (Foam::fireRecord,
    src/general/temperatureHistory): the same keywords, format, checks and
    messages (a FatalIOError naming the file, the line and what is wrong).
    No case, no mesh.

    bin/hearthCase runs it on the logger file of its dictionary's fire
    section before it writes anything, so that a file the solver would
    refuse is refused there, for the same reason, and one the solver
    accepts is accepted.

    The description DICT holds the keywords of the record in the fire
    entry of 0/T (fireTemperatureFvPatchScalarField.H), and no other:

        file              "logger.csv";   // relative to DICT's folder
        timeColumn        0;              // default 0
        temperatureColumn 1;              // default 1
        separator         ",";            // default ","
        // headerLines    1;              // default: detected
        timeUnit          min;            // s | min | h, default s
        temperatureUnit   C;              // C | K, default C
        timeOffset        300;            // s, default 0

    (or table ((t T) ...) instead of file).

    Output: on stdout, two '#' lines (what was read: rows, lines, header
    lines, the ranges in the file's units and in s, K), then one line per
    row, 't T' in s and K with 17 significant digits (the doubles the
    solver holds). Exit status 0; an error ends with status 1 and the
    FatalIOError on stderr.

Usage
    hearthFireRecord DICT

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "checkedRead.H"
#include "fireRecord.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    using namespace Foam;

    argList::addNote
    (
        "Read a fire record (a logger file of time and temperature) as the"
        " fireTemperature boundary condition reads it and print its rows"
        " in s and K, or its error (no case, no mesh)"
    );
    argList::noParallel();
    argList::noFunctionObjects();
    argList::noBanner();
    argList::addArgument("dict");

    #include "setRootCase.H"

    fileName dictFile(args[1]);
    dictFile.expand();
    if (!dictFile.isAbsolute())
    {
        dictFile = cwd()/dictFile;
    }
    dictFile.clean();

    const dictionary dict(checkedRead::readDictionary(dictFile));
    const std::string owner("the record description " + dictFile);
    checkedRead::checkKeywords(dict, fireRecord::keywords(), owner);

    const fireRecord record(dict, dictFile.path(), owner);
    const temperatureHistory& history = record.history();

    // (each line of the summary a comment)
    string summary(record.summary());
    summary.replaceAll("\n", "\n#");

    Sout.precision(17);
    Info<< "# hearthFireRecord: " << summary.c_str() << nl
        << "# t [s]  T [K]" << nl;
    forAll(history.times(), i)
    {
        Info<< history.times()[i] << ' ' << history.temperatures()[i] << nl;
    }
    Info<< flush;

    return 0;
}


// ************************************************************************* //
