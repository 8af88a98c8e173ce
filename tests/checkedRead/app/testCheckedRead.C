/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
-------------------------------------------------------------------------------
Application
    testCheckedRead

Description
    Unit tests of checkedRead::readWithoutDuplicates (src/general/
    checkedRead), the reader that refuses a keyword given twice. Each case
    writes a small dictionary file in the current directory and reads it:
    - the floating-point traps and OpenFOAM's global input mode are those
      of before the read after a parse that succeeds (with 1e400 in the
      file: 1e-400) and after one that throws (FatalIOError with
      throwExceptions(), as hearthFit's forward runs set it: 1e400, which
      raises FE_OVERFLOW and which OpenFOAM refuses, a duplicate keyword,
      an unexpected '}', a duplicate after an #inputMode directive); the
      overflow flag of the parse is not left raised;
    - #remove: a keyword removed then set again is valid (the last value
      kept), at the top level and in a sub-dictionary; set twice after the
      #remove is refused;
    - #include and #includeIfPresent: a keyword given twice in the
      included file is refused, the message naming the included file and
      its lines, also two levels down and inside a sub-dictionary; an
      included entry overridden by the file's own line is valid; a missing
      #includeIfPresent file is valid, a missing #include file an error.
    The traps are enabled as in OpenFOAM's solvers (FOAM_SIGFPE).

\*---------------------------------------------------------------------------*/

#include "checkedRead.H"
#include "entry.H"
#include "error.H"
#include "OSspecific.H"
#include "unitChecks.H"

#include <cfenv>
#include <fstream>

using namespace Foam;

namespace
{

const int traps = FE_DIVBYZERO | FE_INVALID | FE_OVERFLOW;

fileName write(const std::string& name, const std::string& text)
{
    std::ofstream os(name);
    os << text;
    return fileName(cwd()/name);
}


//- The traps enabled and the input mode are those before the read, and no
//  exception flag is left raised
void checkRestored(const std::string& what)
{
    checkTrue
    (
        what + ": traps restored", fegetexcept() == traps,
        fegetexcept(), traps, "=="
    );
    checkTrue
    (
        what + ": no exception flag left raised",
        std::fetestexcept(FE_ALL_EXCEPT & ~FE_INEXACT) == 0,
        std::fetestexcept(FE_ALL_EXCEPT & ~FE_INEXACT), 0, "=="
    );
    checkTrue
    (
        what + ": global input mode restored",
        entry::globalInputMode == entry::inputMode::MERGE,
        label(entry::globalInputMode), label(entry::inputMode::MERGE), "=="
    );
}


//- Before each read: the traps of a solver, no flag raised, the default
//  input mode (each case independent of the one before)
void reset()
{
    fedisableexcept(FE_ALL_EXCEPT);
    feenableexcept(traps);
    std::feclearexcept(FE_ALL_EXCEPT);
    entry::globalInputMode = entry::inputMode::MERGE;
}


//- Read file expecting a FatalIOError naming errorFile at line and
//  holding every needle; then the traps and input mode restored
void bad
(
    const std::string& name,
    const fileName& file,
    const fileName& errorFile,
    const label line,
    std::initializer_list<const char*> needles
)
{
    reset();
    FatalIOError.throwExceptions();
    bool thrown = false;
    std::string message;
    std::string missing;
    try
    {
        checkedRead::readWithoutDuplicates(file);
    }
    catch (const IOerror& err)
    {
        thrown = true;
        message = err.message();
        if (err.ioFileName() != errorFile)
        {
            missing += " (file: " + err.ioFileName() + ")";
        }
        if (err.ioStartLineNumber() != line)
        {
            missing += " (line " + std::to_string(err.ioStartLineNumber())
                + ", not " + std::to_string(line) + ")";
        }
    }
    FatalIOError.dontThrowExceptions();
    checkErrorMessage(name, thrown, message, needles, missing);
    checkRestored(name);
}


//- Read file expecting no error and keyword = value
void good
(
    const std::string& name,
    const fileName& file,
    const word& keyword,
    const scalar value
)
{
    reset();
    FatalIOError.throwExceptions();
    bool thrown = false;
    scalar got = -1;
    try
    {
        const dictionary d(checkedRead::readWithoutDuplicates(file));
        const entry* e = d.findScoped(keyword, keyType::LITERAL);
        if (e)
        {
            got = readScalar(e->stream());
        }
    }
    catch (const IOerror& err)
    {
        thrown = true;
        Info<< "    " << err.message().c_str() << endl;
    }
    FatalIOError.dontThrowExceptions();
    checkTrue(name + ": valid, " + keyword, !thrown && got == value, got,
        value, "==");
    checkRestored(name);
}


void testTraps()
{
    section("floating-point traps and input mode around a parse");
    good("underflow", write("underflow", "a 1e-400;\nb 2;\n"), "b", 2);
    // strtod overflows (FE_OVERFLOW raised): OpenFOAM's tokenizer refuses
    bad
    (
        "1e400 (throws)", write("overflow", "b 2;\na 1e400;\n"),
        cwd()/"overflow", 2, {"ill defined primitiveEntry", "'a'"}
    );
    bad
    (
        "duplicate (throws)", write("duplicate", "a 1;\nb 2;\na 3;\n"),
        cwd()/"duplicate", 3, {"'a' given twice", "line 1", "line 3"}
    );
    bad
    (
        "unexpected '}' (throws)", write("brace", "a 1;\n}\n"),
        cwd()/"brace", 2, {"Unexpected '}'"}
    );
    bad
    (
        "#inputMode then a duplicate (throws)",
        write("inputMode", "#inputMode overwrite\na 1;\na 2;\n"),
        cwd()/"inputMode", 3, {"'a' given twice"}
    );
}


void testRemove()
{
    section("#remove");
    good("removed then set", write("remove", "a 1;\n#remove a\na 2;\n"),
        "a", 2);
    good
    (
        "removed then set in a sub-dictionary",
        write("removeSub", "s\n{\n    a 1;\n    #remove a\n    a 2;\n}\n"),
        "s/a", 2
    );
    good
    (
        "removed by a pattern then set",
        write("removePattern", "a1 1;\n#remove \"a.*\"\na1 2;\n"), "a1", 2
    );
    bad
    (
        "removed then set twice", write("removeTwice",
        "a 1;\n#remove a\na 2;\na 3;\n"), cwd()/"removeTwice", 4,
        {"'a' given twice", "line 3", "line 4"}
    );
    bad
    (
        "another keyword removed, a set twice",
        write("removeOther", "a 1;\nb 1;\n#remove b\na 2;\n"),
        cwd()/"removeOther", 4, {"'a' given twice", "line 1", "line 4"}
    );
}


void testInclude()
{
    section("#include");
    write("incDup", "x 1;\ny 2;\nx 3;\n");
    bad
    (
        "duplicate in an included file",
        write("include", "a 1;\n#include \"incDup\"\n"),
        cwd()/"incDup", 3, {"'x' given twice", "incDup", "line 1", "line 3"}
    );
    write("incInc", "#include \"incDup\"\n");
    bad
    (
        "duplicate two includes down",
        write("include2", "#include \"incInc\"\n"),
        cwd()/"incDup", 3, {"'x' given twice", "incDup"}
    );
    write("incSubDup", "p 1;\n\np 2;\n");
    bad
    (
        "duplicate in a file included in a sub-dictionary",
        write("includeSub", "s\n{\n    #include \"incSubDup\"\n}\n"),
        cwd()/"incSubDup", 3,
        {"'p' given twice in sub-dictionary 's'", "incSubDup"}
    );
    bad
    (
        "duplicate in an #includeIfPresent file",
        write("includeIfPresent", "#includeIfPresent \"incDup\"\n"),
        cwd()/"incDup", 3, {"'x' given twice", "incDup"}
    );
    write("incOk", "FoamFile { version 2.0; format ascii; }\nx 1;\ny 2;\n");
    good
    (
        "an included entry overridden",
        write("includeOverride", "#include \"incOk\"\nx 5;\n"), "x", 5
    );
    good
    (
        "an included file's value",
        write("includeValue", "#include \"incOk\"\nx 5;\n"), "y", 2
    );
    good
    (
        "the name from a $variable",
        write("includeVar", "name incOk;\n#include \"$name\"\n"), "y", 2
    );
    good
    (
        "#includeIfPresent of a missing file",
        write("includeAbsent", "#includeIfPresent \"noSuchFile\"\na 1;\n"),
        "a", 1
    );
    bad
    (
        "#include of a missing file",
        write("includeMissing", "#include \"noSuchFile\"\na 1;\n"),
        cwd()/"includeMissing", 1, {"Cannot open include file", "noSuchFile"}
    );
}

} // End anonymous namespace


int main(int argc, char* argv[])
{
    // Trap floating-point exceptions as OpenFOAM solvers do (FOAM_SIGFPE)
    feenableexcept(traps);

    testTraps();
    testRemove();
    testInclude();

    Info<< nl << nChecks - nFailed << " of " << nChecks << " checks passed"
        << endl;

    return nFailed ? 1 : 0;
}

// ************************************************************************* //
