/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "kelvinLaplace.H"
#include "checkedRead.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::kelvinLaplace::kelvinLaplace(const dictionary& dict)
:
    sigma_(surfaceTensionLaw::New(dict)),
    pSat_(saturationPressureLaw::New(dict)),
    meniscus_(meniscusCurvatureModel::New(dict)),
    rhoL_
    (
        checkedRead::getOrDefault
        (
            dict, "rhoL", dimDensity, 1000, checkedRead::positive()
        ).value()
    ),
    Mw_
    (
        checkedRead::getOrDefault
        (
            dict, "Mw", dimMass/dimMoles, 0.018, checkedRead::positive()
        ).value()
    ),
    R_
    (
        checkedRead::getOrDefault
        (
            dict, "R", dimEnergy/dimMoles/dimTemperature, 8.31,
            checkedRead::positive()
        ).value()
    )
{}

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::wordList Foam::kelvinLaplace::keywords(const dictionary& dict) const
{
    wordList keys({"rhoL", "Mw", "R"});
    keys.append
    (
        checkedRead::modelKeywords(dict, "surfaceTensionLaw", *sigma_)
    );
    keys.append
    (
        checkedRead::modelKeywords(dict, "saturationPressureLaw", *pSat_)
    );
    keys.append
    (
        checkedRead::modelKeywords(dict, "meniscusModel", *meniscus_)
    );
    return keys;
}


Foam::scalar Foam::kelvinLaplace::lnRelativeHumidity
(
    const scalar alphaL,
    const scalar T
) const
{
    if (alphaL <= 0)
    {
        return -GREAT;
    }
    return Vm()*meniscus_->K(alphaL)*sigma_->sigma(T)/(R_*T);
}


Foam::scalar Foam::kelvinLaplace::relativeHumidity
(
    const scalar alphaL,
    const scalar T
) const
{
    return std::exp(lnRelativeHumidity(alphaL, T));
}


Foam::scalar Foam::kelvinLaplace::pw(const scalar alphaL, const scalar T) const
{
    return relativeHumidity(alphaL, T)*pSat_->pSat(T);
}


Foam::scalar Foam::kelvinLaplace::dLnRelativeHumiditydAlphaL
(
    const scalar alphaL,
    const scalar T
) const
{
    return Vm()*meniscus_->dKdAlphaL(alphaL)*sigma_->sigma(T)/(R_*T);
}


Foam::scalar Foam::kelvinLaplace::dLnRelativeHumiditydT
(
    const scalar alphaL,
    const scalar T
) const
{
    if (alphaL <= 0)
    {
        return 0;
    }
    // d/dT [Vm K sigma(T)/(R T)] = Vm K (sigma' T - sigma)/(R T^2)
    return
        Vm()*meniscus_->K(alphaL)
       *(sigma_->dSigmadT(T)*T - sigma_->sigma(T))/(R_*T*T);
}


Foam::scalar Foam::kelvinLaplace::dpwdAlphaL
(
    const scalar alphaL,
    const scalar T
) const
{
    return pw(alphaL, T)*dLnRelativeHumiditydAlphaL(alphaL, T);
}


Foam::scalar Foam::kelvinLaplace::dpwdT
(
    const scalar alphaL,
    const scalar T
) const
{
    const scalar rh = relativeHumidity(alphaL, T);
    return
        rh*pSat_->dpSatdT(T)
      + rh*pSat_->pSat(T)*dLnRelativeHumiditydT(alphaL, T);
}


Foam::scalar Foam::kelvinLaplace::alphaLFromLn
(
    const scalar lnRH,
    const scalar T
) const
{
    const scalar sigma = sigma_->sigma(T);
    if (sigma <= 0)
    {
        // No meniscus at or above the critical point
        return 0;
    }
    if (lnRH >= 0)
    {
        // Saturated: beyond the pendular range
        return 1;
    }
    return meniscus_->alphaL(lnRH*R_*T/(Vm()*sigma));
}


Foam::scalar Foam::kelvinLaplace::alphaL
(
    const scalar RH,
    const scalar T
) const
{
    if (RH <= 0)
    {
        return 0;
    }
    return alphaLFromLn(std::log(RH), T);
}


Foam::tmp<Foam::scalarField> Foam::kelvinLaplace::relativeHumidity
(
    const scalarField& alphaL,
    const scalarField& T
) const
{
    if (alphaL.size() != T.size())
    {
        FatalErrorInFunction
            << "Sizes of alpha_l (" << alphaL.size() << ") and T ("
            << T.size() << ") differ" << exit(FatalError);
    }
    tmp<scalarField> tresult(new scalarField(T.size()));
    scalarField& result = tresult.ref();
    forAll(T, i)
    {
        result[i] = relativeHumidity(alphaL[i], T[i]);
    }
    return tresult;
}


Foam::tmp<Foam::scalarField> Foam::kelvinLaplace::pw
(
    const scalarField& alphaL,
    const scalarField& T
) const
{
    tmp<scalarField> tresult(relativeHumidity(alphaL, T));
    scalarField& result = tresult.ref();
    forAll(T, i)
    {
        result[i] *= pSat_->pSat(T[i]);
    }
    return tresult;
}


Foam::tmp<Foam::scalarField> Foam::kelvinLaplace::alphaL
(
    const scalarField& relativeHumidity,
    const scalarField& T
) const
{
    if (relativeHumidity.size() != T.size())
    {
        FatalErrorInFunction
            << "Sizes of p_w/p_wsat (" << relativeHumidity.size()
            << ") and T (" << T.size() << ") differ" << exit(FatalError);
    }
    tmp<scalarField> tresult(new scalarField(T.size()));
    scalarField& result = tresult.ref();
    forAll(T, i)
    {
        result[i] = alphaL(relativeHumidity[i], T[i]);
    }
    return tresult;
}

// ************************************************************************* //
