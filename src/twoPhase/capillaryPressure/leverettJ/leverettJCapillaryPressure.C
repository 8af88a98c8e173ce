/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "leverettJCapillaryPressure.H"
#include "addToRunTimeSelectionTable.H"
#include "checkedRead.H"

#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace capillaryPressureModels
{
    defineTypeNameAndDebug(leverettJ, 0);
    addToRunTimeSelectionTable
    (
        capillaryPressureModel,
        leverettJ,
        dictionary
    );
}
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::capillaryPressureModels::leverettJ::leverettJ
(
    const dictionary& dict,
    const dictionary& coeffs
)
:
    capillaryPressureModel(dict, coeffs),
    K_
    (
        checkedRead::get
        (
            coeffs, "permeability", dimArea, checkedRead::positive()
        ).value()
    ),
    phi_
    (
        checkedRead::get
        (
            coeffs, "porosity", dimless, validRange{0, 1, true, true}
        ).value()
    ),
    a_({1.417, -2.120, 1.263}),
    sigma_(surfaceTensionLaw::New(coeffs))
{
    if (coeffs.found("J", keyType::LITERAL))
    {
        a_ = checkedRead::getList
        (
            coeffs, "J", validRange{-GREAT, GREAT, false, false},
            "coefficients a_1 .. a_N of J = sum a_i (1 - S_e)^i"
        );
        const label n = 1000;
        bool monotone = (J(0) > 0);
        for (label i = 0; i < n && monotone; ++i)
        {
            monotone = (J(scalar(i + 1)/n) <= J(scalar(i)/n));
        }
        if (a_.empty() || !monotone)
        {
            FatalIOErrorInFunction(coeffs)
                << "Keyword 'J' = " << flatOutput(a_) << " in " << coeffs.name()
                << ": J(S_e) = sum a_i (1 - S_e)^i must be > 0 at S_e = 0"
                << " and non-increasing on S_e in [0, 1]" << nl
                << exit(FatalIOError);
        }
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::capillaryPressureModels::leverettJ::J
(
    const scalar Se
) const
{
    // Horner in x = 1 - S_e, no constant term
    const scalar x = 1 - Se;
    scalar result = 0;
    for (label i = a_.size() - 1; i >= 0; --i)
    {
        result = (result + a_[i])*x;
    }
    return result;
}


Foam::scalar Foam::capillaryPressureModels::leverettJ::dJdSe
(
    const scalar Se
) const
{
    // dJ/dS_e = -sum_i i a_i x^(i-1)
    const scalar x = 1 - Se;
    scalar result = 0;
    for (label i = a_.size() - 1; i >= 0; --i)
    {
        result = result*x + (i + 1)*a_[i];
    }
    return -result;
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

Foam::wordList
Foam::capillaryPressureModels::leverettJ::coeffKeywords() const
{
    wordList keys({"permeability", "porosity", "J"});
    keys.append
    (
        checkedRead::modelKeywords(coeffs_, "surfaceTensionLaw", *sigma_)
    );
    return keys;
}


Foam::scalar Foam::capillaryPressureModels::leverettJ::pcEff
(
    const scalar Se,
    const scalar T
) const
{
    return sigma_->sigma(T)*inversePoreSize()*J(Se);
}


Foam::scalar Foam::capillaryPressureModels::leverettJ::dpcdSeEff
(
    const scalar Se,
    const scalar T
) const
{
    return sigma_->sigma(T)*inversePoreSize()*dJdSe(Se);
}


Foam::scalar Foam::capillaryPressureModels::leverettJ::dpcdTEff
(
    const scalar Se,
    const scalar T
) const
{
    return sigma_->dSigmadT(T)*inversePoreSize()*J(Se);
}

// ************************************************************************* //
