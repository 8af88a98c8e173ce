/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "gasPermeabilityModel.H"
#include "checkedRead.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::gasPermeabilityModel>
Foam::gasPermeabilityModel::New(const dictionary& dict)
{
    const word modelType
    (
        dict.getOrDefault<word>("gasPermeabilityModel", "kozenyCarman")
    );

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        // "Unknown gasPermeabilityModel type <name>", with the valid choices
        FatalIOErrorInLookup
        (
            dict,
            "gasPermeabilityModel",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    autoPtr<gasPermeabilityModel> model
    (
        cstrIter()(dict.optionalSubDict(modelType + "Coeffs"))
    );

    // Unknown keywords of its coefficients sub-dictionary
    checkedRead::checkCoeffs(dict, "gasPermeabilityModel", model());

    return model;
}

// ************************************************************************* //
