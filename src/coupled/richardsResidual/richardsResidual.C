/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "richardsResidual.H"
#include "checkedRead.H"
#include "emptyPolyPatch.H"
#include "processorPolyPatch.H"
#include "uniformDimensionedFields.H"
#include "volFields.H"
#include "surfaceFields.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::richardsResidual::patchType>
Foam::richardsResidual::patchTypeNames
({
    { patchType::fixedSaturation, "fixedSaturation" },
    { patchType::fixedFlux, "fixedFlux" },
    { patchType::impermeable, "impermeable" },
});


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::richardsResidual::readBoundary(const dictionary& dict)
{
    const polyBoundaryMesh& pbm = fvMesh_.boundaryMesh();
    if (!dict.isDict("boundary"))
    {
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
        if (isA<emptyPolyPatch>(pp) || isA<processorPolyPatch>(pp))
        {
            type_[patchi] = patchType::impermeable;
            continue;
        }
        if (pp.coupled())
        {
            FatalIOErrorInFunction(bDict)
                << "Patch '" << pp.name() << "' of type " << pp.type()
                << ": coupled patches other than processor are not"
                << " supported" << exit(FatalIOError);
        }
        names.append(pp.name());
        if (!bDict.isDict(pp.name()))
        {
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
                        validRange{minSaturation(), 1, true, false}
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
            case patchType::impermeable:
                checkedRead::checkKeywords(pDict, {"type"}, where);
                break;
        }
    }
    checkedRead::checkKeywords(bDict, names, "patches of the mesh");
}


Foam::liquidDarcyFlux::liquidState Foam::richardsResidual::state
(
    const scalar S
) const
{
    return darcy_.state(pg_, min(S, scalar(1)), T_, K_);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::richardsResidual::richardsResidual
(
    const fvMesh& mesh,
    const dictionary& dict,
    const vector& g,
    const differenceScheme scheme
)
:
    coupledResidual(mesh, 1, scalarField(1, 1.0), scheme),
    fvMesh_(mesh),
    K_
    (
        checkedRead::get
        (
            dict, "permeability", dimArea, checkedRead::positive()
        ).value()
    ),
    phi_
    (
        checkedRead::get
        (
            dict, "porosity", dimless, validRange{0, 1, true, false}
        ).value()
    ),
    pg_
    (
        checkedRead::get
        (
            dict, "gasPressure", dimPressure, checkedRead::positive()
        ).value()
    ),
    T_
    (
        checkedRead::get
        (
            dict, "temperature", dimTemperature, checkedRead::positive()
        ).value()
    ),
    pc_(capillaryPressureModel::New(dict)),
    kr_(relativePermeabilityModel::New(dict)),
    darcy_(dict, g, pc_(), kr_()),
    type_(mesh.boundaryMesh().size(), patchType::impermeable),
    value_(mesh.boundaryMesh().size(), Zero),
    dt_(1),
    S0_(mesh.nCells(), Zero),
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
    checkedRead::checkKeywords(dict, keywords(dict));
    readBoundary(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::richardsResidual::readGravity(const fvMesh& mesh)
{
    const uniformDimensionedVectorField g
    (
        IOobject
        (
            "g",
            mesh.time().constant(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    );
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


Foam::wordList Foam::richardsResidual::keywords(const dictionary& dict) const
{
    wordList keys
    ({
        "permeability", "porosity", "gasPressure", "temperature", "boundary"
    });
    keys.append(liquidDarcyFlux::keywords());
    keys.append(effectiveSaturation::keywords());
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


void Foam::richardsResidual::setOldTime
(
    const scalarField& S0,
    const scalar dt
)
{
    S0_ = S0;
    dt_ = dt;
}


Foam::scalar Foam::richardsResidual::water(const scalarField& S) const
{
    return returnReduce
    (
        phi_*darcy_.rhoLiquid()*sum(S*fvMesh_.V().field()),
        sumOp<scalar>()
    );
}


Foam::scalar Foam::richardsResidual::outflow(const scalarField& S) const
{
    const labelList& own = fvMesh_.faceOwner();
    scalar sum = 0;
    forAll(fvMesh_.boundaryMesh(), patchi)
    {
        const polyPatch& pp = fvMesh_.boundaryMesh()[patchi];
        if (pp.coupled() || isA<emptyPolyPatch>(pp))
        {
            continue;
        }
        forAll(pp, i)
        {
            const label facei = pp.start() + i;
            scalar F;
            boundaryFlux(facei, &S[own[facei]], &F);
            sum += F;
        }
    }
    return returnReduce(sum, sumOp<scalar>());
}


Foam::scalar Foam::richardsResidual::storage(const label celli) const
{
    return phi_*darcy_.rhoLiquid()*fvMesh_.V()[celli]/dt_;
}


void Foam::richardsResidual::cellTerm
(
    const label celli,
    const scalar* x,
    scalar* S
) const
{
    S[0] = storage(celli)*(x[0] - S0_[celli]);
}


void Foam::richardsResidual::faceFlux
(
    const label facei,
    const scalar* xOwn,
    const scalar* xNei,
    scalar* F
) const
{
    if (facei < fvMesh_.nInternalFaces())
    {
        const vectorField& C = fvMesh_.C();
        F[0] =
            darcy_.massFlux
            (
                state(xOwn[0]),
                state(xNei[0]),
                C[fvMesh_.faceNeighbour()[facei]] - C[fvMesh_.faceOwner()[facei]],
                fvMesh_.magSf()[facei],
                fvMesh_.nonOrthDeltaCoeffs()[facei],
                fvMesh_.weights()[facei]
            );
        return;
    }
    // A face of a processor patch: the internal face seen from this side
    label patchi, i;
    patchFace(facei, patchi, i);
    F[0] =
        darcy_.massFlux
        (
            state(xOwn[0]),
            state(xNei[0]),
            delta_[facei - fvMesh_.nInternalFaces()],
            fvMesh_.magSf().boundaryField()[patchi][i],
            fvMesh_.nonOrthDeltaCoeffs().boundaryField()[patchi][i],
            fvMesh_.weights().boundaryField()[patchi][i]
        );
}


void Foam::richardsResidual::boundaryFlux
(
    const label facei,
    const scalar* xOwn,
    scalar* F
) const
{
    label patchi, i;
    patchFace(facei, patchi, i);
    const scalar magSf = fvMesh_.magSf().boundaryField()[patchi][i];
    switch (type_[patchi])
    {
        case patchType::fixedSaturation:
            F[0] =
                darcy_.massFlux
                (
                    state(xOwn[0]),
                    state(value_[patchi]),
                    delta_[facei - fvMesh_.nInternalFaces()],
                    magSf,
                    fvMesh_.nonOrthDeltaCoeffs().boundaryField()[patchi][i],
                    0.5
                );
            break;
        case patchType::fixedFlux:
            F[0] = value_[patchi]*magSf;
            break;
        case patchType::impermeable:
            F[0] = 0;
            break;
    }
}


// ************************************************************************* //
