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
    coeffs_(coeffs)
{}

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
