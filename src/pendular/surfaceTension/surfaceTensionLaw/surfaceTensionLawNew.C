/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "surfaceTensionLaw.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::surfaceTensionLaw>
Foam::surfaceTensionLaw::New(const dictionary& dict)
{
    const word lawType
    (
        dict.getOrDefault<word>("surfaceTensionLaw", "vargaftik")
    );

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(lawType);

    if (!cstrIter.found())
    {
        // "Unknown surfaceTensionLaw type <name>", with the valid choices
        FatalIOErrorInLookup
        (
            dict,
            "surfaceTensionLaw",
            lawType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<surfaceTensionLaw>
    (
        cstrIter()(dict.optionalSubDict(lawType + "Coeffs"))
    );
}

// ************************************************************************* //
