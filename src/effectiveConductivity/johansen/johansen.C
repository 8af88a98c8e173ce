/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "johansen.H"
#include "addToRunTimeSelectionTable.H"
#include "checkedRead.H"

#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace effectiveConductivityModels
{
    defineTypeNameAndDebug(johansen, 0);
    addToRunTimeSelectionTable
    (
        effectiveConductivityModel,
        johansen,
        dictionary
    );
}
}

const Foam::Enum
<
    Foam::effectiveConductivityModels::johansen::soilType
>
Foam::effectiveConductivityModels::johansen::soilTypeNames
({
    { soilType::coarse, "coarse" },
    { soilType::fine, "fine" },
});

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::effectiveConductivityModels::johansen::johansen
(
    const dictionary& coeffs
)
:
    effectiveConductivityModel(coeffs),
    soilType_(soilType::coarse),
    rhoSolid_
    (
        checkedRead::getOrDefault
        (
            coeffs, "rhoSolid", dimDensity, 2700, checkedRead::positive()
        ).value()
    ),
    kappaDry_(0)
{
    if (!coeffs.found("soilType", keyType::LITERAL))
    {
        FatalIOErrorInFunction(coeffs)
            << "Keyword 'soilType' missing in " << coeffs.name()
            << " (conductivityModel johansen): valid choices are"
            << " coarse fine" << nl << exit(FatalIOError);
    }
    soilType_ =
        checkedRead::getChoice
        (
            coeffs, "soilType", soilTypeNames, soilType::coarse
        );

    if (coeffs.found("kappaDry", keyType::LITERAL))
    {
        kappaDry_ =
            checkedRead::get
            (
                coeffs, "kappaDry", dimPower/dimLength/dimTemperature,
                checkedRead::positive()
            ).value();
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::effectiveConductivityModels::johansen::Ke
(
    const scalar Sr
) const
{
    if (!(Sr > 0))
    {
        return 0;
    }
    const scalar a = (soilType_ == soilType::coarse) ? 0.7 : 1.0;
    const scalar ke = a*std::log10(Sr) + 1;
    return ke > 0 ? ke : scalar(0);
}


Foam::scalar Foam::effectiveConductivityModels::johansen::kappaDry
(
    const scalar porosity
) const
{
    if (kappaDry_ > 0)
    {
        return kappaDry_;
    }
    const scalar rhoDry = (1 - porosity)*rhoSolid_;
    return (0.135*rhoDry + 64.7)/(2700 - 0.947*rhoDry);
}


Foam::scalar Foam::effectiveConductivityModels::johansen::kappaSat
(
    const scalar kappaSolid,
    const scalar kappaLiquid,
    const scalar porosity
) const
{
    return std::pow(kappaSolid, 1 - porosity)*std::pow(kappaLiquid, porosity);
}


Foam::scalar
Foam::effectiveConductivityModels::johansen::kappaPartiallySaturated
(
    const scalar kappaSolid,
    const scalar kappaLiquid,
    const scalar,
    const scalar alphaL,
    const scalar porosity
) const
{
    const scalar kDry = kappaDry(porosity);
    return
        (kappaSat(kappaSolid, kappaLiquid, porosity) - kDry)*Ke(alphaL)
      + kDry;
}

// ************************************************************************* //
