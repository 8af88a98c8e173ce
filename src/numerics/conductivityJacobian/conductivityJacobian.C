/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "conductivityJacobian.H"
#include "lduMatrix.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::conductivityJacobian::checkInterpolation
(
    const word& kappaName
) const
{
    const word key("interpolate(" + kappaName + ")");
    ITstream& is = mesh_.interpolationScheme(key);
    const word scheme(is);

    if (scheme != "linear")
    {
        FatalIOErrorInFunction(mesh_.schemesDict())
            << "The conductivity Jacobian (system/fvSolution nonlinear"
            << " conductivityJacobian true) is derived for the linear"
            << " interpolation of the conductivity: interpolationSchemes "
            << key << " is '" << scheme << "' in " << mesh_.schemesDict().name()
            << nl << "    Valid choice: linear (or conductivityJacobian false)"
            << exit(FatalIOError);
    }
}


void Foam::conductivityJacobian::selectSolver(const word& fieldName)
{
    const dictionary& given = mesh_.solverDict(fieldName);
    solverDict_ = given;

    const word solverName(given.get<word>("solver"));

    if (!lduMatrix::solver::asymMatrixConstructorTablePtr_->found(solverName))
    {
        // A symmetric-only solver: PBiCGStab with DILU at the same
        // tolerances
        solverDict_.set("solver", word("PBiCGStab"));
        solverDict_.set("preconditioner", word("DILU"));
        solverDict_.remove("smoother");

        Info<< "conductivityJacobian: the matrix of " << fieldName
            << " is not symmetric; its solver " << solverName
            << " (" << given.name() << ") is replaced by PBiCGStab with"
            << " DILU at the same tolerances" << nl << endl;
        return;
    }

    // An asymmetric solver: its preconditioner or smoother must be one too
    if (given.found("preconditioner", keyType::LITERAL))
    {
        checkAsymmetric
        (
            given, fieldName, "preconditioner",
            lduMatrix::preconditioner::getName(given),
            lduMatrix::preconditioner::asymMatrixConstructorTablePtr_
                ->sortedToc()
        );
    }
    if (given.found("smoother", keyType::LITERAL))
    {
        checkAsymmetric
        (
            given, fieldName, "smoother",
            lduMatrix::smoother::getName(given),
            lduMatrix::smoother::asymMatrixConstructorTablePtr_->sortedToc()
        );
    }
}


void Foam::conductivityJacobian::checkAsymmetric
(
    const dictionary& given,
    const word& fieldName,
    const word& role,
    const word& name,
    const wordList& valid
)
{
    if (valid.found(name))
    {
        return;
    }
    FatalIOErrorInFunction(given)
        << "The conductivity Jacobian makes the matrix of " << fieldName
        << " asymmetric: " << role << " '" << name << "' of solver "
        << given.get<word>("solver") << " in " << given.name()
        << " is for symmetric matrices only" << nl
        << "    Valid choices:";
    for (const word& v : valid)
    {
        FatalIOError << ' ' << v;
    }
    FatalIOError
        << " (or conductivityJacobian false in the nonlinear controls)"
        << exit(FatalIOError);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::conductivityJacobian::conductivityJacobian
(
    const volScalarField& T,
    const word& kappaName
)
:
    mesh_(T.mesh()),
    solverDict_()
{
    checkInterpolation(kappaName);
    selectSolver(T.name());
}


// * * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

void Foam::conductivityJacobian::add
(
    fvScalarMatrix& eqn,
    const volScalarField& T,
    const volScalarField& dKappadT
) const
{
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const surfaceScalarField& weights = mesh_.weights();
    const scalarField& w = weights.primitiveField();
    // |S_f| Delta_f: G_f = gamma_f (T_N - T_P)
    const surfaceScalarField& deltaCoeffs = mesh_.nonOrthDeltaCoeffs();
    const surfaceScalarField& magSf = mesh_.magSf();
    const scalarField& dc = deltaCoeffs.primitiveField();
    const scalarField& mS = magSf.primitiveField();
    const scalarField& dk = dKappadT.primitiveField();
    const scalarField& Tk = T.primitiveField();

    // Allocate the lower coefficients (a copy of the symmetric upper ones)
    // before changing the upper ones
    scalarField& lower = eqn.lower();
    scalarField& upper = eqn.upper();
    scalarField& diag = eqn.diag();
    scalarField& source = eqn.source();

    forAll(own, facei)
    {
        const label P = own[facei];
        const label N = nei[facei];
        const scalar G = mS[facei]*dc[facei]*(Tk[N] - Tk[P]);
        const scalar aP = w[facei]*dk[P]*G;
        const scalar aN = (1 - w[facei])*dk[N]*G;
        const scalar aTk = aP*Tk[P] + aN*Tk[N];

        diag[P] -= aP;
        upper[facei] -= aN;
        source[P] -= aTk;

        diag[N] += aN;
        lower[facei] += aP;
        source[N] += aTk;
    }

    // Coupled faces: row P of this side; the interface coefficient c
    // enters the product as -c T_N (lduMatrix::updateMatrixInterfaces)
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& p = mesh_.boundary()[patchi];
        if (!p.coupled())
        {
            continue;
        }

        const labelUList& faceCells = p.faceCells();
        const scalarField& wp = weights.boundaryField()[patchi];
        const scalarField& dcp = deltaCoeffs.boundaryField()[patchi];
        const scalarField& mSp = magSf.boundaryField()[patchi];
        const scalarField dkN
        (
            dKappadT.boundaryField()[patchi].patchNeighbourField()
        );
        const scalarField TN(T.boundaryField()[patchi].patchNeighbourField());
        scalarField& bouCoeffs = eqn.boundaryCoeffs()[patchi];

        forAll(faceCells, facei)
        {
            const label P = faceCells[facei];
            const scalar G = mSp[facei]*dcp[facei]*(TN[facei] - Tk[P]);
            const scalar aP = wp[facei]*dk[P]*G;
            const scalar aN = (1 - wp[facei])*dkN[facei]*G;

            diag[P] -= aP;
            bouCoeffs[facei] += aN;
            source[P] -= aP*Tk[P] + aN*TN[facei];
        }
    }
}


// ************************************************************************* //
