/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "capillaryPressureModel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(capillaryPressureModel, 0);
    defineRunTimeSelectionTable(capillaryPressureModel, dictionary);
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::capillaryPressureModel::capillaryPressureModel
(
    const dictionary& dict,
    const dictionary& coeffs
)
:
    coeffs_(coeffs),
    saturation_(dict)
{}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::capillaryPressureModel::checkedSe(const scalar S) const
{
    const string who("capillaryPressureModel " + type());
    const scalar Se = saturation_.Se(S, who);
    if (Se <= 0 && !boundedAtResidual())
    {
        FatalErrorInFunction
            << who.c_str() << " evaluated at S = " << S << " <= Swr = "
            << saturation_.Swr() << " (S_e = 0), where its capillary"
            << " pressure is unbounded: valid range of S is (Swr, 1] = ("
            << saturation_.Swr() << ", 1]" << nl
            << exit(FatalError);
    }
    return Se;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::capillaryPressureModel::pc
(
    const scalar S,
    const scalar T
) const
{
    return pcEff(checkedSe(S), T);
}


Foam::scalar Foam::capillaryPressureModel::dpcdS
(
    const scalar S,
    const scalar T
) const
{
    const scalar Se = checkedSe(S);
    const scalar dSedS = saturation_.dSedS(S, "capillaryPressureModel " + type());
    return dSedS > 0 ? dpcdSeEff(Se, T)*dSedS : scalar(0);
}


Foam::scalar Foam::capillaryPressureModel::dpcdT
(
    const scalar S,
    const scalar T
) const
{
    return dpcdTEff(checkedSe(S), T);
}

// ************************************************************************* //
