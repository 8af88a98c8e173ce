/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "surfaceHeatLossFvPatchScalarField.H"
#include "addToRunTimeSelectionTable.H"
#include "fvPatchFieldMapper.H"
#include "volFields.H"
#include "physicoChemicalConstants.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::scalar Foam::surfaceHeatLossFvPatchScalarField::TminPlausible =
    Foam::checkedRead::minAirTemperature;


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::surfaceHeatLossFvPatchScalarField::checkRange
(
    const word& keyword,
    const scalar value,
    const validRange& range,
    const bool ofTime,
    const scalar t
) const
{
    if (!range.contains(value))
    {
        dictionary dict;
        dict.name() = dictName_;
        FatalIOErrorInFunction(dict)
            << "Keyword '" << keyword << "' = " << value;
        if (ofTime)
        {
            FatalIOError << " (time " << t << ")";
        }
        FatalIOError
            << " of boundary condition " << type()
            << " on patch '" << patch().name() << "' of field "
            << internalField().name()
            << " is outside its valid range " << range.str().c_str() << nl
            << exit(FatalIOError);
    }
}


Foam::scalar Foam::surfaceHeatLossFvPatchScalarField::checkedValue
(
    const word& keyword,
    const Function1<scalar>& f,
    const scalar t
) const
{
    const scalar v = f.value(t);
    if (keyword == "h")
    {
        checkRange(keyword, v, checkedRead::nonNegative(), true, t);
    }
    else if (keyword == "heatFlux")
    {
        checkRange(keyword, v, checkedRead::closed(0, 1e7), true, t);
    }
    else
    {
        checkedRead::checkAirTemperature
        (
            dictName_, keyword, v, t,
            "boundary condition " + type() + " on patch '" + patch().name()
          + "' of field " + internalField().name()
        );
    }
    return v;
}


void Foam::surfaceHeatLossFvPatchScalarField::checkOverRun() const
{
    const Time& runTime = db().time();
    const std::pair<word, const Function1<scalar>*> fs[] =
    {
        {"h", h_.get()}, {"Tair", Tair_.get()}, {"Tsky", Tsky_.get()},
        {"heatFlux", heatFlux_.get()}
    };
    for (const auto& f : fs)
    {
        if (!f.second) continue;
        for
        (
            const scalar t
          : checkedRead::function1CheckTimes(*f.second, runTime)
        )
        {
            checkedValue(f.first, *f.second, t);
        }
    }
}


void Foam::surfaceHeatLossFvPatchScalarField::values
(
    scalar& h,
    scalar& Tair,
    scalar& Tsky
) const
{
    const scalar t = db().time().timeOutputValue();

    h = checkedValue("h", *h_, t);
    Tair = checkedValue("Tair", *Tair_, t);
    Tsky = Tsky_.valid() ? checkedValue("Tsky", *Tsky_, t) : Tair;
}


Foam::scalar Foam::surfaceHeatLossFvPatchScalarField::imposedFlux() const
{
    if (!heatFlux_.valid())
    {
        return 0;
    }
    return
        checkedValue("heatFlux", *heatFlux_, db().time().timeOutputValue());
}


const Foam::scalarField&
Foam::surfaceHeatLossFvPatchScalarField::kappa() const
{
    const volScalarField* kappaPtr =
        db().cfindObject<volScalarField>(kappaName_);

    if (!kappaPtr)
    {
        FatalErrorInFunction
            << "Boundary condition " << type() << " on patch '"
            << patch().name() << "' of field " << internalField().name()
            << " needs the conductivity [W/m/K] as a volScalarField named '"
            << kappaName_ << "' in the mesh registry, and there is none."
            << nl << "    ahcFoam registers the soil's effective"
            << " conductivity as 'kappa'; with another solver, set"
            << " 'kappa <fieldName>;' in the patch entry." << nl
            << exit(FatalError);
    }

    const scalarField& kappap = kappaPtr->boundaryField()[patch().index()];

    forAll(kappap, facei)
    {
        if (!(kappap[facei] > 0))
        {
            FatalErrorInFunction
                << "Boundary condition " << type() << " on patch '"
                << patch().name() << "' of field " << internalField().name()
                << ": conductivity '" << kappaName_ << "' = "
                << kappap[facei] << " on face " << facei
                << " is not positive" << nl
                << exit(FatalError);
        }
    }

    return kappap;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::surfaceHeatLossFvPatchScalarField::surfaceHeatLossFvPatchScalarField
(
    const fvPatch& p,
    const DimensionedField<scalar, volMesh>& iF
)
:
    mixedFvPatchScalarField(p, iF),
    h_(),
    Tair_(),
    Tsky_(),
    heatFlux_(),
    emissivity_(0),
    kappaName_("kappa"),
    dictName_(iF.objectPath())
{
    refValue() = Zero;
    refGrad() = Zero;
    valueFraction() = Zero;
}


Foam::surfaceHeatLossFvPatchScalarField::surfaceHeatLossFvPatchScalarField
(
    const fvPatch& p,
    const DimensionedField<scalar, volMesh>& iF,
    const dictionary& dict
)
:
    mixedFvPatchScalarField(p, iF),
    h_(),
    Tair_(),
    Tsky_(),
    heatFlux_(),
    emissivity_(0),
    kappaName_(dict.getOrDefault<word>("kappa", "kappa")),
    dictName_(dict.name())
{
    // Unknown keywords (a misspelt 'emissivity' would switch radiation
    // off): the standard ones, those written for a restart, the
    // Function1s' and this condition's
    {
        wordList allowed(checkedRead::patchFieldKeywords());
        allowed.append
        (
            wordList({"refValue", "refGradient", "valueFraction"})
        );
        allowed.append(checkedRead::function1Keywords(dict, "h"));
        allowed.append(checkedRead::function1Keywords(dict, "Tair"));
        allowed.append(checkedRead::function1Keywords(dict, "Tsky"));
        allowed.append(checkedRead::function1Keywords(dict, "heatFlux"));
        allowed.append(wordList({"emissivity", "kappa"}));
        checkedRead::checkKeywords
        (
            dict, allowed,
            "boundary condition " + type() + " on patch '" + p.name()
          + "' of field " + iF.name()
        );
    }

    // (after the keyword check: a misspelt 'Tair' is named with the
    // nearest valid keyword, not as a missing entry)
    h_ = Function1<scalar>::New("h", dict);
    Tair_ = Function1<scalar>::New("Tair", dict);
    if (dict.found("Tsky"))
    {
        Tsky_ = Function1<scalar>::New("Tsky", dict);
    }
    if (dict.found("heatFlux"))
    {
        heatFlux_ = Function1<scalar>::New("heatFlux", dict);
    }
    // (a finite number, then its range in the words of this condition)
    emissivity_ =
        checkedRead::getOrDefault
        (
            dict, "emissivity", dimless, 0,
            validRange{-GREAT, GREAT, true, true}
        ).value();
    checkRange("emissivity", emissivity_, checkedRead::closed(0, 1), false);


    // Range of the Function1s over the whole run, before any step
    checkOverRun();

    if (dict.found("value"))
    {
        fvPatchScalarField::operator=(scalarField("value", dict, p.size()));
    }
    else
    {
        fvPatchScalarField::operator=(patchInternalField());
    }

    if (dict.found("refValue"))
    {
        // Restart: the coefficients of the last step
        refValue() = scalarField("refValue", dict, p.size());
        refGrad() = scalarField("refGradient", dict, p.size());
        valueFraction() = scalarField("valueFraction", dict, p.size());
    }
    else
    {
        // Set at the first update (the conductivity field may not exist
        // yet); zero-gradient until then
        refValue() = *this;
        refGrad() = Zero;
        valueFraction() = Zero;
    }
}


Foam::surfaceHeatLossFvPatchScalarField::surfaceHeatLossFvPatchScalarField
(
    const surfaceHeatLossFvPatchScalarField& ptf,
    const fvPatch& p,
    const DimensionedField<scalar, volMesh>& iF,
    const fvPatchFieldMapper& mapper
)
:
    mixedFvPatchScalarField(ptf, p, iF, mapper),
    h_(ptf.h_.clone()),
    Tair_(ptf.Tair_.clone()),
    Tsky_(ptf.Tsky_.clone()),
    heatFlux_(ptf.heatFlux_.clone()),
    emissivity_(ptf.emissivity_),
    kappaName_(ptf.kappaName_),
    dictName_(ptf.dictName_)
{}


Foam::surfaceHeatLossFvPatchScalarField::surfaceHeatLossFvPatchScalarField
(
    const surfaceHeatLossFvPatchScalarField& ptf
)
:
    mixedFvPatchScalarField(ptf),
    h_(ptf.h_.clone()),
    Tair_(ptf.Tair_.clone()),
    Tsky_(ptf.Tsky_.clone()),
    heatFlux_(ptf.heatFlux_.clone()),
    emissivity_(ptf.emissivity_),
    kappaName_(ptf.kappaName_),
    dictName_(ptf.dictName_)
{}


Foam::surfaceHeatLossFvPatchScalarField::surfaceHeatLossFvPatchScalarField
(
    const surfaceHeatLossFvPatchScalarField& ptf,
    const DimensionedField<scalar, volMesh>& iF
)
:
    mixedFvPatchScalarField(ptf, iF),
    h_(ptf.h_.clone()),
    Tair_(ptf.Tair_.clone()),
    Tsky_(ptf.Tsky_.clone()),
    heatFlux_(ptf.heatFlux_.clone()),
    emissivity_(ptf.emissivity_),
    kappaName_(ptf.kappaName_),
    dictName_(ptf.dictName_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::scalarField>
Foam::surfaceHeatLossFvPatchScalarField::heatFlux() const
{
    scalar h, Tair, Tsky;
    values(h, Tair, Tsky);

    const scalar epsSigma =
        emissivity_*constant::physicoChemical::sigma.value();
    const scalarField& Tw = *this;

    return
        imposedFlux() + h*(Tair - Tw) + epsSigma*(pow4(Tsky) - pow4(Tw));
}


Foam::scalar Foam::surfaceHeatLossFvPatchScalarField::wallTemperature
(
    const scalar Tc,
    const scalar kappaDelta
) const
{
    scalar h, Tair, Tsky;
    values(h, Tair, Tsky);
    const scalar qs = imposedFlux();
    const scalar epsSigma =
        emissivity_*constant::physicoChemical::sigma.value();

    // g(T_w) = kappaDelta (T_w - T_c) - q(T_w) = (kappaDelta + h) T_w
    // + eps sigma T_w^4 - const: increasing and convex for T_w > 0, so
    // Newton from a point where g >= 0 decreases monotonically to the
    // root; the root without the T_w^4 term is one (g = eps sigma T_w^4)
    scalar Tw =
        (kappaDelta*Tc + qs + h*Tair + epsSigma*pow4(Tsky))/(kappaDelta + h);
    for (label iter = 0; iter < 100; ++iter)
    {
        const scalar g =
            kappaDelta*(Tw - Tc)
          - (qs + h*(Tair - Tw) + epsSigma*(pow4(Tsky) - pow4(Tw)));
        const scalar dg = kappaDelta + h + 4*epsSigma*pow3(Tw);
        const scalar dTw = g/dg;
        Tw -= dTw;
        if (mag(dTw) <= 1e-12*Tw)
        {
            return Tw;
        }
    }
    FatalErrorInFunction
        << "Boundary condition " << type() << " on patch '"
        << patch().name() << "' of field " << internalField().name()
        << ": no surface temperature balancing the flux after 100 Newton"
        << " iterations (T_c = " << Tc << " K, k delta = " << kappaDelta
        << " W/m2/K)" << nl << exit(FatalError);
    return Tw;
}


void Foam::surfaceHeatLossFvPatchScalarField::updateCoeffs()
{
    if (updated())
    {
        return;
    }

    scalar h, Tair, Tsky;
    values(h, Tair, Tsky);

    const scalar epsSigma =
        emissivity_*constant::physicoChemical::sigma.value();
    const scalar skyTerm = epsSigma*pow4(Tsky);

    const scalarField& kappap = kappa();
    const scalarField& deltaCoeffs = patch().deltaCoeffs();
    const scalarField& Tw = *this;

    scalarField& Tref = refValue();
    scalarField& f = valueFraction();

    forAll(Tw, facei)
    {
        // Linearisation point of the radiative term
        const scalar T0 = max(Tw[facei], scalar(0));

        const scalar hEff = h + 4*epsSigma*pow3(T0);

        if (hEff > 0)
        {
            Tref[facei] = (h*Tair + skyTerm + 3*epsSigma*pow4(T0))/hEff;
            f[facei] = hEff/(hEff + kappap[facei]*deltaCoeffs[facei]);
        }
        else
        {
            // No exchange: zero flux
            Tref[facei] = Tw[facei];
            f[facei] = 0;
        }
    }

    refGrad() = imposedFlux()/kappap;

    mixedFvPatchScalarField::updateCoeffs();
}


void Foam::surfaceHeatLossFvPatchScalarField::write(Ostream& os) const
{
    mixedFvPatchScalarField::write(os);
    h_->writeData(os);
    Tair_->writeData(os);
    if (Tsky_.valid())
    {
        Tsky_->writeData(os);
    }
    if (heatFlux_.valid())
    {
        heatFlux_->writeData(os);
    }
    os.writeEntry("emissivity", emissivity_);
    os.writeEntryIfDifferent<word>("kappa", "kappa", kappaName_);
}


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{
    makePatchTypeField
    (
        fvPatchScalarField,
        surfaceHeatLossFvPatchScalarField
    );
}

// ************************************************************************* //
