/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "liquidFlow.H"
#include "checkedRead.H"
#include "emptyPolyPatch.H"
#include "uniformDimensionedFields.H"
#include "volFields.H"
#include "surfaceFields.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::liquidFlow::patchType>
Foam::liquidFlow::patchTypeNames
({
    { patchType::fixedSaturation, "fixedSaturation" },
    { patchType::fixedFlux, "fixedFlux" },
    { patchType::fixedPressure, "fixedPressure" },
    { patchType::impermeable, "impermeable" },
});


// p_l's range (liquidFlow.H): from the Kelvin limit of an oven-dry soil
// to the upper end of IAPWS-IF97's region 1 (the compressed liquid)
const Foam::scalar Foam::liquidFlow::plMin_ = -1e9;
const Foam::scalar Foam::liquidFlow::plMax_ = 1e8;


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::liquidFlow::checkedPl
(
    const label patchi,
    const scalar t
) const
{
    const scalar pl = pl_[patchi].value(t);
    // (isfinite first: an ordered comparison with a NaN would trap)
    if (!std::isfinite(pl) || pl < plMin_ || pl > plMax_)
    {
        const dictionary& dict = plDict_[patchi];
        FatalIOErrorInFunction(dict)
            << "Keyword 'pl' of the fixedPressure liquid boundary condition"
            << " of patch '" << mesh_.boundaryMesh()[patchi].name()
            << "' in " << dict.name() << ": p_l = " << pl << " Pa at time "
            << t << " s is outside its valid range [" << Foam::name(plMin_)
            << ", " << Foam::name(plMax_) << "] Pa (from the Kelvin limit of an oven-dry soil"
            << " to the compressed liquid's range)" << exit(FatalIOError);
    }
    return pl;
}



void Foam::liquidFlow::checkNotPonded
(
    const label patchi,
    const label i,
    const scalar pl,
    const scalar pg,
    const scalar t
) const
{
    if (pl > pg && !ponding_)
    {
        // An over-pressured (ponded) face: its liquid would flood the
        // cell beyond the saturation form's range (the Newton iterates
        // then leave it, e.g. S <= S_wr, far from the cause)
        const dictionary& dict = plDict_[patchi];
        const label facei = mesh_.boundaryMesh()[patchi].start() + i;
        FatalIOErrorInFunction(dict)
            << "Keyword '" << (pl_.set(patchi) ? "pl" : "waterTable")
            << "' of the fixedPressure liquid boundary condition of patch '"
            << mesh_.boundaryMesh()[patchi].name() << "' in " << dict.name()
            << ": p_l = " << pl << " Pa at time " << t
            << " s is above the gas pressure p_g = " << pg << " Pa of its"
            << " face " << i << " (cell " << mesh_.faceOwner()[facei]
            << "): valid range [" << Foam::name(plMin_) << ", " << pg << "] Pa"
            << " (p_l <= p_g of the face's cell: an over-pressured, ponded"
            << " face is beyond the saturation form; pendularFoam's"
            << " saturatedZone allows it)" << exit(FatalIOError);
    }
}


void Foam::liquidFlow::readFixedPressure
(
    const dictionary& pDict,
    const label patchi
)
{
    const polyPatch& pp = mesh_.boundaryMesh()[patchi];
    const string where
    (
        "fixedPressure liquid boundary condition of patch " + pp.name()
      + ": 'pl <Function1 of time>' or 'waterTable { level; pressure; }'"
    );
    const bool hasPl = pDict.found("pl", keyType::LITERAL);
    const bool hasTable = pDict.found("waterTable", keyType::LITERAL);
    if (hasPl == hasTable)
    {
        FatalIOErrorInFunction(pDict)
            << "Patch '" << pp.name() << "' of type fixedPressure in "
            << pDict.name() << ": "
            << (hasPl ? "both 'pl' and 'waterTable' given" : "missing")
            << ": give one of 'pl <Function1 of time> [Pa]' or"
            << " 'waterTable { level <z> [m]; pressure <p_0> [Pa]; }'"
            << exit(FatalIOError);
    }
    if (hasPl)
    {
        wordList keys({"type"});
        keys.append(checkedRead::function1Keywords(pDict, "pl"));
        checkedRead::checkKeywords(pDict, keys, where);
        checkedRead::checkFunction1Coeffs(pDict, "pl", where);
        pl_.set(patchi, Function1<scalar>::New("pl", pDict));
        plDict_.set(patchi, new dictionary(pDict));
        // Its values over the whole run, before any step (a table at every
        // row), and at every evaluation (liquidPressure)
        for
        (
            const scalar t
          : checkedRead::function1CheckTimes(pl_[patchi], mesh_.time())
        )
        {
            checkedPl(patchi, t);
        }
        return;
    }
    checkedRead::checkKeywords(pDict, {"type", "waterTable"}, where);
    if (!pDict.isDict("waterTable"))
    {
        FatalIOErrorInFunction(pDict)
            << "Keyword 'waterTable' of patch '" << pp.name() << "' in "
            << pDict.name() << " must be a sub-dictionary"
            << " { level <z> [m]; pressure <p_0> [Pa]; }"
            << exit(FatalIOError);
    }
    const dictionary& tDict = pDict.subDict("waterTable");
    checkedRead::checkKeywords
    (
        tDict, {"level", "pressure"}, where + ", its water table"
    );
    plDict_.set(patchi, new dictionary(tDict));
    const scalar magG = mag(darcy_.g());
    if (magG <= 0)
    {
        FatalIOErrorInFunction(tDict)
            << "A water table ('waterTable' of patch '" << pp.name()
            << "' in " << tDict.name() << ") needs gravity: g = "
            << darcy_.g() << " (constant/g)" << exit(FatalIOError);
    }
    // A ponded face (the water table above it, p_l,f > p_0) is beyond the
    // saturation form: refused. Every rank reaches this (the same
    // non-processor patches on every rank)
    const vectorField& Cf = mesh_.Cf().boundaryField()[patchi];
    const scalar zMin =
        returnReduce
        (
            Cf.size() ? min(-(darcy_.g() & Cf)/magG) : GREAT,
            minOp<scalar>()
        )
      + scalar(0);      // (-0 printed as 0)
    const string levelRange
    (
        "valid range (-inf, " + Foam::name(zMin) + "] (at or below the"
        " patch's lowest face, height " + Foam::name(zMin) + " m along -g:"
        " a ponded face is beyond the saturation form)"
    );
    if (!tDict.found("level", keyType::LITERAL))
    {
        FatalIOErrorInFunction(tDict)
            << "Missing keyword 'level' (the water table's height [m] along"
            << " -g) of the water table of patch '" << pp.name() << "' in "
            << tDict.name() << ": " << levelRange.c_str()
            << exit(FatalIOError);
    }
    // (a finite number first: nan, inf, a word, wrong dimensions)
    level_[patchi] =
        checkedRead::get
        (
            tDict, "level", dimLength, validRange{-GREAT, GREAT, true, true}
        ).value();
    if (level_[patchi] > zMin)
    {
        FatalIOErrorInFunction(tDict)
            << "Keyword 'level' = " << level_[patchi] << " m of the water"
            << " table of patch '" << pp.name() << "' in " << tDict.name()
            << " is above its lowest face: " << levelRange.c_str()
            << exit(FatalIOError);
    }
    // p_0: a gas pressure, within p_l's range (plMax_)
    pTable_[patchi] =
        checkedRead::getOrDefault
        (
            tDict, "pressure", dimPressure, 101325,
            validRange{0, plMax_, true, false}
        ).value();
    // p_l,f on every face of the patch within p_l's range (the water
    // table's p_l,f does not change in time: checked once)
    forAll(Cf, i)
    {
        const scalar pl = liquidPressure(patchi, i);
        if (pl < plMin_)
        {
            FatalIOErrorInFunction(tDict)
                << "Keyword 'level' = " << level_[patchi] << " m of the"
                << " water table of patch '" << pp.name() << "' in "
                << tDict.name() << ": the liquid pressure of face " << i
                << " (height " << -(darcy_.g() & Cf[i])/magG << " m), "
                << pl << " Pa, is below p_l's valid range ["
                << Foam::name(plMin_) << ", " << Foam::name(plMax_) << "] Pa: the water table is too deep"
                << exit(FatalIOError);
        }
    }
}


void Foam::liquidFlow::readBoundary
(
    const dictionary& dict,
    const bool everyPatch,
    const scalar maxSaturation
)
{
    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
    if (!dict.isDict("boundary"))
    {
        if (!everyPatch && !dict.found("boundary"))
        {
            return;
        }
        FatalIOErrorInFunction(dict)
            << "Missing sub-dictionary 'boundary' in " << dict.name()
            << ": a condition (" << flatOutput(patchTypeNames.sortedToc())
            << ") for every patch" << exit(FatalIOError);
    }
    const dictionary& bDict = dict.subDict("boundary");
    wordList names;
    forAll(pbm, patchi)
    {
        const polyPatch& pp = pbm[patchi];
        // (the liquid crosses processor and cyclic patches as internal
        // faces: no condition; AMI patches are refused by the Newton
        // engine, pendularResidual::checkCoupledPatches)
        if (isA<emptyPolyPatch>(pp) || pp.coupled())
        {
            continue;
        }
        names.append(pp.name());
        if (!bDict.isDict(pp.name()))
        {
            if (!everyPatch && !bDict.found(pp.name()))
            {
                continue;
            }
            FatalIOErrorInFunction(bDict)
                << "No condition for patch '" << pp.name() << "' in "
                << bDict.name() << ": valid types "
                << flatOutput(patchTypeNames.sortedToc())
                << exit(FatalIOError);
        }
        const dictionary& pDict = bDict.subDict(pp.name());
        if (!pDict.found("type"))
        {
            FatalIOErrorInFunction(pDict)
                << "Missing keyword 'type' for patch '" << pp.name()
                << "': valid types " << flatOutput(patchTypeNames.sortedToc())
                << exit(FatalIOError);
        }
        type_[patchi] =
            checkedRead::getChoice
            (
                pDict, "type", patchTypeNames, patchType::impermeable
            );
        const string where("liquid boundary condition of patch " + pp.name());
        switch (type_[patchi])
        {
            case patchType::fixedSaturation:
                checkedRead::checkKeywords(pDict, {"type", "S"}, where);
                value_[patchi] =
                    checkedRead::get
                    (
                        pDict, "S", dimless,
                        validRange{minSaturation(), maxSaturation, true, false}
                    ).value();
                break;
            case patchType::fixedFlux:
                checkedRead::checkKeywords(pDict, {"type", "flux"}, where);
                value_[patchi] =
                    checkedRead::get
                    (
                        pDict, "flux", dimMass/dimArea/dimTime,
                        validRange{-GREAT, GREAT, false, false}
                    ).value();
                break;
            case patchType::fixedPressure:
                readFixedPressure(pDict, patchi);
                break;
            case patchType::impermeable:
                checkedRead::checkKeywords(pDict, {"type"}, where);
                break;
        }
    }
    checkedRead::checkKeywords(bDict, names, "patches of the mesh");
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::liquidFlow::liquidFlow
(
    const fvMesh& mesh,
    const dictionary& dict,
    const vector& g,
    const bool everyPatch,
    const scalar maxSaturation
)
:
    mesh_(mesh),
    K_
    (
        checkedRead::get
        (
            dict, "permeability", dimArea, checkedRead::positive()
        ).value()
    ),
    pc_(capillaryPressureModel::New(dict)),
    kr_(relativePermeabilityModel::New(dict)),
    darcy_(dict, g, pc_(), kr_()),
    type_(mesh.boundaryMesh().size(), patchType::impermeable),
    value_(mesh.boundaryMesh().size(), Zero),
    pl_(mesh.boundaryMesh().size()),
    level_(mesh.boundaryMesh().size(), Zero),
    pTable_(mesh.boundaryMesh().size(), Zero),
    plDict_(mesh.boundaryMesh().size()),
    ponding_(false),
    delta_(mesh.nBoundaryFaces(), Zero)
{
    forAll(mesh.boundary(), patchi)
    {
        const fvPatch& p = mesh.boundary()[patchi];
        if (!isA<emptyPolyPatch>(p.patch()))
        {
            SubList<vector>(delta_, p.size(), p.start() - mesh.nInternalFaces())
                = p.delta();
        }
    }
    // The mobile range (S_wr, maxSaturation] must not be empty: S_wr at or
    // above the pendular range's alphaLMax leaves no liquid that can flow
    // inside it (hostile testing 2026-12-05b, finding 2)
    const scalar Swr = minSaturation();
    if (Swr >= maxSaturation)
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 'Swr' = " << Swr << " in " << dict.name()
            << " leaves no mobile liquid: valid range "
            << checkedRead::closedOpen(0, maxSaturation).str().c_str()
            << ", below the largest saturation of the unknown's range, "
            << maxSaturation << " (pendularFoam: alphaLMax of the meniscus"
            << " model, the end of the pendular range)" << exit(FatalIOError);
    }
    readBoundary(dict, everyPatch, maxSaturation);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::liquidFlow::readGravity(const fvMesh& mesh)
{
    IOobject gIO
    (
        "g",
        mesh.time().constant(),
        mesh,
        IOobject::MUST_READ,
        IOobject::NO_WRITE
    );
    // (OpenFOAM's own message would name the file, not why it is needed)
    if (!gIO.typeHeaderOk<uniformDimensionedVectorField>(true))
    {
        FatalIOError
        (
            FUNCTION_NAME, __FILE__, __LINE__, gIO.objectPath(), -1, -1
        )
            << "liquidFlow needs gravity from constant/g (the liquid's"
            << " Darcy flux is driven by p_l and rho_l g), and there is no"
            << " such file, or it is not a uniformDimensionedVectorField: add"
            << " constant/g, e.g. dimensions [0 1 -2 0 0 0 0]; value"
            << " (0 0 -9.81);" << exit(FatalIOError);
    }
    const uniformDimensionedVectorField g(gIO);
    if (g.dimensions() != dimAcceleration)
    {
        FatalIOError
        (
            FUNCTION_NAME, __FILE__, __LINE__, g.objectPath(), -1, -1
        )
            << "Gravity g has dimensions " << g.dimensions()
            << ", expected " << dimAcceleration << " [m/s^2]"
            << exit(FatalIOError);
    }
    return g.value();
}


Foam::wordList Foam::liquidFlow::keywords(const dictionary& dict) const
{
    wordList keys({"permeability", "boundary"});
    keys.append(liquidDarcyFlux::keywords());
    keys.append(effectiveSaturation::keywords());
    keys.append(capillaryPressureModel::keywords());
    keys.append
    (
        checkedRead::modelKeywords(dict, "capillaryPressureModel", pc_())
    );
    keys.append
    (
        checkedRead::modelKeywords(dict, "relativePermeabilityModel", kr_())
    );
    return keys;
}


Foam::scalar Foam::liquidFlow::faceFlux
(
    const label facei,
    const liquidDarcyFlux::liquidState& o,
    const liquidDarcyFlux::liquidState& n,
    const scalar snGradCorrection,
    const surfaceScalarField* deltaCoeffs
) const
{
    const surfaceScalarField& dc =
        deltaCoeffs ? *deltaCoeffs : mesh_.nonOrthDeltaCoeffs();
    if (facei < mesh_.nInternalFaces())
    {
        const vectorField& C = mesh_.C();
        return
            darcy_.massFlux
            (
                o, n,
                C[mesh_.faceNeighbour()[facei]] - C[mesh_.faceOwner()[facei]],
                mesh_.magSf()[facei],
                dc[facei],
                mesh_.weights()[facei],
                snGradCorrection
            );
    }
    // A face of a processor or cyclic patch: the internal face seen from
    // this side (delta_: the patch's delta, a cyclic's through its
    // transform)
    const label bFacei = facei - mesh_.nInternalFaces();
    const label patchi = mesh_.boundaryMesh().patchID()[bFacei];
    const label i = facei - mesh_.boundaryMesh()[patchi].start();
    return
        darcy_.massFlux
        (
            o, n, delta_[bFacei],
            mesh_.magSf().boundaryField()[patchi][i],
            dc.boundaryField()[patchi][i],
            mesh_.weights().boundaryField()[patchi][i],
            snGradCorrection
        );
}


Foam::scalar Foam::liquidFlow::liquidPressure
(
    const label patchi,
    const label i
) const
{
    if (pl_.set(patchi))
    {
        return checkedPl(patchi, mesh_.time().value());
    }
    // p_0 - rho_l |g| (z_f - z_wt), z = -g.x/|g|
    const vector& g = darcy_.g();
    const scalar rhol = darcy_.rhoLiquid();
    return
        pTable_[patchi]
      + rhol*(g & mesh_.Cf().boundaryField()[patchi][i])
      + rhol*mag(g)*level_[patchi];
}


void Foam::liquidFlow::checkStart(const volScalarField& p) const
{
    const scalar t0 = mesh_.time().value();
    forAll(type_, patchi)
    {
        if (type_[patchi] != patchType::fixedPressure)
        {
            continue;
        }
        // The face's p_g: the condition's value at the start (a fixed p,
        // or the cell's); a fixedValue p holds it over the run, so a pl
        // of time is checked against it at the times sampled at read
        const fvPatchScalarField& pp = p.boundaryField()[patchi];
        const bool pgFixed = pp.type() == "fixedValue";
        const scalarList times
        (
            pgFixed && pl_.set(patchi)
          ? checkedRead::function1CheckTimes(pl_[patchi], mesh_.time())
          : scalarList(1, t0)
        );
        const scalar t1 = max(t0, mesh_.time().endTime().value());
        forAll(pp, i)
        {
            for (const scalar t : times)
            {
                // a record longer than the run: its rows after the end
                // are never reached
                if (t < t0 || t > t1)
                {
                    continue;
                }
                const scalar pl =
                    pl_.set(patchi)
                  ? pl_[patchi].value(t)
                  : liquidPressure(patchi, i);
                checkNotPonded(patchi, i, pl, pp[i], t);
            }
        }
    }
}


Foam::liquidDarcyFlux::liquidState Foam::liquidFlow::boundaryState
(
    const label patchi,
    const label i,
    const scalar pg,
    const scalar T
) const
{
    if (type_[patchi] != patchType::fixedPressure)
    {
        return state(pg, value_[patchi], T);
    }
    const scalar pl = liquidPressure(patchi, i);
    checkNotPonded(patchi, i, pl, pg, mesh_.time().value());
    const scalar pc = pg - pl;
    return
        liquidDarcyFlux::liquidState
        {
            pg, pc, kr_->krl(pc_->saturation(pc, T)), K_
        };
}


Foam::scalar Foam::liquidFlow::boundaryFlux
(
    const label facei,
    const label patchi,
    const label i,
    const liquidDarcyFlux::liquidState& c,
    const scalar pg,
    const scalar T
) const
{
    const scalar magSf = mesh_.magSf().boundaryField()[patchi][i];
    switch (type_[patchi])
    {
        case patchType::fixedSaturation:
        case patchType::fixedPressure:
            return
                darcy_.massFlux
                (
                    c, boundaryState(patchi, i, pg, T),
                    delta_[facei - mesh_.nInternalFaces()], magSf,
                    mesh_.nonOrthDeltaCoeffs().boundaryField()[patchi][i],
                    0.5
                );
        case patchType::fixedFlux:
            return value_[patchi]*magSf;
        case patchType::impermeable:
            break;
    }
    return 0;
}


// ************************************************************************* //
