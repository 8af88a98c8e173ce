/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "saturationPressureLaw.H"
#include "checkedRead.H"

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

    autoPtr<saturationPressureLaw> model
    (
        cstrIter()(dict.optionalSubDict(lawType + "Coeffs"))
    );

    // Unknown keywords of its coefficients sub-dictionary
    checkedRead::checkCoeffs(dict, "saturationPressureLaw", model());

    return model;
}

// ************************************************************************* //
