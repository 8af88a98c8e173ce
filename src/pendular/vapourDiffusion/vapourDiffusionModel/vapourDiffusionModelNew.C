/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "vapourDiffusionModel.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::vapourDiffusionModel>
Foam::vapourDiffusionModel::New(const dictionary& dict)
{
    const word modelType
    (
        dict.getOrDefault<word>("vapourDiffusionModel", "constant")
    );

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        // "Unknown vapourDiffusionModel type <name>", with the valid choices
        FatalIOErrorInLookup
        (
            dict,
            "vapourDiffusionModel",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    autoPtr<vapourDiffusionModel> model(cstrIter()(dict));

    // Its coefficients are entries of dict: in a <model>Coeffs
    // sub-dictionary nobody would read them
    const word coeffsName(modelType + "Coeffs");
    for (const word& key : model->coeffKeywords())
    {
        if (dict.isDict(coeffsName) && dict.subDict(coeffsName).found(key))
        {
            FatalIOErrorInFunction(dict.subDict(coeffsName))
                << "'" << key << "' in the sub-dictionary " << coeffsName
                << " of " << dict.name() << ": the coefficients of"
                << " vapourDiffusionModel " << modelType << " are entries of"
                << " that dictionary itself (valid: " << key << " beside"
                << " vapourDiffusionModel)" << exit(FatalIOError);
        }
    }

    return model;
}

// ************************************************************************* //
