/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "pendularState.H"
#include "checkedRead.H"
#include "temperatureCheck.H"
#include "surfaceHeatLossFvPatchScalarField.H"
#include "fireTemperatureFvPatchScalarField.H"
#include "waterModel.H"
#include "liquidFlow.H"
#include "fvc.H"
#include "upwind.H"
#include "fixedValueFvPatchFields.H"
#include "zeroGradientFvPatchFields.H"
#include "StringStream.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// Boundary types of W, used by the linearised water equation only: fixed
// where vapour can leave (open and semi-permeable patches)
Foam::wordList WPatchTypes
(
    const Foam::volScalarField& p,
    const Foam::List<Foam::pendularState::patchKind>& kind
)
{
    using namespace Foam;
    wordList types(p.boundaryField().types());
    forAll(kind, patchi)
    {
        if
        (
            kind[patchi] == pendularState::patchKind::open
         || kind[patchi] == pendularState::patchKind::semiPermeable
        )
        {
            types[patchi] = fixedValueFvPatchScalarField::typeName;
        }
        else if (kind[patchi] == pendularState::patchKind::impermeable)
        {
            types[patchi] = zeroGradientFvPatchScalarField::typeName;
        }
    }
    return types;
}

Foam::IOobject readIO(const Foam::word& name, const Foam::fvMesh& mesh)
{
    return Foam::IOobject
    (
        name, mesh.time().timeName(), mesh, Foam::IOobject::MUST_READ,
        Foam::IOobject::AUTO_WRITE
    );
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::pendularState::pendularState(const fvMesh& mesh)
:
    mesh_(mesh),
    T_
    (
        (Info<< "Reading fields T, p, pw and alphaL\n" << endl,
        readIO("T", mesh)),
        mesh
    ),
    // At or below 0 K in a cell or on a patch, or a soil colder than 200 K
    // (Celsius typed as kelvin): FatalIOError before any step.
    // Gas (air + vapour) pressure p_g: an unknown; its boundary conditions
    // say where the soil is open (fixed) or impermeable (zeroGradient)
    p_
    (
        (
            checkedRead::checkDimensions(T_, dimTemperature),
            temperatureCheck::initial(T_),
            readIO("p", mesh)
        ),
        mesh
    ),
    // Vapour partial pressure p_w: in the cells the Kelvin-Laplace
    // equilibrium with the menisci; on open patches the atmosphere's
    pw_
    (
        (checkedRead::checkDimensions(p_, dimPressure), readIO("pw", mesh)),
        mesh
    ),
    // Liquid fraction of the pore volume: the initial state, then a result
    alphaL_
    (
        (
            checkedRead::checkDimensions(pw_, dimPressure),
            readIO("alphaL", mesh)
        ),
        mesh
    ),
    medium_
    (
        (
            checkedRead::checkDimensions(alphaL_, dimless),
            Info<< "Reading pendular properties\n" << endl,
            mesh
        )
    ),
    muGas_("muGas", dimDynamicViscosity, medium_.gasViscosity()),
    Dv_
    (
        IOobject("Dv", mesh.time().timeName(), mesh),
        mesh,
        dimensionedScalar(dimViscosity, Zero),
        zeroGradientFvPatchScalarField::typeName
    ),
    Dvf_
    (
        IOobject("Dvf", mesh.time().timeName(), mesh),
        mesh,
        dimensionedScalar(dimViscosity, Zero)
    ),
    kind_
    (
        (
            checkedRead::check
            (
                alphaL_.objectPath(), "alphaL", alphaL_.primitiveField(),
                medium_.saturatedZone()
              ? checkedRead::closed(0, 1)
              : checkedRead::closedOpen(0, 1)
            ),
            // p_g > 0, T within the saturation laws, no liquid near the
            // critical point, air pressure >= 0
            medium_.checkInitialState(T_, p_, alphaL_),
            patchKinds(p_, pw_)
        )
    ),
    W_
    (
        IOobject("W", mesh.time().timeName(), mesh, IOobject::NO_READ,
            IOobject::AUTO_WRITE),
        mesh,
        dimensionedScalar(dimDensity, Zero),
        WPatchTypes(p_, kind_)
    ),
    WScale_(0),
    pa_(IOobject("pa", mesh.time().timeName(), mesh), p_ - pw_),
    rhoW_
    (
        IOobject("rhoW", mesh.time().timeName(), mesh, IOobject::NO_READ,
            IOobject::AUTO_WRITE),
        pw_*dimensionedScalar("MwByR", dimMass*dimTemperature/dimEnergy,
            medium_.Mw()/medium_.R())/T_
    ),
    rhoA_("rhoA", rhoW_),
    rhoG_("rhoG", rhoW_),
    omegaW_
    (
        IOobject("omegaW", mesh.time().timeName(), mesh),
        mesh,
        dimensionedScalar(dimless, Zero)
    ),
    RH_
    (
        IOobject("RH", mesh.time().timeName(), mesh, IOobject::NO_READ,
            IOobject::AUTO_WRITE),
        mesh,
        dimensionedScalar(dimless, Zero)
    ),
    // Specific enthalpies of the vapour and of the air [J/kg]
    hW_
    (
        IOobject("hW", mesh.time().timeName(), mesh),
        mesh,
        dimensionedScalar(dimEnergy/dimMass, Zero)
    ),
    hA_("hA", hW_),
    Kg_
    (
        IOobject("Kg", mesh.time().timeName(), mesh),
        mesh,
        dimensionedScalar(dimArea, Zero),
        zeroGradientFvPatchScalarField::typeName
    ),
    kappa_
    (
        IOobject("kappa", mesh.time().timeName(), mesh),
        mesh,
        dimensionedScalar(dimPower/dimLength/dimTemperature, Zero),
        zeroGradientFvPatchScalarField::typeName
    ),
    E_
    (
        IOobject("E", mesh.time().timeName(), mesh),
        mesh,
        dimensionedScalar(dimEnergy/dimVolume, Zero)
    ),
    A_
    (
        IOobject("A", mesh.time().timeName(), mesh),
        mesh,
        dimensionedScalar(dimDensity, Zero)
    ),
    q_
    (
        IOobject("q", mesh.time().timeName(), mesh),
        mesh,
        dimensionedScalar(dimVolume/dimTime, Zero)
    ),
    Fw_("Fw", q_*dimensionedScalar(dimDensity, Zero)),
    Fa_("Fa", Fw_),
    FE_("FE", q_*dimensionedScalar(dimPressure, Zero)),
    alphaOld_(alphaL_.primitiveField()),
    stepDeltaT_(0),
    saturationStates_
    (
        mesh.nCells(), pendularMedium::saturationState{-1, 0, 0, 0, 0, false}
    ),
    W0_(),
    A0_(),
    E0_(),
    gasPresent_
    (
        IOobject
        (
            "gasPresent", mesh.time().timeName(), mesh,
            IOobject::NO_READ,
            medium_.saturatedZone()
          ? IOobject::AUTO_WRITE : IOobject::NO_WRITE
        ),
        mesh,
        dimensionedScalar("one", dimless, 1),
        zeroGradientFvPatchScalarField::typeName
    ),
    Xair_
    (
        IOobject
        (
            "Xair", mesh.time().timeName(), mesh,
            IOobject::NO_READ,
            medium_.saturatedZone()
          ? IOobject::AUTO_WRITE : IOobject::NO_WRITE
        ),
        mesh,
        dimensionedScalar(dimless, Zero),
        zeroGradientFvPatchScalarField::typeName
    ),
    pl_
    (
        IOobject
        (
            "pl", mesh.time().timeName(), mesh,
            IOobject::NO_READ,
            medium_.saturatedZone()
          ? IOobject::AUTO_WRITE : IOobject::NO_WRITE
        ),
        mesh,
        dimensionedScalar(dimPressure, Zero),
        zeroGradientFvPatchScalarField::typeName
    )
{
    readPhaseStates();

    const scalarField& porosity = medium_.porosity().primitiveField();
    forAll(W_, celli)
    {
        W_[celli] =
            liquidOnly(celli)
          ? liquidOnlyClosure
            (
                medium_, porosity[celli], T_[celli], pl_[celli], Xair_[celli]
            ).W
          : medium_.waterContent(alphaL_[celli], T_[celli], porosity[celli]);
    }

    WScale_ = gMax(W_.primitiveField());
    forAll(W_, celli)
    {
        WScale_ =
            max
            (
                WScale_,
                porosity[celli]*medium_.Mw()
               *medium_.saturationPressure(T_[celli])
               /(medium_.R()*T_[celli])
            );
    }
    reduce(WScale_, maxOp<scalar>());

    // The cell values of p_w are computed (update): an internalField given
    // in the start time's pw other than them (and than the placeholder 0)
    // is not used, said in one line
    const scalarField pwRead(pw_.primitiveField());

    checkOpenPatches();
    checkOpenPatchHistories();
    warnAboveTestedRange();

    // A mesh without a physical boundary face (every patch empty, wedge,
    // symmetry or coupled): nothing can enter or leave, said in one line
    // (hostile testing 2026-12-05b, 7: it ran with balances of 0, silent)
    {
        label nPhysical = 0;
        for (const fvPatch& fp : mesh_.boundary())
        {
            if (!polyPatch::constraintType(fp.patch().type()))
            {
                nPhysical += fp.size();
            }
        }
        if (returnReduce(nPhysical, sumOp<label>()) == 0)
        {
            Info<< "Note: the mesh has no physical boundary face (every"
                << " patch empty, wedge, symmetry or coupled): no heat, gas"
                << " or water can enter or leave, the state only relaxes"
                << endl;
        }
    }
    update();

    scalar pwIgnored = 0;
    forAll(pwRead, celli)
    {
        const scalar d = mag(pwRead[celli] - pw_[celli]);
        if (pwRead[celli] != 0 && d > 1e-3*(mag(pw_[celli]) + 1))
        {
            pwIgnored = max(pwIgnored, d);
        }
    }
    reduce(pwIgnored, maxOp<scalar>());
    if (pwIgnored > 0)
    {
        Info<< "Note: the internalField of " << pw_.name() << " in "
            << mesh_.time().timeName() << " (up to " << pwIgnored
            << " Pa from the computed p_w) is not used: p_w in the cells is"
            << " computed from T and alpha_L (Kelvin-Laplace equilibrium);"
            << " only its boundary conditions are read" << endl;
    }

    fluxes();
    storeOld();
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::pendularState::readPhaseStates()
{
    const fvMesh& mesh = mesh_;
    const word timeName(mesh.time().timeName());
    const wordList names({"gasPresent", "Xair", "pl"});
    const List<volScalarField*> fields({&gasPresent_, &Xair_, &pl_});
    const dimensionSet* dims[] = {&dimless, &dimless, &dimPressure};

    // A dictionary named after a file, for FatalIOError
    auto fileDict = [](const fileName& file)
    {
        dictionary dict;
        dict.name() = file;
        return dict;
    };
    // The path of field name on processor proci (the case's in serial)
    auto pathOn = [&](const word& name, const label proci)
    {
        if (!Pstream::parRun())
        {
            return fileName(mesh.time().path()/timeName/name);
        }
        return fileName
        (
            mesh.time().rootPath()/mesh.time().globalCaseName()
           /("processor" + Foam::name(proci))/timeName/name
        );
    };

    // Which of the three are given, on every processor alike: the
    // processors holding each (a field on some processors only is an
    // error, not a start that differs from one processor to the next)
    List<bool> given(names.size(), false);
    forAll(names, i)
    {
        labelList has(Pstream::nProcs(), 0);
        has[Pstream::myProcNo()] =
            IOobject
            (
                names[i], timeName, mesh, IOobject::MUST_READ
            ).typeHeaderOk<volScalarField>(true);
        Pstream::gatherList(has);
        Pstream::scatterList(has);
        given[i] = (has.find(1) != -1);
        const label missing = has.find(0);
        if (given[i] && missing != -1)
        {
            FatalIOErrorInFunction(fileDict(pathOn(names[i], missing)))
                << "Field " << names[i] << " missing in "
                << pathOn(names[i], missing) << " but given in "
                << pathOn(names[i], has.find(1)) << ": the"
                << " processors must all have it or none (decompose the"
                << " case's fields again)" << exit(FatalIOError);
        }
    }

    if (!medium_.saturatedZone())
    {
        forAll(names, i)
        {
            if (given[i])
            {
                const fileName file(pathOn(names[i], Pstream::myProcNo()));
                FatalIOErrorInFunction(fileDict(file))
                    << "Field " << names[i] << " given in " << file
                    << " without saturatedZone: it is used only by the"
                    << " saturated zone (the sub-dictionary saturatedZone"
                    << " of liquidFlow in " << medium_.closureDict().name()
                    << "); remove the file, or add saturatedZone"
                    << exit(FatalIOError);
            }
        }
        return;
    }

    // Without gasPresent: the cells start from alphaL (below); Xair or pl
    // alone would be ignored
    if (!given[0])
    {
        for (label i : {1, 2})
        {
            if (given[i])
            {
                const fileName file(pathOn(names[i], Pstream::myProcNo()));
                FatalIOErrorInFunction(fileDict(file))
                    << "Field " << names[i] << " given in " << file
                    << " without gasPresent ("
                    << pathOn(names[0], Pstream::myProcNo()) << " missing):"
                    << " a chosen start of the saturated zone needs"
                    << " gasPresent, Xair and pl (as pendularFoam writes"
                    << " them); without gasPresent the cells start from"
                    << " alphaL (liquid-only at the bubble point where"
                    << " alphaL = 1): give gasPresent, or remove Xair and pl"
                    << exit(FatalIOError);
            }
        }
    }
    else
    {
        for (label i : {1, 2})
        {
            if (!given[i])
            {
                const fileName file(pathOn(names[i], Pstream::myProcNo()));
                FatalIOErrorInFunction(fileDict(file))
                    << "Field " << names[i] << " missing: " << file
                    << " not found, while gasPresent is given in "
                    << pathOn(names[0], Pstream::myProcNo()) << ": a"
                    << " chosen start (or a restart) of the saturated zone"
                    << " needs gasPresent, Xair and pl (as pendularFoam"
                    << " writes them)" << exit(FatalIOError);
            }
        }
    }

    if (!given[0])
    {
        // Liquid-only where alphaL = 1, with p_l = p - p_c(1, T) and X =
        // Henry's at p_a = p - p_w(T, 1): the state at the bubble point,
        // W = phi rho_l (pendularMedium's Description; p is then the DuMux
        // convention p_l + p_c(1))
        forAll(gasPresent_, celli)
        {
            if (alphaL_[celli] >= 1)
            {
                const scalar Tc = T_[celli];
                gasPresent_[celli] = 0;
                pl_[celli] = p_[celli] - medium_.pcSaturated(Tc);
                Xair_[celli] =
                    medium_.dissolvedAir
                    (
                        p_[celli] - medium_.saturatedVapourPressure(Tc), Tc
                    );
            }
        }
        gasPresent_.correctBoundaryConditions();
        return;
    }

    // A chosen start or a restart: the three fields, their dimensions
    forAll(names, i)
    {
        const volScalarField fld
        (
            IOobject
            (
                names[i], timeName, mesh, IOobject::MUST_READ,
                IOobject::NO_WRITE, false
            ),
            mesh
        );
        checkedRead::checkDimensions(fld, *dims[i]);
        fields[i]->primitiveFieldRef() = fld.primitiveField();
    }
    const fileName gFile(pathOn(names[0], Pstream::myProcNo()));
    const fileName XFile(pathOn(names[1], Pstream::myProcNo()));
    const fileName plFile(pathOn(names[2], Pstream::myProcNo()));

    // The phase state of a cell and the liquid fraction agree: a
    // liquid-only cell (gasPresent 0) holds only liquid, alphaL = 1; a cell
    // with gas (gasPresent 1) any alphaL in [0, 1], 1 included (the bubble
    // point, where the two closures agree, and what a liquid fraction
    // within 5e-11 of 1 is written as with 10 digits): warned, as the
    // phase switching decides there at the first step
    label nBubble = 0;
    label firstBubble = -1;
    forAll(gasPresent_, celli)
    {
        if (gasPresent_[celli] == 1 && alphaL_[celli] >= 1)
        {
            if (firstBubble == -1)
            {
                firstBubble = celli;
            }
            ++nBubble;
        }
        const scalar g = gasPresent_[celli];
        if (g != 0 && g != 1)
        {
            FatalIOErrorInFunction(fileDict(gFile))
                << "Field 'gasPresent' (keyword 'internalField') = "
                << g << " in cell " << celli << ", in file " << gFile << nl
                << "    Valid: 0 (liquid-only) or 1 (gas present)"
                << exit(FatalIOError);
        }
        if (g == 0 && alphaL_[celli] < 1)
        {
            FatalIOErrorInFunction(fileDict(gFile))
                << "Field 'gasPresent' (keyword 'internalField') = 0"
                << " (liquid-only) in cell " << celli << ", in file " << gFile
                << ", where alphaL = " << alphaL_[celli] << " < 1 (file "
                << alphaL_.objectPath() << "): inconsistent." << nl
                << "    Valid: a liquid-only cell (gasPresent 0) has alphaL"
                << " = 1; a cell with alphaL < 1 holds gas (gasPresent 1)"
                << exit(FatalIOError);
        }
    }

    if (returnReduce(nBubble, sumOp<label>()) > 0 && firstBubble != -1)
    {
        WarningInFunction
            << nBubble << " cell(s) with gas (gasPresent 1 in " << gFile
            << ") at alphaL = 1 (the first: cell " << firstBubble << ", file "
            << alphaL_.objectPath() << "): at the bubble point, where the"
            << " gas-present and liquid-only states agree; the phase"
            << " switching decides their state at the first step" << endl;
    }

    // The liquid-only cells' (T, p_l, X). The bubble point of a cell is
    //     p_b = p_w(T, 1) + p_a(X, T) - p_c(1, T),
    // p_a(X, T) = X rho_l/(M_a H^cp(T)) the air pressure in Henry's
    // equilibrium with the dissolved X (Henry's law, Sander 2015; the
    // closure of liquidOnlyClosure): below p_b a bubble grows, the gas is
    // present. Hence, in a liquid-only cell,
    //     p_w(T, 1) - p_c(1, T) <= p_l   (the bubble point without air)
    //     0 <= X <= X_max = M_a H^cp(T) (p_l + p_c(1, T) - p_w(T, 1))/rho_l
    // (X_max: Henry's X at an air pressure equal to the gas pressure of a
    // bubble, p_l + p_c(1), less its vapour), and
    //     p_l <= p_b + 0.05/c_s
    // the storage law W = phi rho_l (1 + c_s (p_l - p_b)) being linear, a
    // first-order expansion, held to a 5 % change of the liquid's density
    // (water's c_s = 4.5e-10 1/Pa: 1.1e8 Pa, about the 4 % water is
    // denser at 100 MPa, IAPWS-95). In cells with gas, Xair and pl follow
    // from (T, p_g, alphaL) by the closure (files' values unused)
    const scalar plSpan = 0.05/medium_.storage();
    forAll(gasPresent_, celli)
    {
        if (!liquidOnly(celli))
        {
            continue;
        }
        const scalar Tc = T_[celli];
        const scalar pl = pl_[celli];
        const scalar X = Xair_[celli];
        const scalar pw1 = medium_.saturatedVapourPressure(Tc);
        const scalar pc1 = medium_.pcSaturated(Tc);
        const scalar plMin = pw1 - pc1;
        if (!std::isfinite(pl) || pl < plMin)
        {
            FatalIOErrorInFunction(fileDict(plFile))
                << "Field 'pl' (keyword 'internalField') = " << pl
                << " Pa in the liquid-only cell " << celli << " (T = " << Tc
                << " K) is below the bubble point without air, p_w(T, 1)"
                << " - p_c(1, T) = " << plMin << " Pa, in file " << plFile
                << nl << "    Valid: p_l in [p_b, p_b + 0.05/c_s], p_b = "
                << "p_w(T, 1) + p_a(X, T) - p_c(1, T) the bubble point (in"
                << " this cell [" << plMin + medium_.airPressure(max(X, scalar(0)), Tc)
                << ", " << plMin + medium_.airPressure(max(X, scalar(0)), Tc) + plSpan
                << "] Pa); below it the gas is present (gasPresent 1)"
                << exit(FatalIOError);
        }
        const scalar XMax = medium_.dissolvedAir(pl - plMin, Tc);
        if (!std::isfinite(X) || X < 0 || X > XMax)
        {
            FatalIOErrorInFunction(fileDict(XFile))
                << "Field 'Xair' (keyword 'internalField') = " << X
                << " in the liquid-only cell " << celli << " (T = " << Tc
                << " K, p_l = " << pl << " Pa) is outside its valid range"
                << " [0, " << XMax << "] in file " << XFile << nl
                << "    Valid: 0 <= X <= X_max = M_a H^cp(T) (p_l + p_c(1, T)"
                << " - p_w(T, 1))/rho_l, Henry's dissolved air at the air"
                << " pressure of a bubble at p_l (above it the liquid is"
                << " below its bubble point: the gas is present,"
                << " gasPresent 1)" << exit(FatalIOError);
        }
        const scalar pb = plMin + medium_.airPressure(X, Tc);
        if (pl > pb + plSpan)
        {
            FatalIOErrorInFunction(fileDict(plFile))
                << "Field 'pl' (keyword 'internalField') = " << pl
                << " Pa in the liquid-only cell " << celli << " (T = " << Tc
                << " K) is above its valid range [p_b, p_b + 0.05/c_s] = ["
                << pb << ", " << pb + plSpan << "] Pa in file " << plFile
                << nl << "    (p_b the bubble point; the storage law W = phi"
                << " rho_l (1 + c_s (p_l - p_b)), c_s = "
                << medium_.storage() << " 1/Pa, is held to a 5 % change of"
                << " the liquid's density)" << exit(FatalIOError);
        }
    }

    // p in a liquid-only cell is derived: p_l + p_c(1, T) (update()). A
    // value in 0/p that differs beyond the round-off of the written fields
    // (6 digits, OpenFOAM's default writePrecision) is overridden: warned
    label nOverridden = 0;
    label first = -1;
    forAll(gasPresent_, celli)
    {
        if (liquidOnly(celli))
        {
            const scalar pDerived = pl_[celli] + medium_.pcSaturated(T_[celli]);
            if (mag(p_[celli] - pDerived) > 1e-5*mag(pDerived))
            {
                if (first == -1)
                {
                    first = celli;
                }
                ++nOverridden;
            }
        }
    }
    if (returnReduce(nOverridden, sumOp<label>()) > 0)
    {
        if (first != -1)
        {
            WarningInFunction
                << nOverridden << " liquid-only cell(s) with p in "
                << p_.objectPath() << " other than p_l + p_c(1, T) (the"
                << " first: cell " << first << ", p = " << p_[first]
                << " Pa, p_l + p_c(1, T) = "
                << pl_[first] + medium_.pcSaturated(T_[first]) << " Pa from "
                << plFile << "): in a liquid-only cell p is derived from pl"
                << " (the gas pressure a bubble would have); the file's p"
                << " is not used there" << endl;
        }
    }
    gasPresent_.correctBoundaryConditions();
}


// * * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * //

Foam::List<Foam::pendularState::patchKind> Foam::pendularState::patchKinds
(
    const volScalarField& p,
    const volScalarField& pw
)
{
    const fvMesh& mesh = p.mesh();
    List<patchKind> kind(mesh.boundary().size(), patchKind::other);
    forAll(mesh.boundary(), patchi)
    {
        const fvPatch& patch = mesh.boundary()[patchi];
        if (patch.coupled() || polyPatch::constraintType(patch.type()))
        {
            continue;
        }
        const bool pFixed = p.boundaryField()[patchi].fixesValue();
        const bool pwFixed = pw.boundaryField()[patchi].fixesValue();
        if (pFixed && pwFixed)
        {
            kind[patchi] = patchKind::open;
        }
        else if (pwFixed)
        {
            kind[patchi] = patchKind::semiPermeable;
        }
        else if (!pFixed)
        {
            kind[patchi] = patchKind::impermeable;
        }
        else
        {
            FatalErrorInFunction
                << "Patch " << patch.name() << ": p is fixed but pw is free ("
                << p.objectPath() << ", " << pw.objectPath() << ")." << nl
                << "    Valid: p and pw fixed (open to the atmosphere), pw"
                << " fixed and p zeroGradient (semi-permeable: vapour but no"
                << " air), or both zeroGradient (impermeable)"
                << exit(FatalError);
        }
    }
    return kind;
}


Foam::pendularState::cellState Foam::pendularState::closure
(
    const pendularMedium& medium,
    const scalar phi,
    const scalar T,
    const scalar p,
    const scalar W,
    const scalar alpha,
    const scalar rhoW
)
{
    const scalar R = medium.R();
    cellState s;
    s.T = T;
    s.p = p;
    s.W = W;
    s.alpha = alpha;
    s.rhoW = rhoW;
    s.pw = rhoW*R*T/medium.Mw();
    s.pa = p - s.pw;
    s.rhoA = medium.Ma()*s.pa/(R*T);
    s.rhoG = s.rhoW + s.rhoA;
    // (rho_g = 0 exactly, the pole: omega 0, not a division by zero, which
    // traps under FOAM_SIGFPE; a state with rho_g <= 0 is outside the
    // model's range: pendularNewton::valid refuses such an iterate and
    // solveCellWater such a trial water, whose residuals are then not
    // used; a regula falsi converged onto it, the SIGFPE of 2026-12-04 in
    // tutorials/wetHearthCoupled/README.md)
    s.omega = s.rhoG != 0 ? s.rhoW/s.rhoG : 0;
    s.Kg = medium.Kg(alpha, phi);
    s.Dv = medium.vapourDiffusivity(alpha, phi);
    s.kappa = medium.kappa(alpha, phi);
    s.hW = medium.vapourEnthalpy(T);
    s.hA = medium.airEnthalpy(T);
    s.E = medium.energy(T, W, alpha, rhoW, s.pa, phi);
    s.A = phi*(1 - alpha)*s.rhoA;
    s.X = 0;
    s.liquidOnly = false;
    if (medium.saturatedZone())
    {
        // Henry's dissolved air in the liquid, with its enthalpy
        s.X = medium.dissolvedAir(s.pa, T);
        const scalar dissolved = phi*alpha*medium.rhoL()*s.X;
        s.A += dissolved;
        s.E += dissolved*medium.airEnthalpy(T);
    }
    return s;
}


Foam::pendularState::cellState Foam::pendularState::liquidOnlyClosure
(
    const pendularMedium& medium,
    const scalar phi,
    const scalar T,
    const scalar pl,
    const scalar X
)
{
    const scalar R = medium.R();
    const scalar pc1 = medium.pcSaturated(T);
    cellState s;
    s.T = T;
    s.p = pl + pc1;
    s.alpha = 1;
    s.pw = medium.saturatedVapourPressure(T);
    s.pa = medium.airPressure(X, T);
    // The bubble point p_b = p_w(T, 1) + p_a(X, T) - p_c(1, T)
    s.W =
        phi*medium.rhoL()
       *(1 + medium.storage()*(pl - (s.pw + s.pa - pc1)));
    s.rhoW = medium.Mw()*s.pw/(R*T);
    s.rhoA = medium.Ma()*s.pa/(R*T);
    s.rhoG = s.rhoW + s.rhoA;
    s.omega = s.rhoW/s.rhoG;
    s.Kg = 0;
    s.Dv = 0;
    s.kappa = medium.kappa(1, phi);
    s.hW = medium.vapourEnthalpy(T);
    s.hA = medium.airEnthalpy(T);
    s.X = X;
    s.A = s.W*X;
    s.E = medium.energy(T, s.W, 1, s.rhoW, s.pa, phi) + s.A*s.hA;
    s.liquidOnly = true;
    return s;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::pendularState::update()
{
    // State of the cells from the unknowns T, p (p_g) and W: the liquid
    // fraction holding W at T, the vapour pressure in equilibrium with it
    // (Kelvin-Laplace, model A; with model B the liquid fraction relaxed
    // over the step from alphaOld and the vapour of the rest of the
    // water), then closure(). Boundary values: T, p and pw from their
    // conditions; the derived fields from those.
    const scalar Mw = medium_.Mw();
    const scalar Ma = medium_.Ma();
    const scalar R = medium_.R();
    const scalarField& porosity = medium_.porosity().primitiveField();

    forAll(W_, celli)
    {
        const scalar phi = porosity[celli];
        const scalar Tc = T_[celli];
        if (saturationStates_[celli].T != Tc)
        {
            saturationStates_[celli] = medium_.saturation(Tc);
        }
        const pendularMedium::saturationState& sat = saturationStates_[celli];
        cellState s;
        if (liquidOnly(celli))
        {
            // No gas: the state of (T, p_l, X); p and W follow
            s = liquidOnlyClosure(medium_, phi, Tc, pl_[celli], Xair_[celli]);
            p_[celli] = s.p;
            W_[celli] = s.W;
        }
        else
        {
            scalar alpha, rhoW;
            medium_.water().liquidAndVapour
            (
                W_[celli], sat, phi, p_[celli], alphaOld_[celli],
                stepDeltaT_, alphaL_[celli], alpha, rhoW
            );
            s = closure(medium_, phi, Tc, p_[celli], W_[celli], alpha, rhoW);
            if (medium_.saturatedZone())
            {
                Xair_[celli] = s.X;
                pl_[celli] =
                    s.alpha > 0
                  ? s.p
                  + medium_.lnRelativeHumidity(s.alpha, sat)
                   *medium_.rhoL()*R*Tc/Mw
                  : 0;
            }
        }
        alphaL_[celli] = s.alpha;
        rhoW_[celli] = s.rhoW;
        pw_[celli] = s.pw;
        pa_[celli] = s.pa;
        rhoA_[celli] = s.rhoA;
        Kg_[celli] = s.Kg;
        Dv_[celli] = s.Dv;
        kappa_[celli] = s.kappa;
        E_[celli] = s.E;
        A_[celli] = s.A;
        RH_[celli] = s.pw/sat.pSat;
        hW_[celli] = s.hW;
        hA_[celli] = s.hA;
    }
    // Surface heat loss/flux: the surface temperature balancing the
    // condition's exact (nonlinear) flux with the half cell's conduction
    // (pendularResidual::boundaryState), not its linearisation; set
    // before the conditions of p_w, which may take it (relativeHumidity
    // without airTemperature: p_w = RH p_wsat(T_b), as the Newton
    // residual; before 2026-12-04 they took the condition's own value,
    // its last evaluation)
    forAll(T_.boundaryField(), patchi)
    {
        if (isA<surfaceHeatLossFvPatchScalarField>(T_.boundaryField()[patchi]))
        {
            const surfaceHeatLossFvPatchScalarField& Tp =
                refCast<const surfaceHeatLossFvPatchScalarField>
                (
                    T_.boundaryField()[patchi]
                );
            const labelUList& cells = mesh_.boundary()[patchi].faceCells();
            const scalarField& delta = mesh_.boundary()[patchi].deltaCoeffs();
            scalarField Tw(Tp.size());
            forAll(Tw, facei)
            {
                const label celli = cells[facei];
                Tw[facei] =
                    Tp.wallTemperature
                    (
                        T_[celli], kappa_[celli]*delta[facei]
                    );
            }
            T_.boundaryFieldRef()[patchi] == Tw;
        }
    }

    alphaL_.correctBoundaryConditions();
    pw_.correctBoundaryConditions();
    p_.correctBoundaryConditions();
    Kg_.correctBoundaryConditions();
    Dv_.correctBoundaryConditions();
    kappa_.correctBoundaryConditions();

    // Boundary values of the derived fields (coupled patches: neighbours)
    pa_.boundaryFieldRef() = p_.boundaryField() - pw_.boundaryField();
    rhoW_.boundaryFieldRef() = Mw*pw_.boundaryField()/(R*T_.boundaryField());
    rhoA_.boundaryFieldRef() = Ma*pa_.boundaryField()/(R*T_.boundaryField());
    pa_.correctBoundaryConditions();
    rhoW_.correctBoundaryConditions();
    rhoA_.correctBoundaryConditions();

    rhoG_ = rhoW_ + rhoA_;
    omegaW_ = rhoW_/rhoG_;
    forAll(hW_.boundaryField(), patchi)
    {
        const fvPatchScalarField& Tp = T_.boundaryField()[patchi];
        fvPatchScalarField& hWp = hW_.boundaryFieldRef()[patchi];
        fvPatchScalarField& hAp = hA_.boundaryFieldRef()[patchi];
        forAll(Tp, facei)
        {
            hWp[facei] = medium_.vapourEnthalpy(Tp[facei]);
            hAp[facei] = medium_.airEnthalpy(Tp[facei]);
        }
    }
    hW_.correctBoundaryConditions();
    hA_.correctBoundaryConditions();
    forAll(RH_.boundaryField(), patchi)
    {
        fvPatchScalarField& RHp = RH_.boundaryFieldRef()[patchi];
        const fvPatchScalarField& Tp = T_.boundaryField()[patchi];
        const fvPatchScalarField& pwp = pw_.boundaryField()[patchi];
        forAll(RHp, facei)
        {
            RHp[facei] = pwp[facei]/medium_.saturationPressure(Tp[facei]);
        }
    }
}


Foam::FixedList<Foam::List<Foam::scalarField>, 3>
Foam::pendularState::boundaryValues() const
{
    FixedList<List<scalarField>, 3> values;
    const volScalarField* fields[3] = {&T_, &p_, &pw_};
    forAll(values, k)
    {
        const volScalarField::Boundary& bf = fields[k]->boundaryField();
        values[k].setSize(bf.size());
        forAll(bf, patchi)
        {
            if (!bf[patchi].coupled())
            {
                values[k][patchi] = bf[patchi];
            }
        }
    }
    return values;
}


void Foam::pendularState::restoreBoundaryValues
(
    const FixedList<List<scalarField>, 3>& values
)
{
    volScalarField* fields[3] = {&T_, &p_, &pw_};
    forAll(values, k)
    {
        volScalarField::Boundary& bf = fields[k]->boundaryFieldRef();
        forAll(bf, patchi)
        {
            if (!bf[patchi].coupled())
            {
                bf[patchi] == values[k][patchi];
            }
        }
    }
}


Foam::tmp<Foam::surfaceScalarField> Foam::pendularState::upwindFaces
(
    const volScalarField& vf,
    const surfaceScalarField& flux
) const
{
    tmp<surfaceScalarField> tsf
    (
        upwind<scalar>(mesh_, flux).interpolate(vf)
    );
    surfaceScalarField& sf = tsf.ref();
    forAll(kind_, patchi)
    {
        if (kind_[patchi] == patchKind::open)
        {
            const scalarField inside
            (
                vf.boundaryField()[patchi].patchInternalField()
            );
            const fvsPatchScalarField& fluxp = flux.boundaryField()[patchi];
            fvsPatchScalarField& sfp = sf.boundaryFieldRef()[patchi];
            forAll(sfp, facei)
            {
                if (fluxp[facei] > 0)
                {
                    sfp[facei] = inside[facei];
                }
            }
        }
    }
    return tsf;
}


Foam::tmp<Foam::scalarField> Foam::pendularState::conductionGradient
(
    const label patchi
) const
{
    const fvPatchScalarField& Tp = T_.boundaryField()[patchi];
    if (isA<surfaceHeatLossFvPatchScalarField>(Tp))
    {
        return (Tp - Tp.patchInternalField())*Tp.patch().deltaCoeffs();
    }
    return Tp.snGrad();
}


void Foam::pendularState::fluxes()
{
    // The densities and enthalpies carried are those upwind of the flux;
    // through an open patch the gas leaving carries the cell's, the gas
    // entering the atmosphere's. Nothing crosses impermeable and
    // constraint patches but heat by conduction.
    const surfaceScalarField KgByMuf(fvc::interpolate(Kg_)/muGas_);
    const surfaceScalarField magSf(mesh_.magSf());
    const surfaceScalarField snGradP(fvc::snGrad(p_));
    q_ = -KgByMuf*snGradP*magSf;

    // With liquidFlow, times the gas's relative permeability k_rg(alpha_l)
    // of a face as pendularResidual takes it (liquidFlow::krgFace: upwind
    // of the pressure difference or arithmetic on internal and processor
    // faces, the cell's on the other patches)
    if (const liquidFlow* liquid = medium_.liquidFlowPtr())
    {
        const labelUList& own = mesh_.owner();
        const labelUList& nei = mesh_.neighbour();
        const surfaceScalarField& w = mesh_.weights();
        forAll(own, facei)
        {
            q_[facei] *=
                liquid->krgFace
                (
                    alphaL_[own[facei]], alphaL_[nei[facei]],
                    snGradP[facei], w[facei]
                );
        }
        forAll(q_.boundaryField(), patchi)
        {
            const fvPatch& patch = mesh_.boundary()[patchi];
            const scalarField inside
            (
                alphaL_.boundaryField()[patchi].patchInternalField()
            );
            const scalarField across
            (
                patch.coupled()
              ? alphaL_.boundaryField()[patchi].patchNeighbourField()
              : alphaL_.boundaryField()[patchi].patchInternalField()
            );
            scalarField& qp = q_.boundaryFieldRef()[patchi];
            forAll(qp, i)
            {
                qp[i] *=
                    patch.coupled()
                  ? liquid->krgFace
                    (
                        inside[i], across[i],
                        snGradP.boundaryField()[patchi][i],
                        w.boundaryField()[patchi][i]
                    )
                  : liquid->krg(inside[i]);
            }
        }
    }

    // The effective vapour diffusivity of the faces: faceValue (the
    // distance-weighted harmonic mean) between the cells on internal and
    // coupled faces (as pendularResidual), the cell's on the other patches
    {
        const labelUList& own = mesh_.owner();
        const labelUList& nei = mesh_.neighbour();
        const surfaceScalarField& w = mesh_.weights();
        forAll(own, facei)
        {
            Dvf_[facei] =
                faceValue(Dv_[own[facei]], Dv_[nei[facei]], w[facei]);
        }
        forAll(Dvf_.boundaryField(), patchi)
        {
            const fvPatchScalarField& Dvp = Dv_.boundaryField()[patchi];
            const scalarField inside(Dvp.patchInternalField());
            scalarField& Dvfp = Dvf_.boundaryFieldRef()[patchi];
            if (Dvp.coupled())
            {
                const scalarField across(Dvp.patchNeighbourField());
                const scalarField& wp = w.boundaryField()[patchi];
                forAll(Dvfp, i)
                {
                    Dvfp[i] = faceValue(inside[i], across[i], wp[i]);
                }
            }
            else
            {
                Dvfp = inside;
            }
        }
    }

    const surfaceScalarField j
    (
        -Dvf_*fvc::interpolate(rhoG_)*fvc::snGrad(omegaW_)*magSf
    );

    Fw_ = upwindFaces(rhoW_, q_)*q_ + j;
    Fa_ = upwindFaces(rhoA_, q_)*q_ - j;

    FE_ =
        -fvc::interpolate(kappa_)*fvc::snGrad(T_)*magSf
      + Fa_*upwindFaces(hA_, Fa_)
      + Fw_*upwindFaces(hW_, Fw_);

    // Conduction through a surfaceHeatLoss patch: from the surface
    // temperature update() set (the condition's snGrad is its
    // linearisation's)
    forAll(T_.boundaryField(), patchi)
    {
        if (isA<surfaceHeatLossFvPatchScalarField>(T_.boundaryField()[patchi]))
        {
            FE_.boundaryFieldRef()[patchi] +=
                kappa_.boundaryField()[patchi]
               *(T_.boundaryField()[patchi].snGrad() - conductionGradient(patchi))
               *magSf.boundaryField()[patchi];
        }
    }

    forAll(kind_, patchi)
    {
        if (kind_[patchi] == patchKind::semiPermeable)
        {
            // No air crosses: rho_a q = j (upwind air density), so the
            // vapour flux is the diffusive one carried by its own Stefan
            // flow, F_w = j rho_g/rho_a
            const fvsPatchScalarField& jp = j.boundaryField()[patchi];
            const scalarField rhoAIn
            (
                rhoA_.boundaryField()[patchi].patchInternalField()
            );
            const scalarField rhoGIn
            (
                rhoG_.boundaryField()[patchi].patchInternalField()
            );
            const scalarField& rhoAOut = rhoA_.boundaryField()[patchi];
            const scalarField& rhoGOut = rhoG_.boundaryField()[patchi];
            const scalarField hWIn
            (
                hW_.boundaryField()[patchi].patchInternalField()
            );
            const scalarField& hWOut = hW_.boundaryField()[patchi];
            scalarField& qp = q_.boundaryFieldRef()[patchi];
            scalarField& Fwp = Fw_.boundaryFieldRef()[patchi];
            scalarField& Fap = Fa_.boundaryFieldRef()[patchi];
            scalarField& FEp = FE_.boundaryFieldRef()[patchi];
            FEp =
               -kappa_.boundaryField()[patchi]
               *conductionGradient(patchi)
               *magSf.boundaryField()[patchi];
            forAll(jp, facei)
            {
                const bool out = jp[facei] > 0;
                const scalar rhoAf = out ? rhoAIn[facei] : rhoAOut[facei];
                const scalar rhoGf = out ? rhoGIn[facei] : rhoGOut[facei];
                const scalar stefan = stefanFactor(rhoAf, rhoGf);
                qp[facei] = jp[facei]*stefan/max(rhoGf, SMALL);
                Fwp[facei] = jp[facei]*stefan;
                Fap[facei] = 0;
                FEp[facei] += Fwp[facei]*(out ? hWIn[facei] : hWOut[facei]);
            }
        }
        else if
        (
            kind_[patchi] != patchKind::open
         && !mesh_.boundary()[patchi].coupled()
        )
        {
            q_.boundaryFieldRef()[patchi] = 0;
            Fw_.boundaryFieldRef()[patchi] = 0;
            Fa_.boundaryFieldRef()[patchi] = 0;
            // Conduction only
            FE_.boundaryFieldRef()[patchi] =
               -kappa_.boundaryField()[patchi]
               *conductionGradient(patchi)
               *magSf.boundaryField()[patchi];
        }
    }
}


void Foam::pendularState::checkOpenPatches() const
{
    // 0 <= p_w <= p_g and a relative humidity p_w/p_wsat(T) <= 1 (checked
    // at the start and at every step, as T and p_w may be histories)
    forAll(kind_, patchi)
    {
        if
        (
            kind_[patchi] != patchKind::open
         && kind_[patchi] != patchKind::semiPermeable
        )
        {
            continue;
        }
        const fvPatchScalarField& pwp = pw_.boundaryField()[patchi];
        const fvPatchScalarField& pp = p_.boundaryField()[patchi];
        const fvPatchScalarField& Tp = T_.boundaryField()[patchi];
        forAll(pwp, facei)
        {
            const scalar pSat = medium_.saturationPressure(Tp[facei]);
            const scalar RHb = pwp[facei]/max(pSat, VSMALL);
            if
            (
                !(pp[facei] > 0) || pwp[facei] < 0 || pwp[facei] > pp[facei]
             || RHb > 1 + 1e-9
            )
            {
                FatalErrorInFunction
                    << "Patch " << mesh_.boundary()[patchi].name()
                    << " at t = " << mesh_.time().timeName() << " s: p_w = "
                    << pwp[facei] << " Pa (" << pw_.objectPath() << ") with"
                    << " p_g = " << pp[facei] << " Pa (" << p_.objectPath()
                    << ") and T = " << Tp[facei] << " K: relative humidity "
                    << RHb << nl
                    << "    Valid: p_g > 0, 0 <= p_w <= p_g and p_w <="
                    << " p_wsat(T) = " << pSat
                    << " Pa (relative humidity in [0, 1])"
                    << exit(FatalError);
            }
        }
    }
}


namespace
{
    // A patch value as a Function1 of time when the condition holds one
    // (uniformFixedValue with a Function1: a constant, a table, ...),
    // rebuilt from the condition's own entries as it writes them for a
    // restart (v1912's uniformFixedValue keeps its Function1 private); null
    // otherwise (a condition of another type, or a PatchFunction1 that is
    // no Function1: nonuniform values, mappedFile: checked at every step)
    Foam::autoPtr<Foam::Function1<Foam::scalar>> uniformHistory
    (
        const Foam::fvPatchScalarField& pf
    )
    {
        if (pf.type() != "uniformFixedValue")
        {
            return nullptr;
        }
        Foam::OStringStream os;
        pf.write(os);
        Foam::IStringStream is(os.str());
        const Foam::dictionary dict(is);
        const Foam::entry* e = dict.findEntry("uniformValue");
        if (!e || e->isDict())
        {
            return nullptr;
        }
        Foam::ITstream& value = e->stream();
        const Foam::token first(value.size() ? value[0] : Foam::token());
        if
        (
            !first.isNumber()
         && !(
                first.isWord()
             && Foam::Function1<Foam::scalar>::dictionaryConstructorTablePtr_
             && Foam::Function1<Foam::scalar>::dictionaryConstructorTablePtr_
                    ->found(first.wordToken())
            )
        )
        {
            return nullptr;
        }
        return Foam::Function1<Foam::scalar>::New("uniformValue", dict);
    }
}


void Foam::pendularState::checkOpenPatchHistories() const
{
    // Where the patch's T and p_w are known over the run (T: fireTemperature,
    // uniformFixedValue or fixedValue; p_w: uniformFixedValue or
    // fixedValue), p_w <= p_wsat(T_b) over the run, checked before any step
    // (it stopped the run at the step reaching it). A table is linear
    // between its rows, a fire history too: checked at the rows of both
    // (other Function1 types: at 1001 times, checkedRead::
    // function1CheckTimes), within the run. Other conditions of T
    // (surfaceHeatLoss, ...) give T_b only as the run makes it:
    // checkOpenPatches at every step
    const Time& runTime = mesh_.time();
    const scalar t0 = runTime.startTime().value();
    const scalar t1 = max(t0, runTime.endTime().value());
    forAll(kind_, patchi)
    {
        const fvPatchScalarField& pwp = pw_.boundaryField()[patchi];
        const fvPatchScalarField& Tp = T_.boundaryField()[patchi];
        if
        (
            (
                kind_[patchi] != patchKind::open
             && kind_[patchi] != patchKind::semiPermeable
            )
         || pwp.empty()
        )
        {
            continue;
        }
        const auto* fire = isA<fireTemperatureFvPatchScalarField>(Tp);
        const autoPtr<Function1<scalar>> pwHistory(uniformHistory(pwp));
        const autoPtr<Function1<scalar>> THistory(uniformHistory(Tp));
        if
        (
            !(pwHistory || pwp.type() == "fixedValue")
         || !(fire || THistory || Tp.type() == "fixedValue")
         || !(pwHistory || fire || THistory)    // constant: the start's check
        )
        {
            continue;
        }
        DynamicList<scalar> times({t0, t1});
        if (fire)
        {
            times.append(fire->times());
        }
        for (const auto* f : {pwHistory.get(), THistory.get()})
        {
            if (f)
            {
                times.append(checkedRead::function1CheckTimes(*f, runTime));
            }
        }
        Foam::sort(times);
        for (const scalar t : times)
        {
            if (t < t0 || t > t1)
            {
                continue;
            }
            forAll(pwp, facei)
            {
                const scalar Tb =
                    fire ? fire->temperature(t, false)
                  : THistory ? THistory->value(t) : Tp[facei];
                const scalar pSat = medium_.saturationPressure(Tb);
                const scalar pw =
                    pwHistory ? pwHistory->value(t) : pwp[facei];
                if (pw > (1 + 1e-9)*pSat)
                {
                    dictionary pwDict;
                    pwDict.name() = pw_.objectPath();
                    FatalIOErrorInFunction(pwDict)
                        << "Patch '" << pwp.patch().name() << "' of "
                        << pw_.name() << " (" << pwp.type() << "): p_w = "
                        << pw << " Pa at time " << t << " s is above the"
                        << " saturation pressure p_wsat(T) = " << pSat
                        << " Pa at the patch's temperature T = " << Tb
                        << " K then (" << Tp.type() << " in "
                        << T_.objectPath() << "): relative humidity "
                        << pw/pSat << nl
                        << "    Valid: p_w <= p_wsat(T) over the run"
                        << " (relative humidity in [0, 1]); checked before"
                        << " any step at the rows of the histories of p_w"
                        << " and T" << exit(FatalIOError);
                }
            }
        }
    }
}


void Foam::pendularState::warnAboveTestedRange() const
{
    forAll(T_.boundaryField(), patchi)
    {
        const fvPatchScalarField& Tp = T_.boundaryField()[patchi];
        // (every rank holds every non-processor patch, with or without
        // faces: the reduction is reached by all)
        if (Tp.patch().coupled())
        {
            continue;
        }
        scalar Tmax = gMax(Tp);
        const auto* fire = isA<fireTemperatureFvPatchScalarField>(Tp);
        if (fire)
        {
            for (const scalar T : fire->temperatures())
            {
                Tmax = max(Tmax, T);
            }
        }
        if (Tmax > TmaxTested)
        {
            WarningInFunction
                << "Patch " << Tp.patch().name() << " of " << T_.name()
                << ": temperature up to " << Tmax << " K ("
                << Tmax - 273.15 << " C)"
                << (fire ? " in its fire history" : " at the start")
                << ", above " << TmaxTested << " K (2000 C), the hottest"
                << " fire pendularFoam's tests run" << nl
                << "    (tests/pendularCriticalPoint; hearthCase refuses"
                << " such a fire for pendularFoam): the results beyond are"
                << " untested" << endl;
        }
    }
}


void Foam::pendularState::startStep(const scalar dt)
{
    alphaOld_ = alphaL_.primitiveField();
    stepDeltaT_ = dt;
}


Foam::labelList Foam::pendularState::phases() const
{
    labelList ph(gasPresent_.size(), 0);
    forAll(ph, celli)
    {
        ph[celli] = liquidOnly(celli) ? 1 : 0;
    }
    return ph;
}


void Foam::pendularState::setPhases
(
    const labelList& phases,
    const scalarField& pl,
    const scalarField& X
)
{
    forAll(phases, celli)
    {
        gasPresent_[celli] = phases[celli] == 1 ? 0 : 1;
        if (phases[celli] == 1)
        {
            pl_[celli] = pl[celli];
            Xair_[celli] = X[celli];
        }
    }
    gasPresent_.correctBoundaryConditions();
}


void Foam::pendularState::storeOld()
{
    W0_ = W_.primitiveField();
    A0_ = A_.primitiveField();
    E0_ = E_.primitiveField();
}


Foam::scalar Foam::pendularState::relaxedVapourDensity
(
    const label celli,
    const scalar Wc,
    const scalar Tc
) const
{
    scalar alpha, rhoW;
    medium_.water().liquidAndVapour
    (
        Wc, medium_.saturation(Tc), medium_.porosity()[celli], p_[celli],
        alphaOld_[celli], stepDeltaT_, alphaOld_[celli], alpha, rhoW
    );
    return rhoW;
}


Foam::tmp<Foam::scalarField> Foam::pendularState::waterResidual
(
    const scalar dt
) const
{
    return
        (W_.primitiveField() - W0_)/dt
      + fvc::surfaceIntegrate(Fw_)().primitiveField();
}


Foam::tmp<Foam::scalarField> Foam::pendularState::gasResidual
(
    const scalar dt
) const
{
    return
        (W_.primitiveField() + A_.primitiveField() - W0_ - A0_)/dt
      + fvc::surfaceIntegrate(Fw_ + Fa_)().primitiveField();
}


Foam::tmp<Foam::scalarField> Foam::pendularState::energyResidual
(
    const scalar dt
) const
{
    return
        (E_.primitiveField() - E0_)/dt
      + fvc::surfaceIntegrate(FE_)().primitiveField();
}


Foam::string Foam::pendularState::liquidNearCritical() const
{
    const scalarField& porosity = medium_.porosity().primitiveField();
    forAll(W_, celli)
    {
        if
        (
            medium_.liquidNearCritical
            (
                W_[celli], alphaL_[celli], saturationStates_[celli],
                porosity[celli]
            )
        )
        {
            return
                "cell " + Foam::name(celli) + " holds liquid water"
                " near the critical point: T = "
              + Foam::name(T_[celli]) + " K, alpha_l = "
              + Foam::name(alphaL_[celli]) + ", W = "
              + Foam::name(W_[celli]) + " kg/m3 (no liquid within "
              + Foam::name(pendularMedium::criticalMargin)
              + " K of " + Foam::name(medium_.dryOutTemperature())
              + " K, nor water denser than the saturated vapour"
                " above it)";
        }
    }
    return string();
}


// ************************************************************************* //
