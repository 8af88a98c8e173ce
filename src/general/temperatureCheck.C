/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "temperatureCheck.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

//- The first face of a non-coupled patch of T at or below 0 K (or NaN):
//  true, with its patch and face; false if there is none
bool firstNonPositiveFace
(
    const Foam::volScalarField& T,
    Foam::label& patchi,
    Foam::label& facei
)
{
    forAll(T.boundaryField(), pi)
    {
        const Foam::fvPatchScalarField& Tp = T.boundaryField()[pi];
        if (Tp.coupled())
        {
            continue;
        }
        forAll(Tp, fi)
        {
            if (!(Tp[fi] > 0))
            {
                patchi = pi;
                facei = fi;
                return true;
            }
        }
    }
    return false;
}

} // End anonymous namespace


void Foam::temperatureCheck::initial(const volScalarField& T)
{
    dictionary fieldDict;
    fieldDict.name() = T.objectPath();

    forAll(T, celli)
    {
        if (!(T[celli] > 0))
        {
            FatalIOErrorInFunction(fieldDict)
                << "Field '" << T.name() << "' (keyword 'internalField') = "
                << T[celli] << " K in cell " << celli << " is outside its"
                << " valid range (0, inf): at or below absolute zero, in"
                << " file " << T.objectPath() << nl
                << exit(FatalIOError);
        }
        if (T[celli] < celsiusThreshold)
        {
            FatalIOErrorInFunction(fieldDict)
                << "Field '" << T.name() << "' (keyword 'internalField') = "
                << T[celli] << " K in cell " << celli << " is below "
                << celsiusThreshold << " K (" << celsiusThreshold - 273.15
                << " C), colder than any soil: was it given in Celsius?"
                << " T is in kelvin: " << T[celli] << " C is "
                << T[celli] + 273.15 << " K. Valid range ["
                << celsiusThreshold << ", inf) K, in file "
                << T.objectPath() << nl
                << exit(FatalIOError);
        }
    }

    label patchi = -1, facei = -1;
    if (firstNonPositiveFace(T, patchi, facei))
    {
        const fvPatchScalarField& Tp = T.boundaryField()[patchi];
        FatalIOErrorInFunction(fieldDict)
            << "Field '" << T.name() << "' on patch '"
            << Tp.patch().name() << "' (boundaryField "
            << Tp.patch().name() << ", type " << Tp.type()
            << ") = " << Tp[facei] << " K at t = "
            << T.time().timeName() << " s, face " << facei
            << ": outside its valid range (0, inf), at or below"
            << " absolute zero, in file " << T.objectPath() << nl
            << exit(FatalIOError);
    }
}


void Foam::temperatureCheck::boundary(const volScalarField& T)
{
    label patchi = -1, facei = -1;
    if (firstNonPositiveFace(T, patchi, facei))
    {
        const fvPatchScalarField& Tp = T.boundaryField()[patchi];
        FatalErrorInFunction
            << "Temperature on patch '" << Tp.patch().name()
            << "' (boundaryField " << Tp.patch().name() << " of "
            << T.name() << ", type " << Tp.type() << ") = " << Tp[facei]
            << " K at t = " << T.time().timeName() << " s, face " << facei
            << ": at or below absolute zero (valid range (0, inf)"
            << " K). Check the temperature history of patch '"
            << Tp.patch().name() << "' (a table going below 0 K?)"
            << nl << exit(FatalError);
    }
}

// ************************************************************************* //
