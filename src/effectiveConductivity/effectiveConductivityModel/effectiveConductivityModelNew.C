/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "effectiveConductivityModel.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::effectiveConductivityModel>
Foam::effectiveConductivityModel::New(const dictionary& dict)
{
    const word modelType(dict.get<word>("conductivityModel"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "conductivityModel",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<effectiveConductivityModel>
    (
        cstrIter()(dict.optionalSubDict(modelType + "Coeffs"))
    );
}

// ************************************************************************* //
