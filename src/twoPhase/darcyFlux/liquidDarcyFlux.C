/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "liquidDarcyFlux.H"
#include "harmonicFaceMean.H"
#include "checkedRead.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::liquidDarcyFlux::krlInterpolation>
Foam::liquidDarcyFlux::krlInterpolationNames
({
    { krlInterpolation::upwind, "upwind" },
    { krlInterpolation::arithmetic, "arithmetic" },
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::liquidDarcyFlux::liquidDarcyFlux
(
    const dictionary& dict,
    const vector& g,
    const capillaryPressureModel& pc,
    const relativePermeabilityModel& kr
)
:
    rhol_
    (
        checkedRead::get
        (
            dict, "rhoLiquid", dimDensity, checkedRead::positive()
        ).value()
    ),
    mul_
    (
        checkedRead::get
        (
            dict, "muLiquid", dimPressure*dimTime, checkedRead::positive()
        ).value()
    ),
    g_(g),
    scheme_
    (
        checkedRead::getChoice
        (
            dict, "krlInterpolation", krlInterpolationNames,
            krlInterpolation::upwind
        )
    ),
    pc_(pc),
    kr_(kr)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::liquidDarcyFlux::liquidState Foam::liquidDarcyFlux::state
(
    const scalar pg,
    const scalar S,
    const scalar T,
    const scalar K
) const
{
    return liquidState{pg, pc_.pc(S, T), kr_.krl(S), K};
}


Foam::scalar Foam::liquidDarcyFlux::massFlux
(
    const liquidState& o,
    const liquidState& n,
    const vector& d,
    const scalar magSf,
    const scalar delta,
    const scalar w,
    const scalar snGradCorrection
) const
{
    // The potential difference driving the flow from o to n, with the
    // non-orthogonal correction of its gradient over delta (0: the same
    // value, bit for bit, as without it)
    const scalar dPhi =
        (n.pg - o.pg) - (n.pc - o.pc) - rhol_*(g_ & d)
      + snGradCorrection/delta;
    const scalar Kf = harmonicFaceMean(o.K, n.K, w);
    const scalar krf = faceValue(o.krl, n.krl, dPhi, w);
    return -rhol_*Kf*krf/mul_*magSf*delta*dPhi;
}


// ************************************************************************* //
