/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "capillaryPressureModel.H"
#include "checkedRead.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::capillaryPressureModel>
Foam::capillaryPressureModel::New(const dictionary& dict)
{
    const word modelType(dict.get<word>("capillaryPressureModel"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "capillaryPressureModel",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    autoPtr<capillaryPressureModel> model
    (
        cstrIter()(dict, dict.optionalSubDict(modelType + "Coeffs"))
    );

    checkedRead::checkCoeffs(dict, "capillaryPressureModel", model());

    return model;
}

// ************************************************************************* //
