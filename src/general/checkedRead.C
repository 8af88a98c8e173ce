/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "checkedRead.H"
#include "OStringStream.H"
#include "token.H"

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
        FatalIOErrorInFunction(dict)
            << "Missing keyword '" << keyword << "' in dictionary "
            << dict.name() << ": expected a value with dimensions " << dims
            << " in the range " << range.str().c_str() << nl
            << exit(FatalIOError);
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

// ************************************************************************* //
