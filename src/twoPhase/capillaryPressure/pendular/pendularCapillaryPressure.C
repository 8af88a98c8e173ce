/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "pendularCapillaryPressure.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace capillaryPressureModels
{
    defineTypeNameAndDebug(pendular, 0);
    addToRunTimeSelectionTable
    (
        capillaryPressureModel,
        pendular,
        dictionary
    );
}
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::capillaryPressureModels::pendular::pendular
(
    const dictionary& dict,
    const dictionary& coeffs
)
:
    capillaryPressureModel(dict, coeffs),
    equilibrium_(coeffs)
{
    if (saturation_.Swr() != 0 || saturation_.Sgr() != 0)
    {
        FatalIOErrorInFunction(dict)
            << "capillaryPressureModel pendular in " << dict.name()
            << " takes the liquid fraction alpha_l = S itself: residual"
            << " saturations 'Swr' = " << saturation_.Swr() << " and 'Sgr' = "
            << saturation_.Sgr() << " must be 0 (or absent)" << nl
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::capillaryPressureModels::pendular::pcEff
(
    const scalar Se,
    const scalar T
) const
{
    return
       -equilibrium_.surfaceTension().sigma(T)
       *equilibrium_.meniscus().K(Se);
}


Foam::scalar Foam::capillaryPressureModels::pendular::dpcdSeEff
(
    const scalar Se,
    const scalar T
) const
{
    return
       -equilibrium_.surfaceTension().sigma(T)
       *equilibrium_.meniscus().dKdAlphaL(Se);
}


Foam::scalar Foam::capillaryPressureModels::pendular::dpcdTEff
(
    const scalar Se,
    const scalar T
) const
{
    return
       -equilibrium_.surfaceTension().dSigmadT(T)
       *equilibrium_.meniscus().K(Se);
}

// ************************************************************************* //
