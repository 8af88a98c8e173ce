/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "effectiveSaturation.H"
#include "checkedRead.H"

#include <cmath>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::effectiveSaturation::effectiveSaturation(const dictionary& dict)
:
    Swr_
    (
        checkedRead::getOrDefault
        (
            dict, "Swr", dimless, 0, checkedRead::closedOpen(0, 1)
        ).value()
    ),
    Sgr_
    (
        checkedRead::getOrDefault
        (
            dict, "Sgr", dimless, 0, checkedRead::closedOpen(0, 1)
        ).value()
    )
{
    if (Swr_ + Sgr_ >= 1)
    {
        FatalIOErrorInFunction(dict)
            << "Residual saturations 'Swr' = " << Swr_ << " and 'Sgr' = "
            << Sgr_ << " in " << dict.name() << " are inconsistent:"
            << " Swr + Sgr = " << Swr_ + Sgr_ << " must be in [0, 1)"
            << " (no mobile saturation range left)" << nl
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * //

Foam::scalar Foam::effectiveSaturation::checkedSaturation
(
    const dictionary& dict,
    const word& keyword
)
{
    return
        checkedRead::get
        (
            dict, keyword, dimless, checkedRead::closed(0, 1)
        ).value();
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::effectiveSaturation::checkS(const scalar S, const string& who) const
{
    // (NaN first: an ordered comparison with it would trap)
    if (std::isnan(S) || S < 0 || S > 1)
    {
        FatalErrorInFunction
            << who.c_str() << " evaluated at the liquid saturation S = " << S
            << ", outside its valid range [0, 1]" << nl
            << exit(FatalError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::effectiveSaturation::Se
(
    const scalar S,
    const string& who
) const
{
    checkS(S, who);
    const scalar se = (S - Swr_)/(1 - Swr_ - Sgr_);
    return se < 0 ? scalar(0) : (se > 1 ? scalar(1) : se);
}


Foam::scalar Foam::effectiveSaturation::dSedS
(
    const scalar S,
    const string& who
) const
{
    checkS(S, who);
    return (S <= Swr_ || S >= 1 - Sgr_) ? scalar(0) : 1/(1 - Swr_ - Sgr_);
}

// ************************************************************************* //
