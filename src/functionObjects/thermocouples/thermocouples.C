/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "thermocouples.H"
#include "checkedRead.H"
#include "volFields.H"
#include "interpolation.H"
#include "IFstream.H"
#include "HashTable.H"
#include "OStringStream.H"
#include "ListOps.H"
#include "Time.H"
#include "addToRunTimeSelectionTable.H"
#include "numericTable.H"
#include "emptyPolyPatch.H"
#include "wedgePolyPatch.H"
#include "symmetryPlanePolyPatch.H"
#include "symmetryPolyPatch.H"

#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(thermocouples, 0);

    addToRunTimeSelectionTable
    (
        functionObject,
        thermocouples,
        dictionary
    );
}
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// Offset from K to C
constexpr Foam::scalar zeroCelsius = 273.15;

// Most faulty lines listed in one error message
constexpr Foam::label maxListed = 20;

// Silences Info and Warning for its lifetime (probes' own messages)
class silence
{
    const int level_;

public:

    silence()
    :
        level_(Foam::messageStream::level)
    {
        Foam::messageStream::level = 0;
    }

    ~silence()
    {
        Foam::messageStream::level = level_;
    }
};

} // End anonymous namespace


// * * * * * * * * * * * * * Static Member Functions  * * * * * * * * * * * * //

void Foam::functionObjects::thermocouples::readSensorFile
(
    const fileName& file,
    pointField& positions,
    wordList& names,
    labelList& lines,
    labelList& errorLines,
    List<string>& errors
)
{
    // Read on the master, which sends the sensors and the errors on
    if (Pstream::master())
    {
        DynamicList<point> pts;
        DynamicList<word> nms;
        DynamicList<label> lns;
        DynamicList<label> errLns;
        DynamicList<string> errs;
        HashTable<label, word> firstLine;

        auto addError = [&](const label lineNo, const std::string& msg)
        {
            errLns.append(lineNo);
            errs.append(msg);
        };

        // The common table reader (src/general/numericTable), collecting
        // every faulty line: name (text), x, y, z (numbers), exactly 4
        // columns; header lines at the top (no number in x, y, z) skipped
        numericTable::settings s;
        s.numericColumns = labelList({1, 2, 3});
        s.nColumns = 4;
        s.collect = true;
        s.what = "the sensor file";
        const numericTable table(file, s);

        const char* axis[3] = {"x", "y", "z"};

        // "line N \"text\": "
        auto whereLine = [](const label n, const std::string& text)
        {
            return
                "line " + std::to_string(n) + " \"" + text + "\": ";
        };

        // The errors of the reader, and the sensors of its rows, in the
        // order of the lines
        const std::vector<numericTable::error>& tableErrors = table.errors();
        std::size_t ei = 0;
        label rowi = 0;

        while (ei < tableErrors.size() || rowi < table.size())
        {
            const bool takeError =
                ei < tableErrors.size()
             && (
                    rowi >= table.size()
                 || tableErrors[ei].line < table.line(rowi)
                );

            if (takeError)
            {
                const numericTable::error& e = tableErrors[ei++];
                const std::string first
                (
                    e.fields.size() ? e.fields[0] : std::string()
                );
                switch (e.kind)
                {
                    case numericTable::errorKind::open:
                        addError
                        (
                            -1,
                            "cannot open the sensor file (missing or"
                            " unreadable)"
                        );
                        break;
                    case numericTable::errorKind::noData:
                        addError(-1, "no sensors in the file");
                        break;
                    case numericTable::errorKind::tooFewColumns:
                    case numericTable::errorKind::wrongColumns:
                        addError
                        (
                            e.line,
                            whereLine(e.line, e.text) + "sensor '" + first
                          + "': expected 4 columns (name, x, y, z), found "
                          + std::to_string(e.fields.size())
                        );
                        break;
                    case numericTable::errorKind::empty:
                    case numericTable::errorKind::notNumber:
                    case numericTable::errorKind::notFinite:
                    case numericTable::errorKind::overflow:
                        addError
                        (
                            e.line,
                            whereLine(e.line, e.text) + "sensor '" + first
                          + "': " + axis[e.column - 1] + " = '" + e.field
                          + "' is " + numericTable::describe(e.kind)
                        );
                        break;
                    default:
                        addError
                        (
                            e.line,
                            e.line > 0
                          ? whereLine(e.line, e.text) + e.message
                          : e.message
                        );
                }
                continue;
            }

            const label lineNo = table.line(rowi);
            const std::string& name = table.field(rowi, 0);
            const std::string& text = table.text(rowi);
            const scalar xyz[3] =
            {
                table.value(rowi, 1),
                table.value(rowi, 2),
                table.value(rowi, 3)
            };
            ++rowi;

            bool validName = !name.empty();
            for (const char c : name)
            {
                validName = validName && word::valid(c);
            }
            if (!validName)
            {
                addError
                (
                    lineNo,
                    whereLine(lineNo, text) + "sensor name '" + name
                  + "' contains white space, a quote or one of / ; { }"
                );
                continue;
            }

            const word sensor(name, false);
            const auto iter = firstLine.cfind(sensor);
            if (iter.found())
            {
                addError
                (
                    lineNo,
                    whereLine(lineNo, text) + "duplicate sensor name '"
                  + name + "' (first at line " + std::to_string(*iter)
                  + ")"
                );
                continue;
            }

            firstLine.insert(sensor, lineNo);
            nms.append(sensor);
            pts.append(point(xyz[0], xyz[1], xyz[2]));
            lns.append(lineNo);
        }

        positions.transfer(pts);
        names.transfer(nms);
        lines.transfer(lns);
        errorLines.transfer(errLns);
        errors.transfer(errs);
    }

    Pstream::scatter(positions);
    Pstream::scatter(names);
    Pstream::scatter(lines);
    Pstream::scatter(errorLines);
    Pstream::scatter(errors);
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

Foam::labelList Foam::functionObjects::thermocouples::locate
(
    const fvMesh& mesh
)
{
    // probes' search (its warnings silenced: replaced by ours)
    {
        silence quiet;
        probes::findElements(mesh);
    }

    // Keep each sensor on the lowest-numbered processor that found it
    labelList owner(size(), Pstream::nProcs());
    nFound_.setSize(size());
    nFound_ = 0;
    forAll(owner, i)
    {
        if (elementList_[i] != -1)
        {
            owner[i] = Pstream::myProcNo();
            nFound_[i] = 1;
        }
    }
    Pstream::listCombineGather(owner, minEqOp<label>());
    Pstream::listCombineScatter(owner);
    Pstream::listCombineGather(nFound_, plusEqOp<label>());
    Pstream::listCombineScatter(nFound_);

    DynamicList<label> outside;
    forAll(owner, i)
    {
        if (owner[i] != Pstream::myProcNo())
        {
            elementList_[i] = -1;
            faceList_[i] = -1;
        }

        if (owner[i] == Pstream::nProcs())
        {
            processor_[i] = -1;
            outside.append(i);
        }
        else
        {
            processor_[i] = owner[i];
        }
    }

    return labelList(std::move(outside));
}


void Foam::functionObjects::thermocouples::warnOnBoundary() const
{
    // Per sensor the boundary patch it lies on in its cell (-1: none), on
    // the rank that holds it, then on every rank
    labelList onPatch(size(), -1);
    const polyBoundaryMesh& bMesh = mesh_.boundaryMesh();
    forAll(onPatch, i)
    {
        const label celli = elementList_[i];
        if (celli < 0) continue;
        const scalar h = cbrt(mesh_.cellVolumes()[celli]);
        for (const label facei : mesh_.cells()[celli])
        {
            if (mesh_.isInternalFace(facei)) continue;
            const label patchi = bMesh.whichPatch(facei);
            const polyPatch& pp = bMesh[patchi];
            if
            (
                pp.coupled() || isA<emptyPolyPatch>(pp)
             || isA<wedgePolyPatch>(pp) || isA<symmetryPlanePolyPatch>(pp)
             || isA<symmetryPolyPatch>(pp)
            )
            {
                continue;
            }
            const vector& Sf = mesh_.faceAreas()[facei];
            const scalar d =
                mag((operator[](i) - mesh_.faceCentres()[facei]) & Sf)
               /max(mag(Sf), VSMALL);
            if (d <= 1e-9*h) onPatch[i] = patchi;
        }
    }
    Pstream::listCombineGather(onPatch, maxEqOp<label>());
    Pstream::listCombineScatter(onPatch);
    forAll(onPatch, i)
    {
        if (onPatch[i] < 0) continue;
        WarningInFunction
            << "Sensor " << names_[i] << ' ' << operator[](i) << " (line "
            << lines_[i] << " of " << sensorFile_ << ") lies on the"
            << " boundary patch " << bMesh[onPatch[i]].name() << nl
            << "    Found in a cell here, but a point exactly on the"
            << " boundary may be found in no cell on another mesh or"
            << " decomposition (then an error): move it slightly inside"
            << endl;
    }
}


void Foam::functionObjects::thermocouples::fatal
(
    const labelList& errorLines,
    const List<string>& errors,
    const label nOutside
) const
{
    // The errors in the order of the lines
    const labelList order(sortedOrder(errorLines));

    OSstream& os =
        FatalIOError
        (
            FUNCTION_NAME, __FILE__, __LINE__,
            sensorFile_, errorLines[order[0]], -1
        );

    os  << "Sensor file " << sensorFile_ << " of function object '"
        << name() << "' (" << typeName << "): " << errors.size()
        << " error(s)";

    forAll(order, k)
    {
        if (k == maxListed)
        {
            os  << nl << "    ... and " << errors.size() - maxListed
                << " more";
            break;
        }
        os  << nl << "    " << errors[order[k]].c_str();
    }

    if (errors.size() > nOutside)
    {
        os  << nl << "Each line: name, x, y, z (metres), separated by"
            << " commas or white space; '#' starts a comment; optional"
            << " header line";
    }
    if (nOutside)
    {
        os  << nl << "The mesh spans " << mesh_.bounds() << " m. A sensor"
            << " exactly on the outer boundary of the mesh may not be"
            << " found: move it slightly inside";
    }

    os  << exit(FatalIOError);
}


void Foam::functionObjects::thermocouples::addOutside
(
    const labelList& outside,
    DynamicList<label>& errorLines,
    DynamicList<string>& errors
) const
{
    for (const label i : outside)
    {
        OStringStream msg;
        msg << "line " << lines_[i] << ": sensor '" << names_[i].c_str()
            << "' at " << operator[](i) << " m is outside the mesh";
        if (Pstream::parRun())
        {
            msg << " (of every processor)";
        }
        errorLines.append(lines_[i]);
        errors.append(msg.str());
    }
}


void Foam::functionObjects::thermocouples::openFile()
{
    csvPtr_.clear();

    if (!Pstream::master())
    {
        return;
    }

    const fileName file(csvFile());
    mkDir(file.path());
    csvPtr_.reset(new OFstream(file));

    OFstream& os = *csvPtr_;
    os  << "time_s";
    for (const word& n : names_)
    {
        os  << ',' << n.c_str();
    }
    os  << endl;
}


bool Foam::functionObjects::thermocouples::writeRow()
{
    const volScalarField* fieldPtr =
        mesh_.findObject<volScalarField>(fieldName_);

    // Same answer on all ranks (the field is registered on all or none)
    if (!returnReduce(fieldPtr != nullptr, andOp<bool>()))
    {
        return false;
    }

    // Sampled and gathered by probes: all values on all ranks
    scalarField values(sample(*fieldPtr));

    if (unit_ == "C")
    {
        values -= zeroCelsius;
    }

    if (Pstream::master() && csvPtr_.valid())
    {
        OFstream& os = *csvPtr_;

        os.precision(12);
        os  << mesh_.time().value();

        os.precision(precision_);
        for (const scalar v : values)
        {
            os  << ',' << v;
        }
        os  << endl;
    }

    return true;
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

void Foam::functionObjects::thermocouples::findElements(const fvMesh& mesh)
{
    const labelList outside(locate(mesh));

    if (outside.size())
    {
        DynamicList<label> errorLines;
        DynamicList<string> errors;
        addOutside(outside, errorLines, errors);
        fatal(errorLines, errors, outside.size());
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::thermocouples::thermocouples
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    probes(name, runTime, dict, false, false),
    sensorFile_(),
    fieldName_("T"),
    unit_("C"),
    precision_(10),
    names_(),
    lines_(),
    nFound_(),
    csvPtr_()
{
    read(dict);
}


Foam::fileName Foam::functionObjects::thermocouples::sensorFilePath
(
    const dictionary& foDict,
    const fileName& caseDir
)
{
    fileName file(foDict.get<fileName>("file"));
    file.expand();
    if (!file.isAbsolute())
    {
        file = caseDir/file;
    }
    file.clean();
    return file;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::fileName Foam::functionObjects::thermocouples::csvFile() const
{
    fileName dir = mesh_.time().globalPath()/functionObject::outputPrefix/name();

    if (mesh_.name() != polyMesh::defaultRegion)
    {
        dir = dir/mesh_.name();
    }
    dir = dir/mesh_.time().timeName();
    dir.clean();

    return dir/"sensors.csv";
}


bool Foam::functionObjects::thermocouples::read(const dictionary& dict)
{
    // The output so far (a re-read with the same output keeps its file)
    const string oldSettings
    (
        fieldName_ + ' ' + interpolationScheme_ + ' ' + unit_
    );

    // Unknown keywords (a misspelt 'unit' would silently give C)
    {
        wordList known(checkedRead::functionObjectKeywords());
        known.append
        (
            wordList({"file", "field", "interpolationScheme", "unit", "precision"})
        );
        checkedRead::checkKeywords
        (
            dict, known, "function object " + name() + " (thermocouples)"
        );
    }

    // Settings
    sensorFile_ = sensorFilePath(dict, mesh_.time().globalPath());

    fieldName_ = dict.getOrDefault<word>("field", "T");

    interpolationScheme_ =
        dict.getOrDefault<word>("interpolationScheme", "cellLinear");
    if
    (
        !interpolation<scalar>::dictionaryConstructorTablePtr_
     || !interpolation<scalar>::dictionaryConstructorTablePtr_->found
        (
            interpolationScheme_
        )
    )
    {
        FatalIOErrorInFunction(dict)
            << "Unknown interpolationScheme " << interpolationScheme_
            << " in function object '" << name() << "'; valid schemes: "
            << interpolation<scalar>::dictionaryConstructorTablePtr_
               ->sortedToc()
            << exit(FatalIOError);
    }

    unit_ = dict.getOrDefault<word>("unit", "C");
    if (unit_ != "C" && unit_ != "K")
    {
        FatalIOErrorInFunction(dict)
            << "unit " << unit_ << " in function object '" << name()
            << "' is neither C nor K" << exit(FatalIOError);
    }

    if (dict.found("precision"))
    {
        checkedRead::checkNumbers
        (
            dict, "precision", "an integer in [1, 17] (significant digits)"
        );
    }
    precision_ = checkedRead::getLabelOrDefault(dict, "precision", 10, 1, 17);
    if (precision_ < 1 || precision_ > 17)
    {
        FatalIOErrorInFunction(dict)
            << "precision " << precision_ << " in function object '"
            << name() << "' is outside [1, 17]" << exit(FatalIOError);
    }

    // probes' settings: sample fieldName_ at fixed locations
    fieldSelection_ = wordRes(1, wordRe(fieldName_));
    fixedLocations_ = true;
    includeOutOfBounds_ = true;

    // Sensors: the file's errors and the sensors outside the mesh are
    // reported together, in the order of the lines
    pointField positions;
    wordList names;
    labelList lines;
    labelList fileErrorLines;
    List<string> fileErrors;
    readSensorFile
    (
        sensorFile_, positions, names, lines, fileErrorLines, fileErrors
    );

    const bool changed =
    (
        names != names_
     || positions != static_cast<const pointField&>(*this)
     || oldSettings != fieldName_ + ' ' + interpolationScheme_ + ' ' + unit_
    );

    names_.transfer(names);
    lines_.transfer(lines);
    static_cast<pointField&>(*this) = positions;

    const labelList outside(locate(mesh_));
    if (changed)
    {
        warnOnBoundary();
    }

    if (fileErrors.size() || outside.size())
    {
        DynamicList<label> errorLines(fileErrorLines);
        DynamicList<string> errors(fileErrors);
        addOutside(outside, errorLines, errors);
        fatal(errorLines, errors, outside.size());
    }

    if (changed)
    {
        Info<< type() << ' ' << name() << ": " << size() << " sensors from "
            << sensorFile_ << ", field " << fieldName_ << " ("
            << interpolationScheme_ << ") in " << unit_ << nl;
        forAll(names_, i)
        {
            Info<< "    " << names_[i] << ' ' << operator[](i);
            if (Pstream::parRun())
            {
                Info<< " on processor " << processor_[i];
                if (nFound_[i] > 1)
                {
                    Info<< " (found on " << nFound_[i] << " processors:"
                        << " on their boundary)";
                }
            }
            Info<< nl;
        }

        openFile();

        if (writeRow())
        {
            Info<< "    writing " << csvFile() << nl;
        }
        else
        {
            Info<< "    writing " << csvFile() << " (field " << fieldName_
                << " not yet available: no row at time "
                << mesh_.time().timeName() << ')' << nl;
        }
        Info<< endl;
    }

    return true;
}


bool Foam::functionObjects::thermocouples::execute()
{
    return true;
}


bool Foam::functionObjects::thermocouples::write()
{
    if (!writeRow())
    {
        FatalErrorInFunction
            << "Function object '" << name() << "': no volScalarField "
            << fieldName_ << " in the registry of mesh " << mesh_.name()
            << exit(FatalError);
    }

    return true;
}


// ************************************************************************* //
