/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "waterModel.H"
#include "checkedRead.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::waterModel> Foam::waterModel::New
(
    const pendularMedium& medium,
    const dictionary& dict
)
{
    const word modelType
    (
        dict.getOrDefault<word>("waterModel", "equilibrium")
    );

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        // "Unknown waterModel type <name>", with the valid choices
        FatalIOErrorInLookup
        (
            dict,
            "waterModel",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    autoPtr<waterModel> model
    (
        cstrIter()(medium, dict.optionalSubDict(modelType + "Coeffs"))
    );

    // Unknown keywords of its coefficients sub-dictionary
    checkedRead::checkCoeffs(dict, "waterModel", model());

    return model;
}

// ************************************************************************* //
