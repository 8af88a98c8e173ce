/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "relativeHumidityFvPatchScalarField.H"
#include "addToRunTimeSelectionTable.H"
#include "volFields.H"
#include "pendularMedium.H"
#include "checkedRead.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::relativeHumidityFvPatchScalarField::relativeHumidityFvPatchScalarField
(
    const fvPatch& p,
    const DimensionedField<scalar, volMesh>& iF
)
:
    fixedValueFvPatchScalarField(p, iF),
    relativeHumidity_(),
    airTemperature_(),
    TName_("T")
{}


Foam::relativeHumidityFvPatchScalarField::relativeHumidityFvPatchScalarField
(
    const fvPatch& p,
    const DimensionedField<scalar, volMesh>& iF,
    const dictionary& dict
)
:
    fixedValueFvPatchScalarField(p, iF, dict, false),
    relativeHumidity_(),
    airTemperature_(),
    TName_(dict.getOrDefault<word>("T", "T"))
{
    // Unknown keywords (a misspelt 'airTemperature' would silently take
    // the patch temperature)
    {
        wordList allowed(checkedRead::patchFieldKeywords());
        allowed.append
        (
            checkedRead::function1Keywords(dict, "relativeHumidity")
        );
        allowed.append(checkedRead::function1Keywords(dict, "airTemperature"));
        allowed.append("T");
        checkedRead::checkKeywords
        (
            dict, allowed,
            "boundary condition " + type() + " on patch '" + p.name()
          + "' of field " + iF.name()
        );
    }

    // (after the keyword check: a misspelt 'relativeHumidity' is named
    // with the nearest valid keyword, not as a missing entry)
    relativeHumidity_ = Function1<scalar>::New("relativeHumidity", dict);
    if (dict.found("airTemperature"))
    {
        airTemperature_ = Function1<scalar>::New("airTemperature", dict);
    }

    // RH, and the air temperature in kelvin (degrees Celsius typed would
    // give a saturation pressure of nearly 0: dry air), over the whole
    // run, before any step
    for
    (
        const scalar t
      : checkedRead::function1CheckTimes(*relativeHumidity_, db().time())
    )
    {
        relativeHumidity(t, &dict);
    }
    if (airTemperature_.valid())
    {
        for
        (
            const scalar t
          : checkedRead::function1CheckTimes(*airTemperature_, db().time())
        )
        {
            checkedRead::checkAirTemperature
            (
                dict.name(), "airTemperature", airTemperature_->value(t), t,
                "boundary condition " + type() + " on patch '" + p.name()
              + "' of field " + iF.name()
            );
        }
    }

    if (dict.found("value"))
    {
        fvPatchScalarField::operator=(scalarField("value", dict, p.size()));
    }
    else
    {
        fvPatchScalarField::operator=(Zero);
    }
}


Foam::relativeHumidityFvPatchScalarField::relativeHumidityFvPatchScalarField
(
    const relativeHumidityFvPatchScalarField& ptf,
    const fvPatch& p,
    const DimensionedField<scalar, volMesh>& iF,
    const fvPatchFieldMapper& mapper
)
:
    fixedValueFvPatchScalarField(ptf, p, iF, mapper),
    relativeHumidity_(ptf.relativeHumidity_.clone()),
    airTemperature_
    (
        ptf.airTemperature_.valid()
      ? ptf.airTemperature_.clone()
      : autoPtr<Function1<scalar>>()
    ),
    TName_(ptf.TName_)
{}


Foam::relativeHumidityFvPatchScalarField::relativeHumidityFvPatchScalarField
(
    const relativeHumidityFvPatchScalarField& ptf
)
:
    fixedValueFvPatchScalarField(ptf),
    relativeHumidity_(ptf.relativeHumidity_.clone()),
    airTemperature_
    (
        ptf.airTemperature_.valid()
      ? ptf.airTemperature_.clone()
      : autoPtr<Function1<scalar>>()
    ),
    TName_(ptf.TName_)
{}


Foam::relativeHumidityFvPatchScalarField::relativeHumidityFvPatchScalarField
(
    const relativeHumidityFvPatchScalarField& ptf,
    const DimensionedField<scalar, volMesh>& iF
)
:
    fixedValueFvPatchScalarField(ptf, iF),
    relativeHumidity_(ptf.relativeHumidity_.clone()),
    airTemperature_
    (
        ptf.airTemperature_.valid()
      ? ptf.airTemperature_.clone()
      : autoPtr<Function1<scalar>>()
    ),
    TName_(ptf.TName_)
{}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::relativeHumidityFvPatchScalarField::relativeHumidity
(
    const dictionary* dict
) const
{
    return relativeHumidity(db().time().timeOutputValue(), dict);
}


Foam::scalar Foam::relativeHumidityFvPatchScalarField::relativeHumidity
(
    const scalar t,
    const dictionary* dict
) const
{
    const scalar RH = relativeHumidity_->value(t);
    if (!(RH >= 0 && RH <= 1))
    {
        if (dict)
        {
            FatalIOErrorInFunction(*dict)
                << "Patch " << patch().name() << " of field "
                << internalField().name() << ": keyword 'relativeHumidity' = "
                << RH << " at t = " << t
                << " s is outside its valid range [0, 1]"
                << exit(FatalIOError);
        }
        FatalErrorInFunction
            << "Patch " << patch().name() << " of field "
            << internalField().name() << " (" << internalField().objectPath()
            << "): keyword 'relativeHumidity' = " << RH << " at t = " << t
            << " s is outside its valid range [0, 1]"
            << exit(FatalError);
    }
    return RH;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::relativeHumidityFvPatchScalarField::updateCoeffs()
{
    if (updated())
    {
        return;
    }

    const scalar t = db().time().timeOutputValue();
    const scalar RH = relativeHumidity();

    // The medium is registered under the name of its file (soilProperties
    // or the alias pendularProperties)
    const HashTable<const pendularMedium*> media =
        db().lookupClass<pendularMedium>();
    if (media.size() != 1)
    {
        FatalErrorInFunction
            << "Boundary condition " << type() << " on patch "
            << patch().name() << " needs the pendular medium of"
            << " pendularFoam; found " << media.size() << nl
            << exit(FatalError);
    }
    const pendularMedium& medium = *media.cbegin().val();
    const fvPatchScalarField& Tp =
        patch().lookupPatchField<volScalarField, scalar>(TName_);

    // The air temperature of the Function1, in kelvin (checked)
    const scalar TairUniform =
        airTemperature_.valid() ? airTemperature_->value(t) : 0;
    if (airTemperature_.valid())
    {
        checkedRead::checkAirTemperature
        (
            internalField().objectPath(), "airTemperature", TairUniform, t,
            "boundary condition " + type() + " on patch '" + patch().name()
          + "' of field " + internalField().name()
        );
    }

    scalarField pw(Tp.size());
    forAll(pw, facei)
    {
        const scalar Tair =
            airTemperature_.valid() ? TairUniform : Tp[facei];
        // p_wsat held at its critical value above the critical point
        pw[facei] = RH*medium.saturationPressure(Tair);
    }
    operator==(pw);

    fixedValueFvPatchScalarField::updateCoeffs();
}


void Foam::relativeHumidityFvPatchScalarField::write(Ostream& os) const
{
    fvPatchScalarField::write(os);
    relativeHumidity_->writeData(os);
    if (airTemperature_.valid())
    {
        airTemperature_->writeData(os);
    }
    os.writeEntryIfDifferent<word>("T", "T", TName_);
    writeEntry("value", os);
}


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{
    makePatchTypeField
    (
        fvPatchScalarField,
        relativeHumidityFvPatchScalarField
    );
}

// ************************************************************************* //
