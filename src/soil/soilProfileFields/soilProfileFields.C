/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "soilProfileFields.H"
#include "volFields.H"
#include "TableBase.H"
#include "IOdictionary.H"
#include "propertyField.H"
#include "zeroGradientFvPatchFields.H"
#include <cmath>

// * * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * //

namespace Foam
{

typedef soilProfileFields::property soilProperty;
typedef soilProfileFields::piece profilePiece;

//- Equal within round-off (layer bounds typed in decimal)
static bool sameDepth(const scalar a, const scalar b)
{
    return mag(a - b) <= 1e-12*max(scalar(1), max(mag(a), mag(b)));
}


//- A depth interval as text
static string intervalText(const scalar from, const scalar to, const bool closedTop)
{
    OStringStream os;
    os.precision(10);
    os  << (closedTop ? "[" : "(") << from << ", ";
    if (to >= GREAT) os << "inf)"; else os << to << ")";
    return os.str();
}


//- Read the layers or the profile of one property
static std::vector<profilePiece> readPieces
(
    const dictionary& topDict,
    const soilProperty& prop
)
{
    std::vector<profilePiece> pieces;

    if (!topDict.isDict(prop.name))
    {
        FatalIOErrorInFunction(topDict)
            << "Keyword '" << prop.name << "' in " << topDict.name().c_str()
            << " must be a sub-dictionary: " << prop.name
            << " { layers { <name> { from <m>; to <m>; value <Function1>; }"
            << " ... } } or " << prop.name
            << " { profile <Function1 of depth>; }" << nl
            << exit(FatalIOError);
    }
    const dictionary& propDict = topDict.subDict(prop.name);

    checkedRead::checkKeywords
    (
        propDict, wordList({"layers", "profile", "profileCoeffs"}),
        "'" + prop.name + "' of " + topDict.name()
    );

    const bool hasLayers = propDict.found("layers");
    const bool hasProfile = propDict.found("profile");
    if (hasLayers == hasProfile)
    {
        FatalIOErrorInFunction(propDict)
            << (hasLayers ? "Both 'layers' and 'profile' given" : "Neither"
                " 'layers' nor 'profile' given")
            << " for '" << prop.name << "' in " << topDict.name().c_str()
            << ": expected exactly one of" << nl
            << "    layers { <name> { from <m>; to <m>; value <Function1>; }"
            << " ... }   (top to bottom)" << nl
            << "    profile <Function1 of the depth [m]>;" << nl
            << exit(FatalIOError);
    }

    if (hasProfile)
    {
        profilePiece p;
        p.fn.reset(Function1<scalar>::New("profile", propDict).ptr());
        p.dict = &propDict;
        p.keyword = "profile";
        p.path = prop.name + "/profile";
        pieces.push_back(std::move(p));
        return pieces;
    }

    if (!propDict.isDict("layers"))
    {
        FatalIOErrorInFunction(propDict)
            << "Keyword 'layers' of '" << prop.name << "' in "
            << topDict.name().c_str() << " must be a sub-dictionary of named layers,"
            << " top to bottom: layers { <name> { from <m>; to <m>;"
            << " value <Function1>; } ... }" << nl
            << exit(FatalIOError);
    }
    const dictionary& layersDict = propDict.subDict("layers");

    const label nLayers = layersDict.size();
    if (!nLayers)
    {
        FatalIOErrorInFunction(layersDict)
            << "No layer in '" << prop.name << "/layers' of "
            << topDict.name().c_str() << nl << exit(FatalIOError);
    }

    label i = 0;
    for (const entry& e : layersDict)
    {
        const word& name = e.keyword();
        const string where(prop.name + "/layers/" + name);
        if (!e.isDict())
        {
            FatalIOErrorInFunction(layersDict)
                << "Entry '" << where.c_str() << "' of " << topDict.name().c_str()
                << " must be a layer: " << name
                << " { from <m>; to <m>; value <Function1>; }" << nl
                << exit(FatalIOError);
        }
        const dictionary& ld = e.dict();
        checkedRead::checkKeywords
        (
            ld, wordList({"from", "to", "value", "valueCoeffs"}),
            "layer '" + where + "' of " + topDict.name()
        );

        const bool last = (i == nLayers - 1);
        if (!ld.found("from") || (!last && !ld.found("to")))
        {
            FatalIOErrorInFunction(ld)
                << "Missing keyword '" << (ld.found("from") ? "to" : "from")
                << "' in layer '" << where.c_str() << "' of " << topDict.name().c_str()
                << ": every layer needs 'from' and 'to' (depths in m, from"
                << " < to); only the last one may omit 'to' (it then"
                << " extends to all depths below)" << nl
                << exit(FatalIOError);
        }
        if (!ld.found("value"))
        {
            FatalIOErrorInFunction(ld)
                << "Missing keyword 'value' in layer '" << where.c_str() << "' of "
                << topDict.name().c_str() << ": a number or a Function1 of the"
                << " depth [m] (polynomial, table, tableFile, csvFile...)"
                << nl << exit(FatalIOError);
        }

        profilePiece p;
        p.layer = name;
        checkedRead::checkNumbers(ld, "from", "a depth [m]");
        p.from = ld.get<scalar>("from");
        p.hasTo = ld.found("to");
        if (p.hasTo)
        {
            checkedRead::checkNumbers(ld, "to", "a depth [m] below 'from'");
        }
        p.to = p.hasTo ? ld.get<scalar>("to") : GREAT;
        p.dict = &ld;
        p.keyword = "value";
        p.path = where + "/value";

        if (!std::isfinite(p.from) || !std::isfinite(p.to))
        {
            FatalIOErrorInFunction(ld)
                << "Layer '" << where.c_str() << "' of " << topDict.name().c_str()
                << ": 'from' and 'to' must be finite depths [m]" << nl
                << exit(FatalIOError);
        }
        if (p.hasTo && !(p.to > p.from))
        {
            FatalIOErrorInFunction(ld)
                << "Layer '" << where.c_str() << "' of " << topDict.name().c_str()
                << ": keyword 'to' = " << p.to << " must be greater than"
                << " 'from' = " << p.from << " (depths in m, increasing"
                << " downward)" << nl << exit(FatalIOError);
        }
        if (i > 0)
        {
            const profilePiece& above = pieces.back();
            if (!sameDepth(p.from, above.to))
            {
                FatalIOErrorInFunction(ld)
                    << "Layer '" << where.c_str() << "' of " << topDict.name().c_str()
                    << ": keyword 'from' = " << p.from
                    << (p.from < above.to ? " overlaps" : " leaves a gap"
                        " below")
                    << " the layer above, '" << above.layer << "', which"
                    << " ends at 'to' = " << above.to
                    << ": layers are listed top to bottom and each must"
                    << " start where the previous one ends" << nl
                    << exit(FatalIOError);
            }
            p.from = above.to;
        }

        p.fn.reset(Function1<scalar>::New("value", ld).ptr());
        pieces.push_back(std::move(p));
        ++i;
    }

    return pieces;
}


//- The first bad cell over all ranks (the shallowest): depth, value and
//  centre. False if there is none
static bool firstBad
(
    const scalarField& depth,
    const scalarField& values,
    const boolList& bad,
    const vectorField& centres,
    scalar& d,
    scalar& v,
    vector& C
)
{
    label first = -1;
    forAll(bad, celli)
    {
        if (bad[celli] && (first < 0 || depth[celli] < depth[first]))
        {
            first = celli;
        }
    }
    d = first >= 0 ? depth[first] : GREAT;
    reduce(d, minOp<scalar>());
    if (d >= GREAT)
    {
        return false;
    }
    const bool mine = first >= 0 && depth[first] == d;
    scalar n = mine ? 1 : 0;
    v = mine ? values[first] : 0;
    C = mine ? centres[first] : vector::zero;
    reduce(n, sumOp<scalar>());
    reduce(v, sumOp<scalar>());
    reduce(C, sumOp<vector>());
    v /= n;
    C /= n;
    return true;
}


//- At the first bad cell (firstBad's depth dBad, on any rank): its piece
//  (pieceOfCell) and the value of field there, the same on every rank
static void atFirstBad
(
    const scalarField& depth,
    const boolList& bad,
    const scalar dBad,
    const labelList& pieceOfCell,
    const scalarField& field,
    label& piece,
    scalar& value
)
{
    piece = -1;
    value = -GREAT;
    forAll(depth, celli)
    {
        if (bad[celli] && depth[celli] == dBad)
        {
            piece = pieceOfCell[celli];
            value = field[celli];
            break;
        }
    }
    reduce(piece, maxOp<label>());
    reduce(value, maxOp<scalar>());
}


//- Evaluate the pieces of one property at the cell depths
static tmp<scalarField> evaluate
(
    const dictionary& topDict,
    const soilProperty& prop,
    std::vector<profilePiece>& pieces,
    const scalarField& depth,
    const vectorField& centres,
    labelList& pieceOfCell
)
{
    auto tvalues = tmp<scalarField>::New(depth.size(), Zero);
    scalarField& values = tvalues.ref();
    pieceOfCell.setSize(depth.size());
    pieceOfCell = -1;

    // Layers: assign the cells, from <= d < to (the last also d = to)
    const label n = pieces.size();
    boolList outside(depth.size(), false);
    forAll(depth, celli)
    {
        const scalar d = depth[celli];
        for (label i = 0; i < n; ++i)
        {
            const profilePiece& p = pieces[i];
            const bool top = (i == 0) ? (d >= p.from || sameDepth(d, p.from))
                                      : d >= p.from;
            const bool bottom =
                (i == n - 1)
              ? (!p.hasTo || d <= p.to || sameDepth(d, p.to))
              : d < p.to;
            if (top && bottom)
            {
                pieceOfCell[celli] = i;
                break;
            }
        }
        outside[celli] = pieceOfCell[celli] < 0;
    }

    scalar dBad, vBad;
    vector CBad;
    if (firstBad(depth, depth, outside, centres, dBad, vBad, CBad))
    {
        const profilePiece& first = pieces.front();
        const profilePiece& last = pieces.back();
        const bool above = dBad < first.from;
        FatalIOErrorInFunction(above ? *first.dict : *last.dict)
            << "The layers of '" << prop.name << "' in " << topDict.name().c_str()
            << " cover the depths "
            << intervalText(first.from, last.hasTo ? last.to : GREAT, true)
               .c_str()
            << " m, but the cell at " << CBad << " lies at depth " << dBad
            << " m, " << (above ? "above the first layer, '" : "below the"
               " last layer, '")
            << (above ? first.layer : last.layer)
            << "' (depth = (C - origin) . direction/|direction|):"
            << (above ? " lower its 'from'" : " raise its 'to' or omit it")
            << ", or check origin and direction" << nl
            << exit(FatalIOError);
    }

    // Per piece: cells and depths; a table used beyond its rows (an
    // error if its outOfBounds rule is 'error', reported here with the
    // file and keyword rather than by the table itself)
    scalarField dMin(n, GREAT), dMax(n, -GREAT);
    forAll(depth, celli)
    {
        const label i = pieceOfCell[celli];
        ++pieces[i].nCells;
        dMin[i] = min(dMin[i], depth[celli]);
        dMax[i] = max(dMax[i], depth[celli]);
    }
    for (label i = 0; i < n; ++i)
    {
        profilePiece& p = pieces[i];
        reduce(p.nCells, sumOp<label>());
        reduce(dMin[i], minOp<scalar>());
        reduce(dMax[i], maxOp<scalar>());

        const auto* table =
            dynamic_cast<const Function1Types::TableBase<scalar>*>(p.fn.get());
        if (!table || !p.nCells)
        {
            continue;
        }
        const scalarField x(table->x());
        if (x.empty() || (dMin[i] >= x.first() && dMax[i] <= x.last()))
        {
            continue;
        }
        const entry* e = p.dict->findEntry(p.keyword, keyType::LITERAL);
        const dictionary& coeffs =
            e && e->isDict()
          ? e->dict()
          : p.dict->optionalSubDict(p.keyword + "Coeffs");
        const word rule(coeffs.getOrDefault<word>("outOfBounds", "clamp"));
        if (rule == "error")
        {
            FatalIOErrorInFunction(coeffs)
                << "Keyword '" << p.keyword << "' (" << p.path.c_str()
                << ") in " << topDict.name().c_str() << ": the table has"
                << " rows from depth " << x.first() << " to " << x.last()
                << " m, the cells " << (p.layer.empty() ? "" : "of the layer ")
                << "lie from " << dMin[i] << " to " << dMax[i] << " m, and"
                << " its outOfBounds rule is 'error': extend the table, or"
                << " set outOfBounds clamp (the end values) in its"
                << " coefficients" << nl << exit(FatalIOError);
        }
        Info<< "    note: " << p.path.c_str() << ": cells from depth "
            << dMin[i] << " to " << dMax[i] << " m, table rows from "
            << x.first() << " to " << x.last() << " m: outside them,"
            << " outOfBounds " << rule << nl;
    }

    // Values, checked finite (the range is checked by the caller)
    boolList nonFinite(depth.size(), false);
    forAll(depth, celli)
    {
        profilePiece& p = pieces[pieceOfCell[celli]];
        values[celli] = p.fn->value(depth[celli]);
        nonFinite[celli] = !std::isfinite(values[celli]);
        p.vMin = min(p.vMin, values[celli]);
        p.vMax = max(p.vMax, values[celli]);
    }
    for (profilePiece& p : pieces)
    {
        reduce(p.vMin, minOp<scalar>());
        reduce(p.vMax, maxOp<scalar>());
    }
    if (firstBad(depth, values, nonFinite, centres, dBad, vBad, CBad))
    {
        label i = -1;
        forAll(depth, celli)
        {
            if (depth[celli] == dBad) { i = pieceOfCell[celli]; break; }
        }
        reduce(i, maxOp<label>());
        const profilePiece& p = pieces[max(i, 0)];
        FatalIOErrorInFunction(*p.dict)
            << "Keyword '" << p.keyword << "' (" << p.path.c_str() << ") in "
            << topDict.name().c_str() << " is not a finite number at depth "
            << dBad << " m (cell at " << CBad << ")" << nl
            << exit(FatalIOError);
    }

    return tvalues;
}


//- Check a property's values against its range (upper bound per cell for
//  the water content)
static void checkRange
(
    const dictionary& topDict,
    const soilProperty& prop,
    const std::vector<profilePiece>& pieces,
    const labelList& pieceOfCell,
    const scalarField& values,
    const scalarField& depth,
    const vectorField& centres,
    const scalarField* upper,
    const string& upperSource
)
{
    const scalarField rangeUpper
    (
        upper ? *upper : scalarField(values.size(), prop.range.upper)
    );
    boolList bad(values.size(), false);
    forAll(values, celli)
    {
        validRange r = prop.range;
        r.upper = rangeUpper[celli];
        bad[celli] = !r.contains(values[celli]);
    }

    scalar dBad, vBad;
    vector CBad;
    if (firstBad(depth, values, bad, centres, dBad, vBad, CBad))
    {
        label i;
        scalar up;
        atFirstBad(depth, bad, dBad, pieceOfCell, rangeUpper, i, up);
        const profilePiece& p = pieces[max(i, 0)];

        validRange r = prop.range;
        r.upper = up;
        FatalIOErrorInFunction(*p.dict)
            << "Keyword '" << p.keyword << "' (" << p.path.c_str() << ") in "
            << topDict.name().c_str() << " gives " << prop.name << " = " << vBad
            << " at depth " << dBad << " m (cell at " << CBad << "),"
            << " outside its valid range " << r.str().c_str()
            << " (" << prop.meaning << ")"
            << (upper ? " with the porosity of " + upperSource : string())
                .c_str()
            << nl << exit(FatalIOError);
    }
}

} // End namespace Foam


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * //

bool Foam::soilProfileFields::soilFileValue(const word& key, scalar& v) const
{
    IOobject io
    (
        soilFile_,
        mesh_.time().constant(),
        mesh_,
        IOobject::MUST_READ,
        IOobject::NO_WRITE,
        false
    );
    if (!io.typeHeaderOk<IOdictionary>(false))
    {
        return false;
    }
    const IOdictionary pp(io);
    if (!pp.found(key))
    {
        return false;
    }
    v = checkedRead::get
    (
        pp, key, dimless, checkedRead::closed(0, 1)
    ).value();
    return true;
}


void Foam::soilProfileFields::porosityOf
(
    scalarField& porosity,
    string& source
) const
{
    const label iPor = 0;
    const Time& runTime = mesh_.time();
    scalar uniform = 0;
    word instance;
    if (values_.set(iPor))
    {
        porosity = values_[iPor];
        source = "'porosity' of " + dict_.name();
    }
    else if (readCellValues(mesh_, "porosity", porosity, instance))
    {
        source = instance/"porosity";
    }
    else if (soilFileValue("porosity", uniform))
    {
        porosity = uniform;
        source = "constant/" + soilFile_;
    }
    else
    {
        FatalIOErrorInFunction(dict_)
            << "Cannot check 'waterContent' of " << dict_.name().c_str()
            << " against the porosity (the water content cannot exceed"
            << " it): give 'porosity' in the same dictionary, or the"
            << " field " << runTime.timeName()/"porosity"
            << ", or the keyword 'porosity' of constant/" << soilFile_
            << nl << exit(FatalIOError);
    }
}


void Foam::soilProfileFields::checkPorosityHoldsWater() const
{
    const label iPor = 0;
    const vectorField& centres = mesh_.C().primitiveField();

    scalarField water(mesh_.nCells(), Zero);
    string source;
    scalar uniform = 0;
    word instance;
    if (readCellValues(mesh_, "waterContent", water, instance))
    {
        source = instance/"waterContent";
    }
    else if (soilFileValue("waterContent", uniform))
    {
        water = uniform;
        source = "keyword 'waterContent' of constant/" + soilFile_;
    }
    else
    {
        return;     // none, or a saturation: always consistent
    }

    const scalarField& por = values_[iPor];
    boolList bad(por.size(), false);
    forAll(por, celli)
    {
        bad[celli] = water[celli] > por[celli] + SMALL;
    }
    scalar dBad, vBad;
    vector CBad;
    if (firstBad(depth_, por, bad, centres, dBad, vBad, CBad))
    {
        label i;
        scalar w;
        atFirstBad(depth_, bad, dBad, pieceOfCell_[iPor], water, i, w);
        const profilePiece& p = pieces_[iPor][max(i, 0)];
        FatalIOErrorInFunction(*p.dict)
            << "Keyword '" << p.keyword << "' (" << p.path.c_str()
            << ") in " << dict_.name().c_str() << " gives porosity = "
            << vBad << " at depth " << dBad << " m (cell at "
            << CBad << "), below the water content " << w
            << " there (" << source.c_str() << "): the volumetric"
            << " water content cannot exceed the porosity; give"
            << " 'waterContent' in the same dictionary" << nl
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::soilProfileFields::soilProfileFields
(
    const fvMesh& mesh,
    const dictionary& dict,
    const fileName& dictArg
)
:
    mesh_(mesh),
    dict_(dict),
    dictArg_(dictArg),
    properties_
    ({
        {"porosity", dimless, checkedRead::closedOpen(0, 1),
         "volume fraction of the pores, [0, 1)"},
        {"waterContent", dimless, checkedRead::closed(0, 1),
         "volumetric initial water content, [0, porosity]"},
        {"rhoCpSolid", dimEnergy/dimVolume/dimTemperature,
         checkedRead::positive(),
         "volumetric heat capacity of the solid [J/(m3 K)], > 0"},
        {"kappaSolid", dimPower/dimLength/dimTemperature,
         checkedRead::positive(),
         "conductivity of the solid [W/(m K)], > 0"}
    }),
    pieces_(properties_.size()),
    pieceOfCell_(properties_.size()),
    values_(properties_.size()),
    soilFile_("soilProperties")
{
    wordList valid({"FoamFile", "origin", "direction"});
    for (const soilProperty& p : properties_)
    {
        valid.append(p.name);
    }
    checkedRead::checkKeywords(dict, valid, "the top level of " + dictArg);

    const point origin(dict.getOrDefault<point>("origin", point::zero));
    vector direction(dict.getOrDefault<vector>("direction", vector(0, 0, -1)));
    if (!(mag(direction) > VSMALL))
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 'direction' = " << direction << " in "
            << dict.name().c_str() << " must be a non-zero vector: the downward"
            << " direction along which depth is measured" << nl
            << exit(FatalIOError);
    }
    direction /= mag(direction);

    const vectorField& centres = mesh.C().primitiveField();
    depth_ = (centres - origin) & direction;

    Info<< "Depth = (C - " << origin << ") . " << direction
        << ": cells from " << gMin(depth_) << " to " << gMax(depth_) << " m"
        << nl << endl;

    // Read and evaluate every property given
    label nGiven = 0;
    for (size_t pi = 0; pi < properties_.size(); ++pi)
    {
        const soilProperty& prop = properties_[pi];
        if (!dict.found(prop.name))
        {
            continue;
        }
        ++nGiven;
        pieces_[pi] = readPieces(dict, prop);
        values_.set
        (
            pi,
            evaluate
            (
                dict, prop, pieces_[pi], depth_, centres, pieceOfCell_[pi]
            ).ptr()
        );
    }
    if (!nGiven)
    {
        FatalIOErrorInFunction(dict)
            << "Nothing to write: " << dict.name().c_str() << " gives none of "
            << "porosity, waterContent, rhoCpSolid, kappaSolid" << nl
            << exit(FatalIOError);
    }

    IOobject io
    (
        soilFile_, mesh.time().constant(), mesh,
        IOobject::MUST_READ, IOobject::NO_WRITE, false
    );
    if (!io.typeHeaderOk<IOdictionary>(false))
    {
        soilFile_ = "porousProperties";
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::soilProfileFields::checkRanges() const
{
    // Water content and porosity are checked against each other: the one
    // written now, else the cell field of the start time, else the uniform
    // value of constant/soilProperties (or of its deprecated alias
    // constant/porousProperties)
    const label iPor = 0, iWat = 1;
    const vectorField& centres = mesh_.C().primitiveField();

    for (const label pi : {iPor, 2, 3})
    {
        if (values_.set(pi))
        {
            checkRange
            (
                dict_, properties_[pi], pieces_[pi], pieceOfCell_[pi],
                values_[pi], depth_, centres, nullptr, ""
            );
        }
    }

    if (values_.set(iWat))
    {
        scalarField porosity(mesh_.nCells(), Zero);
        string source;
        porosityOf(porosity, source);
        checkRange
        (
            dict_, properties_[iWat], pieces_[iWat], pieceOfCell_[iWat],
            values_[iWat], depth_, centres, &porosity, source
        );
    }
    else if (values_.set(iPor))
    {
        checkPorosityHoldsWater();
    }
}


void Foam::soilProfileFields::checkExisting(const bool overwrite) const
{
    const Time& runTime = mesh_.time();
    wordList refused;
    forAll(values_, pi)
    {
        if (!values_.set(pi))
        {
            continue;
        }
        IOobject io
        (
            properties_[pi].name,
            runTime.timeName(),
            mesh_,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        );
        const fileName f(io.objectPath());
        bool exists = isFile(f) || isFile(f + ".gz");
        bool ours =
            exists
         && io.typeHeaderOk<volScalarField>(false, true, false)
         && io.note().find("soilProfile") == 0;
        reduce(exists, orOp<bool>());
        reduce(ours, andOp<bool>());
        if (exists && !ours && !overwrite)
        {
            refused.append(properties_[pi].name);
        }
    }
    if (refused.size())
    {
        FatalErrorInFunction
            << "Not written: the field(s) " << refused << " already exist in "
            << runTime.timePath() << " and were not written by soilProfile"
            << " (no note \"soilProfile ...\" in their header). Remove them,"
            << " or rerun with -overwrite to replace them. Nothing was"
            << " written." << nl << exit(FatalError);
    }
}


void Foam::soilProfileFields::write() const
{
    const Time& runTime = mesh_.time();
    const string noteText("soilProfile: from " + dictArg_);
    forAll(values_, pi)
    {
        if (!values_.set(pi))
        {
            continue;
        }
        const soilProperty& prop = properties_[pi];
        Info<< prop.name << " (" << prop.meaning << "):" << nl;
        for (const profilePiece& p : pieces_[pi])
        {
            Info<< "    " << (p.layer.empty() ? word("profile") : p.layer);
            if (!p.layer.empty())
            {
                Info<< " " << intervalText(p.from, p.to, true).c_str()
                    << " m";
            }
            Info<< ": " << p.nCells << " cells";
            if (p.nCells)
            {
                Info<< ", " << p.vMin << " to " << p.vMax;
            }
            Info<< nl;
        }

        volScalarField fld
        (
            IOobject
            (
                prop.name,
                runTime.timeName(),
                mesh_,
                IOobject::NO_READ,
                IOobject::NO_WRITE,
                false
            ),
            mesh_,
            dimensionedScalar(prop.dims, Zero),
            zeroGradientFvPatchScalarField::typeName
        );
        fld.primitiveFieldRef() = values_[pi];
        fld.correctBoundaryConditions();
        fld.note() = noteText;
        fld.write();
        Info<< "    -> " << fld.objectPath() << nl << endl;
    }
}


// ************************************************************************* //
