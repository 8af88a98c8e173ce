/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "meniscusCurvatureModel.H"
#include "checkedRead.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(meniscusCurvatureModel, 0);
    defineRunTimeSelectionTable(meniscusCurvatureModel, dictionary);
}

const Foam::scalar Foam::meniscusCurvatureModel::alphaLTiny = 1e-150;

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::meniscusCurvatureModel::meniscusCurvatureModel
(
    const dictionary& coeffs
)
:
    coeffs_(coeffs),
    alphaLMax_
    (
        checkedRead::getOrDefault
        (
            coeffs, "alphaLMax", dimless, 0.1,
            validRange{0, 1, true, true}
        ).value()
    )
{}

// * * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * //

Foam::scalar Foam::meniscusCurvatureModel::checkedAlphaL
(
    const dictionary& dict,
    const word& keyword
)
{
    return
        checkedRead::get
        (
            dict, keyword, dimless, checkedRead::closedOpen(0, 1)
        ).value();
}


void Foam::meniscusCurvatureModel::checkAlphaL
(
    const fileName& fieldFile,
    const word& fieldName,
    const scalarField& alphaL
)
{
    checkedRead::check
    (
        fieldFile, fieldName, alphaL, checkedRead::closedOpen(0, 1)
    );
}

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::meniscusCurvatureModel::alphaL(const scalar Kt) const
{
    if (Kt >= K(1))
    {
        return 1;
    }
    if (Kt <= K(alphaLTiny))
    {
        return 0;
    }

    // Root in x = log(alpha_l) of an increasing function F(x):
    //   Kt < 0: F = log(-Kt) - log(-K(e^x)), linear in x for a power law
    //           K ~ -alpha_l^(-m), so that Newton is then exact at once
    //   else:   F = K(e^x) - Kt
    // Newton steps, bisection of the bracket [lo, hi] when a step leaves it
    // or does not halve |F|
    const bool logForm = (Kt < 0);
    const scalar lnMinusKt = logForm ? std::log(-Kt) : 0;
    const scalar tol = 1e-14;

    scalar lo = std::log(alphaLTiny);
    scalar hi = 0;
    scalar x = 0.5*(lo + hi);
    scalar Fprev = GREAT;

    for (label iter = 0; iter < 400; ++iter)
    {
        const scalar a = std::exp(x);
        const scalar k = K(a);
        const scalar dkdx = dKdAlphaL(a)*a;

        scalar F, dFdx;
        if (logForm)
        {
            if (k >= 0)
            {
                // Above the root (the log is undefined): bisect
                hi = x;
                x = 0.5*(lo + hi);
                continue;
            }
            F = lnMinusKt - std::log(-k);
            dFdx = -dkdx/k;
        }
        else
        {
            F = k - Kt;
            dFdx = dkdx;
        }

        if (F == 0)
        {
            return a;
        }
        if (F < 0)
        {
            lo = x;
        }
        else
        {
            hi = x;
        }

        scalar xNew = 0.5*(lo + hi);
        if (dFdx > 0 && mag(F) < 0.5*mag(Fprev))
        {
            const scalar xNewton = x - F/dFdx;
            if (xNewton > lo && xNewton < hi)
            {
                xNew = xNewton;
            }
        }
        Fprev = F;

        const scalar dx = mag(xNew - x);
        x = xNew;
        if (dx <= tol*max(scalar(1), mag(x)) || hi - lo <= tol)
        {
            break;
        }
    }

    return std::exp(x);
}


Foam::scalar Foam::meniscusCurvatureModel::nonEquilibriumCoeff() const
{
    FatalErrorInFunction
        << "The meniscus model " << type() << " gives no rate coefficient"
        << " for the non-equilibrium evaporation (model B)" << nl
        << exit(FatalError);
    return 0;
}


Foam::scalar Foam::meniscusCurvatureModel::nonEquilibriumExponent() const
{
    FatalErrorInFunction
        << "The meniscus model " << type() << " gives no exponent"
        << " for the non-equilibrium evaporation (model B)" << nl
        << exit(FatalError);
    return 0;
}


Foam::scalar Foam::meniscusCurvatureModel::grainRadius() const
{
    FatalErrorInFunction
        << "The meniscus model " << type() << " gives no grain radius"
        << " for the non-equilibrium evaporation (model B)" << nl
        << exit(FatalError);
    return 0;
}


Foam::tmp<Foam::scalarField>
Foam::meniscusCurvatureModel::K(const scalarField& alphaL) const
{
    tmp<scalarField> tresult(new scalarField(alphaL.size()));
    scalarField& result = tresult.ref();
    forAll(alphaL, i)
    {
        result[i] = K(alphaL[i]);
    }
    return tresult;
}


Foam::tmp<Foam::scalarField>
Foam::meniscusCurvatureModel::dKdAlphaL(const scalarField& alphaL) const
{
    tmp<scalarField> tresult(new scalarField(alphaL.size()));
    scalarField& result = tresult.ref();
    forAll(alphaL, i)
    {
        result[i] = dKdAlphaL(alphaL[i]);
    }
    return tresult;
}

// ************************************************************************* //
