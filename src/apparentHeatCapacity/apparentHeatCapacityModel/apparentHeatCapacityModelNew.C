/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "apparentHeatCapacityModel.H"
#include "checkedRead.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::apparentHeatCapacityModel>
Foam::apparentHeatCapacityModel::New
(
    const dictionary& dict,
    const phaseProperties& liquid,
    const phaseProperties& vapour
)
{
    // Unknown keywords (a misspelt 'irreversible' would give its default)
    checkedRead::checkKeywords
    (
        dict,
        wordList({"type", "Tv", "dT", "latentHeat", "irreversible"})
    );

    const word modelType(dict.getOrDefault<word>("type", "energyConsistent"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        // "Unknown phaseChange type <name>", with the valid choices
        FatalIOErrorInLookup
        (
            dict,
            "phaseChange",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<apparentHeatCapacityModel>
    (
        cstrIter()(dict, liquid, vapour)
    );
}

// ************************************************************************* //
