/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "saturationPressureLaw.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(saturationPressureLaw, 0);
    defineRunTimeSelectionTable(saturationPressureLaw, dictionary);
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::saturationPressureLaw::saturationPressureLaw(const dictionary& coeffs)
:
    coeffs_(coeffs)
{}

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::scalarField>
Foam::saturationPressureLaw::pSat(const scalarField& T) const
{
    tmp<scalarField> tresult(new scalarField(T.size()));
    scalarField& result = tresult.ref();
    forAll(T, i)
    {
        result[i] = pSat(T[i]);
    }
    return tresult;
}


Foam::tmp<Foam::scalarField>
Foam::saturationPressureLaw::dpSatdT(const scalarField& T) const
{
    tmp<scalarField> tresult(new scalarField(T.size()));
    scalarField& result = tresult.ref();
    forAll(T, i)
    {
        result[i] = dpSatdT(T[i]);
    }
    return tresult;
}

// ************************************************************************* //
