/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "saturationPressureLaw.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::saturationPressureLaw>
Foam::saturationPressureLaw::New(const dictionary& dict)
{
    const word lawType
    (
        dict.getOrDefault<word>("saturationPressureLaw", "wagnerPruss")
    );

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(lawType);

    if (!cstrIter.found())
    {
        // "Unknown saturationPressureLaw type <name>", with the valid choices
        FatalIOErrorInLookup
        (
            dict,
            "saturationPressureLaw",
            lawType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<saturationPressureLaw>
    (
        cstrIter()(dict.optionalSubDict(lawType + "Coeffs"))
    );
}

// ************************************************************************* //
