/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "pendularBdf2Levels.H"
#include "pendularResidual.H"
#include "checkedRead.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::volScalarField Foam::pendularBdf2Levels::field
(
    const fvMesh& mesh,
    const word& name,
    const dimensionSet& dims
)
{
    return volScalarField
    (
        IOobject
        (
            name,
            mesh.time().timeName(),
            mesh,
            IOobject::READ_IF_PRESENT,
            IOobject::NO_WRITE
        ),
        mesh,
        dimensionedScalar(dims, Zero)
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * //

Foam::pendularBdf2Levels::pendularBdf2Levels(const fvMesh& mesh)
:
    T1_(field(mesh, "T.bdf2Old", dimTemperature)),
    p1_(field(mesh, "p.bdf2Old", dimPressure)),
    W1_(field(mesh, "W.bdf2Old", dimDensity)),
    A1_(field(mesh, "A.bdf2Old", dimDensity)),
    E1_(field(mesh, "E.bdf2Old", dimEnergy/dimVolume)),
    T2_(field(mesh, "T.bdf2Older", dimTemperature)),
    absent_()
{
    for (volScalarField* f : {&T1_, &p1_, &W1_, &A1_, &E1_, &T2_})
    {
        if
        (
           !checkedRead::presentOnEveryRank
            (
                *f, "BDF2 level",
                "remove every processor*/" + mesh.time().timeName()
              + "/*.bdf2Old* to start by backward Euler"
            )
        )
        {
            absent_.append(f->name());
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::pendularBdf2Levels::found(const variableStepBdf2& bdf2) const
{
    return bdf2.savedLevels() > 0 && missing(bdf2).empty();
}


Foam::string Foam::pendularBdf2Levels::missing
(
    const variableStepBdf2& bdf2
) const
{
    const label n = bdf2.savedLevels();
    if (n == 0)
    {
        return
            bdf2.savedState()
          ? "uniform/variableStepBdf2 holds no level (a run at order 1)"
          : "no uniform/variableStepBdf2 (a time written by an older build)";
    }
    string what;
    for (const word& name : absent_)
    {
        if (name != T2_.name() || n > 1)
        {
            what += (what.empty() ? "no " : ", ") + name;
        }
    }
    return what;
}


void Foam::pendularBdf2Levels::restore
(
    variableStepBdf2& bdf2,
    const scalar pRef,
    scalarField& WOld,
    scalarField& AOld,
    scalarField& EOld
) const
{
    if (!found(bdf2))
    {
        FatalErrorInFunction
            << "BDF2's levels are not all there: " << missing(bdf2).c_str()
            << abort(FatalError);
    }
    bdf2.restore
    (
        pendularResidual::pack
        (
            T1_.primitiveField(), p1_.primitiveField(), W1_.primitiveField(),
            pRef
        ),
        bdf2.savedLevels() > 1 ? T2_.primitiveField() : scalarField(),
        scalarField
        ({
            gSum(W1_.mesh().V()*W1_.primitiveField()),
            gSum(W1_.mesh().V()*A1_.primitiveField()),
            gSum(W1_.mesh().V()*E1_.primitiveField())
        })
    );
    WOld = W1_.primitiveField();
    AOld = A1_.primitiveField();
    EOld = E1_.primitiveField();
}


void Foam::pendularBdf2Levels::store
(
    const variableStepBdf2& bdf2,
    const scalar pRef,
    const scalarField& AOld,
    const scalarField& EOld
)
{
    const label n = bdf2.levels();
    for (volScalarField* f : {&T1_, &p1_, &W1_, &A1_, &E1_, &T2_})
    {
        f->writeOpt() =
            n > 1 || (n > 0 && f != &T2_)
          ? IOobject::AUTO_WRITE : IOobject::NO_WRITE;
    }
    if (n == 0)
    {
        return;
    }
    // x^{n-1}: T, p_g - pRef, W per cell (pendularResidual::pack)
    const scalarField& x1 = bdf2.xOld();
    forAll(T1_, celli)
    {
        T1_[celli] = x1[3*celli];
        p1_[celli] = x1[3*celli + 1] + pRef;
        W1_[celli] = x1[3*celli + 2];
    }
    A1_.primitiveFieldRef() = AOld;
    E1_.primitiveFieldRef() = EOld;
    if (n > 1)
    {
        T2_.primitiveFieldRef() = bdf2.xOlder();
    }
    for (volScalarField* f : {&T1_, &p1_, &W1_, &A1_, &E1_, &T2_})
    {
        f->correctBoundaryConditions();
    }
}


// ************************************************************************* //
