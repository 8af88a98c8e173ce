/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "effectiveConductivityModel.H"
#include "checkedRead.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::effectiveConductivityModel>
Foam::effectiveConductivityModel::New(const dictionary& dict)
{
    if (!dict.found("conductivityModel"))
    {
        FatalIOErrorInFunction(dict)
            << "Missing keyword 'conductivityModel' in dictionary "
            << dict.name() << ": expected one of the valid"
            << " conductivityModel types :" << nl
            << dictionaryConstructorTablePtr_->sortedToc() << nl
            << exit(FatalIOError);
    }

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

    autoPtr<effectiveConductivityModel> model
    (
        cstrIter()(dict.optionalSubDict(modelType + "Coeffs"))
    );

    // Unknown keywords of its coefficients sub-dictionary
    checkedRead::checkCoeffs(dict, "conductivityModel", model());

    return model;
}

// ************************************************************************* //
