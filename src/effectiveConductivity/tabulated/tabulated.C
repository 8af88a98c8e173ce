/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "tabulated.H"
#include "addToRunTimeSelectionTable.H"
#include "numericTable.H"
#include "checkedRead.H"
#include "Tuple2.H"
#include "OSspecific.H"

#include <algorithm>
#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace effectiveConductivityModels
{
    defineTypeNameAndDebug(tabulated, 0);
    addToRunTimeSelectionTable
    (
        effectiveConductivityModel,
        tabulated,
        dictionary
    );
}
}

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::effectiveConductivityModels::tabulated::readFile
(
    const dictionary& coeffs
)
{
    const fileName given(coeffs.get<fileName>("file"));
    fileName file(given);
    file.expand();
    if (!file.isAbsolute() && !getEnv("FOAM_CASE").empty())
    {
        file = fileName(getEnv("FOAM_CASE"))/file;
    }
    file.clean();

    // Columns count from 0
    const label alphaLColumn =
        checkedRead::getLabelOrDefault(coeffs, "alphaLColumn", 0, 0);
    const label kappaColumn =
        checkedRead::getLabelOrDefault(coeffs, "kappaColumn", 1, 0);
    if (alphaLColumn < 0 || kappaColumn < 0 || alphaLColumn == kappaColumn)
    {
        FatalIOErrorInFunction(coeffs)
            << "Keywords 'alphaLColumn' = " << alphaLColumn
            << " and 'kappaColumn' = " << kappaColumn
            << " must be two different columns >= 0 (from 0)" << nl
            << exit(FatalIOError);
    }
    if (!isFile(file))
    {
        FatalIOErrorInFunction(coeffs)
            << "Cannot open the conductivity table " << file
            << " (keyword 'file' \"" << given.c_str() << "\": "
            << (isDir(file) ? "a directory, not a file" : "no such file")
            << ")" << nl << exit(FatalIOError);
    }

    // The common table reader: format, numbers, increasing alpha_l
    numericTable::settings s;
    s.twoColumns
    (
        "alphaLColumn", alphaLColumn, "a liquid fraction alpha_l",
        "kappaColumn", kappaColumn, "a conductivity k_e"
    );
    s.orderedColumn = alphaLColumn;
    s.what = "the conductivity table";
    s.context = "conductivityModel tabulated of " + coeffs.name();

    const numericTable table(file, s);

    alphaL_.setSize(table.size());
    kappa_.setSize(table.size());
    forAll(table, rowi)
    {
        alphaL_[rowi] = table.value(rowi, alphaLColumn);
        kappa_[rowi] = table.value(rowi, kappaColumn);

        const char* bad =
            (alphaL_[rowi] < 0 || alphaL_[rowi] > 1)
          ? "a liquid fraction alpha_l outside [0, 1]"
          : (kappa_[rowi] <= 0)
          ? "a conductivity k_e <= 0 (valid: > 0 W/(m K))"
          : nullptr;
        if (bad)
        {
            FatalIOError
            (
                FUNCTION_NAME, __FILE__, __LINE__, file, table.line(rowi)
            )   << "Line " << table.line(rowi) << " of the conductivity"
                << " table has " << bad << ": " << table.text(rowi).c_str()
                << nl << "    in conductivityModel tabulated of "
                << coeffs.name() << nl << exit(FatalIOError);
        }
    }

    source_ = "table " + file;
}


void Foam::effectiveConductivityModels::tabulated::readInline
(
    const dictionary& coeffs
)
{
    const List<Tuple2<scalar, scalar>> rows
    (
        coeffs.get<List<Tuple2<scalar, scalar>>>("table")
    );

    alphaL_.setSize(rows.size());
    kappa_.setSize(rows.size());
    forAll(rows, rowi)
    {
        alphaL_[rowi] = rows[rowi].first();
        kappa_[rowi] = rows[rowi].second();

        const char* bad =
            !(std::isfinite(alphaL_[rowi]) && std::isfinite(kappa_[rowi]))
          ? "a value that is not a finite number"
          : (alphaL_[rowi] < 0 || alphaL_[rowi] > 1)
          ? "a liquid fraction alpha_l outside [0, 1]"
          : (kappa_[rowi] <= 0)
          ? "a conductivity k_e <= 0 (valid: > 0 W/(m K))"
          : (rowi > 0 && alphaL_[rowi] <= alphaL_[rowi - 1])
          ? "a liquid fraction alpha_l not above the previous row's"
            " (alpha_l must strictly increase)"
          : nullptr;
        if (bad)
        {
            FatalIOErrorInFunction(coeffs)
                << "Keyword 'table': row " << rowi << " (from 0) ("
                << alphaL_[rowi] << " " << kappa_[rowi] << ") has " << bad
                << nl << "    rows are (alpha_l k_e [W/(m K)])" << nl
                << exit(FatalIOError);
        }
    }

    source_ = "keyword 'table' of " + coeffs.name();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::effectiveConductivityModels::tabulated::tabulated
(
    const dictionary& coeffs
)
:
    effectiveConductivityModel(coeffs),
    alphaL_(),
    kappa_(),
    clamp_(false),
    source_()
{
    const bool hasFile = coeffs.found("file");
    const bool hasTable = coeffs.found("table");
    if (hasFile == hasTable)
    {
        FatalIOErrorInFunction(coeffs)
            << "conductivityModel tabulated needs exactly one of the"
            << " keywords 'file' (a table file of alpha_l and k_e) and"
            << " 'table' ((alpha_l k_e) pairs); "
            << (hasFile ? "both are given" : "neither is given")
            << " in " << coeffs.name() << nl << exit(FatalIOError);
    }
    if (hasTable)
    {
        for (const word key : {"alphaLColumn", "kappaColumn"})
        {
            if (coeffs.found(key))
            {
                FatalIOErrorInFunction(coeffs)
                    << "Keyword '" << key << "' is for a table 'file',"
                    << " not for an inline 'table'" << nl
                    << exit(FatalIOError);
            }
        }
        readInline(coeffs);
    }
    else
    {
        readFile(coeffs);
    }

    if (alphaL_.size() < 2)
    {
        FatalIOErrorInFunction(coeffs)
            << "The conductivity table (" << source_.c_str() << ") has "
            << alphaL_.size() << " row(s): at least 2 are needed" << nl
            << exit(FatalIOError);
    }

    const word bounds(coeffs.getOrDefault<word>("outOfBounds", "error"));
    if (bounds != "error" && bounds != "clamp")
    {
        FatalIOErrorInFunction(coeffs)
            << "Keyword 'outOfBounds' = " << bounds << " is not valid:"
            << " expected error or clamp" << nl << exit(FatalIOError);
    }
    clamp_ = (bounds == "clamp");
}

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::effectiveConductivityModels::tabulated::interpolate
(
    const scalar alphaL
) const
{
    const label n = alphaL_.size();

    if (!(alphaL >= alphaL_[0] && alphaL <= alphaL_[n - 1]))
    {
        if (clamp_ && std::isfinite(alphaL))
        {
            return alphaL < alphaL_[0] ? kappa_[0] : kappa_[n - 1];
        }
        FatalErrorInFunction
            << "Liquid fraction alpha_l = " << alphaL << " is outside the"
            << " conductivity table [" << alphaL_[0] << ", "
            << alphaL_[n - 1] << "] (" << source_.c_str() << ")" << nl
            << "    extend the table, or set 'outOfBounds clamp;' to use"
            << " its first or last k_e" << nl << exit(FatalError);
    }

    // First row above alphaL (n if alphaL is the last row's)
    const label i =
        label(std::upper_bound(alphaL_.cbegin(), alphaL_.cend(), alphaL)
      - alphaL_.cbegin());

    if (i == n || alphaL == alphaL_[i - 1])
    {
        return kappa_[i - 1];
    }

    const scalar w = (alphaL - alphaL_[i - 1])/(alphaL_[i] - alphaL_[i - 1]);
    return kappa_[i - 1] + w*(kappa_[i] - kappa_[i - 1]);
}


Foam::scalar
Foam::effectiveConductivityModels::tabulated::kappaPartiallySaturated
(
    const scalar,
    const scalar,
    const scalar,
    const scalar alphaL,
    const scalar
) const
{
    return interpolate(alphaL);
}

// ************************************************************************* //
