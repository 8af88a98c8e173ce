/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "surfaceTensionLaw.H"
#include "checkedRead.H"

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

    autoPtr<surfaceTensionLaw> model
    (
        cstrIter()(dict.optionalSubDict(lawType + "Coeffs"))
    );

    // Unknown keywords of its coefficients sub-dictionary
    checkedRead::checkCoeffs(dict, "surfaceTensionLaw", model());

    return model;
}

// ************************************************************************* //
