/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "capillaryPressureModel.H"
#include "checkedRead.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(capillaryPressureModel, 0);
    defineRunTimeSelectionTable(capillaryPressureModel, dictionary);
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::capillaryPressureModel::capillaryPressureModel
(
    const dictionary& dict,
    const dictionary& coeffs
)
:
    coeffs_(coeffs),
    saturation_(dict),
    SeLinear_
    (
        dict.found("pcLinearBelowSe")
      ? checkedRead::get
        (
            dict, "pcLinearBelowSe", dimless,
            validRange{0, 0.5, true, false}
        ).value()
      : scalar(0)
    )
{}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::capillaryPressureModel::checkedSe(const scalar S) const
{
    const string who("capillaryPressureModel " + type());
    const scalar Se = saturation_.Se(S, who);
    if (Se <= 0 && !boundedAtResidual() && SeLinear_ <= 0)
    {
        FatalErrorInFunction
            << who.c_str() << " evaluated at S = " << S << " <= Swr = "
            << saturation_.Swr() << " (S_e = 0), where its capillary"
            << " pressure is unbounded: valid range of S is (Swr, 1] = ("
            << saturation_.Swr() << ", 1]" << nl
            << exit(FatalError);
    }
    if (!finiteEff(linear(Se) ? SeLinear_ : Se))
    {
        FatalIOErrorInFunction(coeffs_)
            << who.c_str() << " (coefficients in " << coeffs_.name()
            << ") evaluated at S = " << S << " (S_e = " << Se << "): its"
            << " capillary pressure or its derivative exceeds 1e300 Pa,"
            << " beyond the floating-point range (and p_l's [-1e9, 1e8] Pa"
            << " by far)" << nl
            << "    Valid: coefficients whose p_c stays finite over the"
            << " saturations of the run (van Genuchten: n not so close to"
            << " 1), or pcLinearBelowSe above this S_e" << nl
            << exit(FatalIOError);
    }
    return Se;
}


bool Foam::capillaryPressureModel::finite(const scalar S) const
{
    const scalar Se = saturation_.Se(S, "capillaryPressureModel " + type());
    if (Se <= 0 && !finiteAtResidual())
    {
        return false;
    }
    return finiteEff(linear(Se) ? SeLinear_ : Se);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::capillaryPressureModel::pc
(
    const scalar S,
    const scalar T
) const
{
    const scalar Se = checkedSe(S);
    if (linear(Se))
    {
        const scalar Sr = SeLinear_;
        return pcEff(Sr, T) + dpcdSeEff(Sr, T)*(Se - Sr);
    }
    return pcEff(Se, T);
}


Foam::scalar Foam::capillaryPressureModel::dpcdS
(
    const scalar S,
    const scalar T
) const
{
    const scalar Se = checkedSe(S);
    const scalar dSedS = saturation_.dSedS(S, "capillaryPressureModel " + type());
    if (dSedS <= 0)
    {
        return 0;
    }
    return dpcdSeEff(linear(Se) ? SeLinear_ : Se, T)*dSedS;
}


Foam::scalar Foam::capillaryPressureModel::dpcdT
(
    const scalar S,
    const scalar T
) const
{
    const scalar Se = checkedSe(S);
    if (linear(Se))
    {
        // d/dT of the tangent at S_r, for p_c = s(T) f(S_e)
        const scalar Sr = SeLinear_;
        const scalar pcr = pcEff(Sr, T);
        const scalar dpcdTr = dpcdTEff(Sr, T);
        const scalar d2pc =
            mag(pcr) > VSMALL ? dpcdSeEff(Sr, T)*dpcdTr/pcr : scalar(0);
        return dpcdTr + d2pc*(Se - Sr);
    }
    return dpcdTEff(Se, T);
}



Foam::scalar Foam::capillaryPressureModel::saturation
(
    const scalar pcValue,
    const scalar T
) const
{
    const scalar Swr = saturation_.Swr();
    scalar hi = 1 - saturation_.Sgr();
    if (pcValue <= pc(hi, T))
    {
        return 1;
    }
    scalar lo = Swr;
    if (finiteAtResidual() && pcValue >= pc(lo, T))
    {
        return lo;
    }
    // p_c(lo) > pcValue > p_c(hi); lo itself never evaluated (unbounded
    // laws end there)
    for (label iter = 0; iter < 200 && hi - lo > 4*SMALL*hi; ++iter)
    {
        const scalar mid = 0.5*(lo + hi);
        if (mid <= lo || mid >= hi)
        {
            break;
        }
        (pc(mid, T) > pcValue ? lo : hi) = mid;
    }
    return 0.5*(lo + hi);
}


// ************************************************************************* //
