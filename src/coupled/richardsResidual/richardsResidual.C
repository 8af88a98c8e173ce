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
    liquid_(mesh, dict, g, true),
    dt_(1),
    S0_(mesh.nCells(), Zero)
{
    checkedRead::checkKeywords(dict, keywords(dict));
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::wordList Foam::richardsResidual::keywords(const dictionary& dict) const
{
    wordList keys({"porosity", "gasPressure", "temperature"});
    keys.append(liquid_.keywords(dict));
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
        phi_*liquid_.darcy().rhoLiquid()*sum(S*fvMesh_.V().field()),
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
    return phi_*liquid_.darcy().rhoLiquid()*fvMesh_.V()[celli]/dt_;
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
    F[0] = liquid_.faceFlux(facei, state(xOwn[0]), state(xNei[0]));
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
    F[0] =
        liquid_.boundaryFlux
        (
            facei, patchi, i, state(xOwn[0]), pg_, T_
        );
}


// ************************************************************************* //
