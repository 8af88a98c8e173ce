/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "surfaceTensionLaw.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(surfaceTensionLaw, 0);
    defineRunTimeSelectionTable(surfaceTensionLaw, dictionary);
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::surfaceTensionLaw::surfaceTensionLaw(const dictionary& coeffs)
:
    coeffs_(coeffs),
    Tmin_(248.15),
    Tmax_(GREAT)
{}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

void Foam::surfaceTensionLaw::rangeError(const scalar T) const
{
    FatalErrorInFunction
        << "surfaceTensionLaw " << type() << " evaluated at T = " << T
        << " K, outside its valid range [" << Tmin_ << ", " << Tmax_
        << "] K" << nl
        << "    (no liquid surface above the law's critical temperature "
        << Tmax_ << " K, where sigma = 0; below " << Tmin_
        << " K the liquid would be ice)"
        << exit(FatalError);
}

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::scalarField>
Foam::surfaceTensionLaw::sigma(const scalarField& T) const
{
    tmp<scalarField> tresult(new scalarField(T.size()));
    scalarField& result = tresult.ref();
    forAll(T, i)
    {
        result[i] = sigma(T[i]);
    }
    return tresult;
}


Foam::tmp<Foam::scalarField>
Foam::surfaceTensionLaw::dSigmadT(const scalarField& T) const
{
    tmp<scalarField> tresult(new scalarField(T.size()));
    scalarField& result = tresult.ref();
    forAll(T, i)
    {
        result[i] = dSigmadT(T[i]);
    }
    return tresult;
}

// ************************************************************************* //
