/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "liquidFlow.H"
#include "checkedRead.H"
#include "emptyPolyPatch.H"
#include "processorPolyPatch.H"
#include "uniformDimensionedFields.H"
#include "volFields.H"
#include "surfaceFields.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::liquidFlow::patchType>
Foam::liquidFlow::patchTypeNames
({
    { patchType::fixedSaturation, "fixedSaturation" },
    { patchType::fixedFlux, "fixedFlux" },
    { patchType::impermeable, "impermeable" },
});


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

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
        if (isA<emptyPolyPatch>(pp) || isA<processorPolyPatch>(pp))
        {
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
    readBoundary(dict, everyPatch, maxSaturation);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::liquidFlow::readGravity(const fvMesh& mesh)
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
    const liquidDarcyFlux::liquidState& n
) const
{
    if (facei < mesh_.nInternalFaces())
    {
        const vectorField& C = mesh_.C();
        return
            darcy_.massFlux
            (
                o, n,
                C[mesh_.faceNeighbour()[facei]] - C[mesh_.faceOwner()[facei]],
                mesh_.magSf()[facei],
                mesh_.nonOrthDeltaCoeffs()[facei],
                mesh_.weights()[facei]
            );
    }
    // A face of a processor patch: the internal face seen from this side
    const label bFacei = facei - mesh_.nInternalFaces();
    const label patchi = mesh_.boundaryMesh().patchID()[bFacei];
    const label i = facei - mesh_.boundaryMesh()[patchi].start();
    return
        darcy_.massFlux
        (
            o, n, delta_[bFacei],
            mesh_.magSf().boundaryField()[patchi][i],
            mesh_.nonOrthDeltaCoeffs().boundaryField()[patchi][i],
            mesh_.weights().boundaryField()[patchi][i]
        );
}


Foam::scalar Foam::liquidFlow::boundaryFlux
(
    const label facei,
    const label patchi,
    const label i,
    const liquidDarcyFlux::liquidState& c,
    const liquidDarcyFlux::liquidState& f
) const
{
    const scalar magSf = mesh_.magSf().boundaryField()[patchi][i];
    switch (type_[patchi])
    {
        case patchType::fixedSaturation:
            return
                darcy_.massFlux
                (
                    c, f, delta_[facei - mesh_.nInternalFaces()], magSf,
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
