/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "vanGenuchtenMualemRelativePermeability.H"
#include "addToRunTimeSelectionTable.H"
#include "checkedRead.H"

#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace relativePermeabilityModels
{
    defineTypeNameAndDebug(vanGenuchtenMualem, 0);
    addToRunTimeSelectionTable
    (
        relativePermeabilityModel,
        vanGenuchtenMualem,
        dictionary
    );
}
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::relativePermeabilityModels::vanGenuchtenMualem::vanGenuchtenMualem
(
    const dictionary& dict,
    const dictionary& coeffs
)
:
    relativePermeabilityModel(dict, coeffs),
    n_
    (
        checkedRead::get
        (
            coeffs, "n", dimless, validRange{1, GREAT, true, true}
        ).value()
    ),
    m_(1 - 1/n_),
    l_
    (
        checkedRead::getOrDefault
        (
            coeffs, "l", dimless, 0.5, checkedRead::closed(-GREAT, GREAT)
        ).value()
    ),
    lg_
    (
        checkedRead::getOrDefault
        (
            coeffs, "lg", dimless, 1.0/3.0, checkedRead::nonNegative()
        ).value()
    )
{
    // Mualem's closed form (van Genuchten 1980, eq. 8) is Mualem's
    // integral of van Genuchten's retention curve of the same m = 1 - 1/n:
    // with the capillary law vanGenuchten of another n, k_rl is an
    // empirical law fitted on its own, not that integral. Warned, not
    // refused: each law is valid and the run well posed (k_rl monotone in
    // [0, 1]); separately fitted n are a user's choice
    const word pcModel =
        dict.getOrDefault<word>("capillaryPressureModel", word::null);
    if (pcModel == "vanGenuchten" && dict.isDict("vanGenuchtenCoeffs"))
    {
        const dictionary& pcCoeffs = dict.subDict("vanGenuchtenCoeffs");
        if (pcCoeffs.found("n"))
        {
            const scalar nPc =
                checkedRead::get
                (
                    pcCoeffs, "n", dimless, validRange{1, GREAT, true, true}
                ).value();
            if (mag(nPc - n_) > 1e-9*n_)
            {
                IOWarningInFunction(coeffs)
                    << "Keyword 'n' = " << n_ << " of relativePermeability"
                    << "Model vanGenuchtenMualem in " << coeffs.name()
                    << " differs from the capillary law vanGenuchten's n = "
                    << nPc << " in " << pcCoeffs.name() << ": Mualem's"
                    << " closed form holds for the retention curve's own m"
                    << " = 1 - 1/n (van Genuchten 1980, eq. 8)" << endl;
            }
        }
    }
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::relativePermeabilityModels::vanGenuchtenMualem::krlEff
(
    const scalar Se
) const
{
    if (Se <= 0)
    {
        return 0;
    }
    const scalar f = 1 - std::pow(1 - std::pow(Se, 1/m_), m_);
    return std::pow(Se, l_)*f*f;
}


Foam::scalar Foam::relativePermeabilityModels::vanGenuchtenMualem::krgEff
(
    const scalar Se
) const
{
    return std::pow(1 - Se, lg_)*std::pow(1 - std::pow(Se, 1/m_), 2*m_);
}


Foam::scalar
Foam::relativePermeabilityModels::vanGenuchtenMualem::dkrldSeEff
(
    const scalar Se
) const
{
    const scalar x = std::pow(Se, 1/m_);
    if (Se <= 0 || x >= 1)
    {
        return 0;
    }
    const scalar f = 1 - std::pow(1 - x, m_);
    const scalar dfdSe = std::pow(1 - x, m_ - 1)*x/Se;
    return
        l_*std::pow(Se, l_ - 1)*f*f + std::pow(Se, l_)*2*f*dfdSe;
}


Foam::scalar
Foam::relativePermeabilityModels::vanGenuchtenMualem::dkrgdSeEff
(
    const scalar Se
) const
{
    const scalar x = std::pow(Se, 1/m_);
    if (Se <= 0 || x >= 1)
    {
        return 0;
    }
    const scalar g = 1 - x;
    return
       -lg_*std::pow(1 - Se, lg_ - 1)*std::pow(g, 2*m_)
       - 2*std::pow(1 - Se, lg_)*std::pow(g, 2*m_ - 1)*x/Se;
}

// ************************************************************************* //
