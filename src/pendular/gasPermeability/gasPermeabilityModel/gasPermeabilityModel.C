/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "gasPermeabilityModel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(gasPermeabilityModel, 0);
    defineRunTimeSelectionTable(gasPermeabilityModel, dictionary);
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::gasPermeabilityModel::gasPermeabilityModel(const dictionary& coeffs)
:
    coeffs_(coeffs)
{}

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::scalarField> Foam::gasPermeabilityModel::Kg
(
    const scalarField& alphaL,
    const scalar porosity
) const
{
    tmp<scalarField> tresult(new scalarField(alphaL.size()));
    scalarField& result = tresult.ref();
    forAll(alphaL, i)
    {
        result[i] = Kg(alphaL[i], porosity);
    }
    return tresult;
}

// ************************************************************************* //
