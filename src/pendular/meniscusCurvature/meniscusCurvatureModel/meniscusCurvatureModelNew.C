/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "meniscusCurvatureModel.H"
#include "checkedRead.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::meniscusCurvatureModel>
Foam::meniscusCurvatureModel::New(const dictionary& dict)
{
    const word modelType
    (
        dict.getOrDefault<word>("meniscusModel", "asymptoticToroidal")
    );

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        // "Unknown meniscusModel type <name>", with the valid choices
        FatalIOErrorInLookup
        (
            dict,
            "meniscusModel",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    autoPtr<meniscusCurvatureModel> model
    (
        cstrIter()(dict.optionalSubDict(modelType + "Coeffs"))
    );

    // Unknown keywords of its coefficients sub-dictionary
    checkedRead::checkCoeffs(dict, "meniscusModel", model());

    return model;
}

// ************************************************************************* //
