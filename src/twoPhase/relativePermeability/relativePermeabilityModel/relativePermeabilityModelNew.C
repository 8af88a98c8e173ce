/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "relativePermeabilityModel.H"
#include "checkedRead.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::relativePermeabilityModel>
Foam::relativePermeabilityModel::New(const dictionary& dict)
{
    const word modelType(dict.get<word>("relativePermeabilityModel"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "relativePermeabilityModel",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    autoPtr<relativePermeabilityModel> model
    (
        cstrIter()(dict, dict.optionalSubDict(modelType + "Coeffs"))
    );

    checkedRead::checkCoeffs(dict, "relativePermeabilityModel", model());

    return model;
}

// ************************************************************************* //
