/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "startupReport.H"
#include "PstreamReduceOps.H"
#include "Ostream.H"

#include <sstream>
#include <iomanip>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    //- One row: key, min, max, unit, description
    std::string formatRow
    (
        const std::string& key,
        const std::string& minValue,
        const std::string& maxValue,
        const std::string& unit,
        const std::string& description
    )
    {
        std::ostringstream os;
        os  << "    " << std::left << std::setw(14) << key << ' '
            << std::setw(18) << minValue << ' '
            << std::setw(18) << maxValue << ' '
            << std::setw(8) << unit << ' ' << description;
        return os.str();
    }

    std::string formatValue(const double value)
    {
        std::ostringstream os;
        os  << std::setprecision(10) << value;
        return os.str();
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::startupReport::startupReport(const word& solver)
:
    solver_(solver)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::startupReport::add
(
    const word& key,
    const scalarField& values,
    const word& unit,
    const string& description
)
{
    // gMin/gMax: every rank reduces, also one without cells
    scalar minValue = values.size() ? min(values) : VGREAT;
    scalar maxValue = values.size() ? max(values) : -VGREAT;
    reduce(minValue, minOp<scalar>());
    reduce(maxValue, maxOp<scalar>());

    rows_.append
    (
        formatRow
        (
            key, formatValue(minValue), formatValue(maxValue), unit,
            description
        )
    );
}


void Foam::startupReport::add
(
    const word& key,
    const scalar value,
    const word& unit,
    const string& description
)
{
    rows_.append
    (
        formatRow
        (
            key, formatValue(value), formatValue(value), unit, description
        )
    );
}


void Foam::startupReport::add
(
    const word& key,
    const scalarField& values,
    const bool defined,
    const word& unit,
    const string& description,
    const string& undefinedWhy
)
{
    if (returnReduce(defined, andOp<bool>()))
    {
        add(key, values, unit, description);
    }
    else
    {
        rows_.append
        (
            formatRow
            (
                key, "-", "-", unit,
                description + " (" + undefinedWhy + ")"
            )
        );
    }
}


void Foam::startupReport::addConductivities
(
    const scalarField& kDry,
    const bool dryDefined,
    const scalarField& kWet,
    const bool wetDefined,
    const scalarField& kSat,
    const bool satDefined,
    const scalarField& rhoCpDry,
    const scalarField& rhoCpWet
)
{
    const word kUnit("W/m/K");
    const word aUnit("m2/s");
    const string outside("outside the conductivity table");
    add("k_e_dry", kDry, dryDefined, kUnit, "k_e at alpha_l = 0", outside);
    add("k_e_wet", kWet, wetDefined, kUnit, "k_e at alpha_l_0", outside);
    add
    (
        "k_e_sat", kSat, satDefined, kUnit,
        "k_e at alpha_l = 1 (saturated)", outside
    );
    add
    (
        "a_dry", scalarField(kDry/rhoCpDry), dryDefined, aUnit,
        "thermal diffusivity k_e_dry/rhoCp_dry", outside
    );
    add
    (
        "a_wet", scalarField(kWet/rhoCpWet), wetDefined, aUnit,
        "thermal diffusivity k_e_wet/rhoCp_wet", outside
    );
}


void Foam::startupReport::warn
(
    const boolList& flagged,
    const string& message
)
{
    label nFlagged = 0;
    for (const bool f : flagged)
    {
        if (f)
        {
            ++nFlagged;
        }
    }
    reduce(nFlagged, sumOp<label>());

    if (nFlagged)
    {
        std::ostringstream os;
        os  << message << " (" << nFlagged << " cell"
            << (nFlagged > 1 ? "s" : "") << ")";
        warnings_.append(os.str());
    }
}


void Foam::startupReport::write(Ostream& os) const
{
    os  << nl << "Start-up report of " << solver_ << " (soil and validity"
        << " range; min and max over the cells)" << nl
        << formatRow("key", "min", "max", "unit", "description").c_str()
        << nl;
    for (const string& row : rows_)
    {
        os  << row.c_str() << nl;
    }
    os  << "start-up report ends" << nl;
    for (const string& warning : warnings_)
    {
        os  << "--> FOAM Warning : start-up: " << warning.c_str() << nl;
    }
    os  << endl;
}

// ************************************************************************* //
