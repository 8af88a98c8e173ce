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

const Foam::scalar Foam::saturationPressureLaw::criticalTemperature = 647.096;
const Foam::scalar Foam::saturationPressureLaw::supercooledLimit = 248.15;

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::saturationPressureLaw::saturationPressureLaw(const dictionary& coeffs)
:
    coeffs_(coeffs),
    Tmin_(supercooledLimit),
    Tmax_(criticalTemperature)
{}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

void Foam::saturationPressureLaw::rangeError(const scalar T) const
{
    FatalErrorInFunction
        << "saturationPressureLaw " << type() << " evaluated at T = " << T
        << " K, outside its valid range [" << Tmin_ << ", " << Tmax_
        << "] K" << nl
        << "    (no liquid-vapour saturation above the critical point of"
        << " water, " << criticalTemperature << " K; below " << Tmin_
        << " K the liquid would be ice)"
        << exit(FatalError);
}

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
