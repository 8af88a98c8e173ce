/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "pendularMedium.H"
#include "propertyField.H"
#include "checkedRead.H"
#include "startupReport.H"
#include "waterModel.H"
#include "liquidFlow.H"
#include "capillaryPressureModel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(pendularMedium, 0);
}

const Foam::scalar Foam::pendularMedium::alphaLDry = 1e-100;
const Foam::scalar Foam::pendularMedium::criticalMargin = 10;
const Foam::scalar Foam::pendularMedium::alphaLCritical = 1e-9;
const Foam::scalar Foam::pendularMedium::nearRootTol = 1e-6;

const Foam::Enum<Foam::pendularMedium::vapourPressureLaw>
Foam::pendularMedium::vapourPressureLawNames
({
    { vapourPressureLaw::meniscus, "meniscus" },
    { vapourPressureLaw::kelvin, "kelvin" },
});

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

const Foam::dictionary& Foam::pendularMedium::kelvinDictionary()
{
    if (!alias())
    {
        kelvinDict_.set("rhoL", liquid().rho());
    }
    return kelvinDict_;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::pendularMedium::pendularMedium(const fvMesh& mesh)
:
    soilProperties(mesh, soilProperties::layout::pendularAlias),
    mesh_(mesh),
    closures_(closures("pendular")),
    rhoSolid_(solid().rho()),
    CpSolid_(solid().Cp()),
    kappaSolid_(solid().kappa()),
    CpLiquid_(liquid().Cp()),
    kappaLiquid_(liquid().kappa()),
    kappaGas_(gas().kappa()),
    kelvinDict_(closures_),
    kelvin_(kelvinDictionary()),
    permeability_(gasPermeabilityModel::New(closures_)),
    vapourDiffusion_(vapourDiffusionModel::New(closures_)),
    minimumTemperature_
    (
        max
        (
            kelvin_.saturationPressure().Tmin(),
            kelvin_.surfaceTension().Tmin()
        )
    ),
    dryOutTemperature_
    (
        min
        (
            kelvin_.saturationPressure().Tmax(),
            kelvin_.surfaceTension().Tmax()
        )
    ),
    pSatDryOut_(kelvin_.saturationPressure().pSat(dryOutTemperature_)),
    vapourPressure_(vapourPressureLaw::meniscus),
    kelvinPc_(nullptr),
    saturatedZone_(false),
    henryHcp_(0),
    henryVantHoff_(0),
    henryT0_(298.15),
    storage_(0)
{
    // The split of the water into liquid and vapour (waterModel,
    // run-time selected; default equilibrium)
    water_ = waterModel::New(*this, closures_);

    // The saturated zone lives in liquidFlow (before the unknown
    // keywords: say where it belongs)
    if (closures_.found("saturatedZone"))
    {
        FatalIOErrorInFunction(closures_)
            << "saturatedZone in " << closures_.name() << ": it belongs in"
            << " the sub-dictionary liquidFlow (a saturated zone needs the"
            << " liquid's flow: without it a saturated cell cannot change)"
            << exit(FatalIOError);
    }

    // Unknown keywords: a misspelt one would silently take its default
    {
        wordList allowed
        ({
            "CpAir", "Ma", "CpVapour",
            "latentHeat", "latentHeatTemperature", "vapourDiffusivity",
            "gasViscosity", "liquidFlow", "vapourDiffusionModel"
        });
        // The diffusion factor's coefficients (tortuosity of constant)
        allowed.append(vapourDiffusion_->coeffKeywords());
        allowed.append
        (
            checkedRead::modelKeywords(closures_, "waterModel", water_())
        );
        for (const word& key : kelvin_.keywords(closures_))
        {
            // soilProperties: the liquid density is liquid { rho; }
            if (alias() || key != "rhoL")
            {
                allowed.append(key);
            }
        }
        allowed.append
        (
            checkedRead::modelKeywords
            (
                closures_, "gasPermeabilityModel", permeability_()
            )
        );
        if (alias())
        {
            allowed.append
            (
                wordList
                ({
                    "porosity", "rhoSolid", "CpSolid", "kappaSolid",
                    "CpLiquid", "kappaLiquid", "kappaGas"
                })
            );
            allowed.append
            (
                checkedRead::modelKeywords
                (
                    *this, "conductivityModel", conductivityModel()
                )
            );
        }
        checkedRead::checkKeywords(closures_, allowed);
    }

    const auto positive = checkedRead::positive();
    const dimensionSet dimCp(dimEnergy/dimMass/dimTemperature);
    const auto read =
        [&](const word& key, const dimensionSet& dims, scalar deflt)
        {
            return checkedRead::getOrDefault
            (
                closures_, key, dims, deflt, positive
            ).value();
        };

    CpAir_ = read("CpAir", dimCp, 1005);
    Ma_ = read("Ma", dimMass/dimMoles, 0.029);
    CpVapour_ = read("CpVapour", dimCp, 1890);
    latentHeat_ = read("latentHeat", dimEnergy/dimMass, 2.2e6);
    latentHeatTemperature_ =
        read("latentHeatTemperature", dimTemperature, 373.15);
    vapourDiffusivity_ = read("vapourDiffusivity", dimViscosity, 2e-5);
    gasViscosity_ = read("gasViscosity", dimDynamicViscosity, 1.22e-5);


    // The capillary flow of the liquid (optional): its closures and patch
    // conditions (liquidFlow), the liquid's density that of the soil,
    // fixed saturations within the pendular range, gravity constant/g
    if (closures_.found("liquidFlow"))
    {
        if (!closures_.isDict("liquidFlow"))
        {
            FatalIOErrorInFunction(closures_)
                << "liquidFlow in " << closures_.name() << " must be a"
                << " sub-dictionary (capillaryPressureModel,"
                << " relativePermeabilityModel, permeability, muLiquid, ...)"
                << exit(FatalIOError);
        }
        const dictionary& userDict = closures_.subDict("liquidFlow");
        if (userDict.found("rhoLiquid"))
        {
            FatalIOErrorInFunction(userDict)
                << "rhoLiquid in " << userDict.name() << ": the liquid's"
                << " density is the soil's (" << rhoL() << " kg/m3), not"
                << " set here" << exit(FatalIOError);
        }
        dictionary dict(userDict);
        dict.add("rhoLiquid", rhoL());
        liquidFlow_.reset
        (
            new liquidFlow
            (
                mesh, dict, liquidFlow::readGravity(mesh), false,
                pendularLimit()
            )
        );
        wordList allowed({"vapourPressure", "saturatedZone"});
        for (const word& key : liquidFlow_->keywords(dict))
        {
            if (key != "rhoLiquid")
            {
                allowed.append(key);
            }
        }
        checkedRead::checkKeywords(userDict, allowed);

        // The vapour over the liquid: the menisci's law (default) or
        // Kelvin's with the capillary pressure of the liquid
        vapourPressure_ =
            checkedRead::getChoice
            (
                userDict, "vapourPressure", vapourPressureLawNames,
                vapourPressureLaw::meniscus
            );
        if (vapourPressure_ == vapourPressureLaw::kelvin)
        {
            const capillaryPressureModel& pc =
                liquidFlow_->capillaryPressure();
            if (!pc.finiteAtResidual())
            {
                FatalIOErrorInFunction(userDict)
                    << "vapourPressure kelvin in " << userDict.name()
                    << ": capillaryPressureModel " << pc.type() << " has"
                    << " an unbounded p_c at S = Swr, where Kelvin's"
                    << " vapour pressure would vanish while the cell"
                    << " still holds liquid: give pcLinearBelowSe (in (0,"
                    << " 0.5]), or use a law bounded there (leverettJ,"
                    << " pendular), or vapourPressure meniscus"
                    << exit(FatalIOError);
            }
            kelvinPc_ = &pc;
        }

        // The saturated zone: Henry's dissolved air and the storage of a
        // cell without gas (see Description)
        if (userDict.found("saturatedZone"))
        {
            readSaturatedZone(userDict);
        }
    }

    // (phi = 0 leaves no pores: the cell field 0/porosity if given, else
    // the keyword of the soil's file, constant/soilProperties or its alias)
    if (isFile(porosity().objectPath()))
    {
        checkedRead::check
        (
            porosity().objectPath(), "porosity", porosity(),
            checkedRead::closedOpen(SMALL, 1)
        );
    }
    else
    {
        checkedRead::check
        (
            *this, "porosity", readPorosity().value(),
            checkedRead::closedOpen(SMALL, 1)
        );
    }

    Info<< "Pendular medium: porosity " << gMin(porosity().primitiveField())
        << " to " << gMax(porosity().primitiveField())
        << ", (rho C)_s " << rhoSolid_*CpSolid_ << " J/(m3 K)"
        << ", L " << latentHeat_ << " J/kg at " << latentHeatTemperature_
        << " K, vapour diffusion " << vapourDiffusion_->type()
        << " (xi D_wa dry "
        << vapourDiffusivity(0, gMin(porosity().primitiveField())) << " m2/s)"
        << ", pendular range alpha_l < " << pendularLimit() << nl
        << "    saturation laws from " << minimumTemperature_ << " K;"
        << " liquid-free (all water vapour) at and above "
        << dryOutTemperature_ << " K (critical point of the laws)" << endl;
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::pendularMedium::~pendularMedium()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::pendularMedium::nonEquilibrium() const
{
    return water_->relaxes();
}


const Foam::waterModel& Foam::pendularMedium::water() const
{
    return *water_;
}


Foam::pendularMedium::saturationState
Foam::pendularMedium::lawState
(
    const scalar T,
    const bool slopes
) const
{
    const saturationPressureLaw& pSatLaw = kelvin_.saturationPressure();
    const surfaceTensionLaw& sigmaLaw = kelvin_.surfaceTension();
    const scalar pSat = pSatLaw.pSat(T);
    const scalar sigma = sigmaLaw.sigma(T);
    const scalar VmByR = kelvin_.Vm()/R();
    if (!slopes)
    {
        return {T, pSat, VmByR*sigma/T, 0, 0, false};
    }
    return
    {
        T,
        pSat,
        VmByR*sigma/T,
        pSatLaw.dpSatdT(T)/pSat,
        // d/dT [Vm sigma/(R T)] = Vm (sigma' T - sigma)/(R T^2)
        VmByR*(sigmaLaw.dSigmadT(T)*T - sigma)/sqr(T),
        false
    };
}


Foam::pendularMedium::saturationState
Foam::pendularMedium::saturation(const scalar T, const bool slopes) const
{
    if (std::isnan(T) || T < minimumTemperature_)
    {
        // Out of the laws' range (an iterate the solver rejects; NaN
        // included): the laws at their lowest temperature, without slopes
        saturationState sat = lawState(minimumTemperature_, false);
        sat.T = T;
        return sat;
    }
    if (T >= dryOutTemperature_)
    {
        // No liquid at or above the critical point: superheated vapour and
        // air; p_wsat held at its value at T_d for relative humidities
        return {T, pSatDryOut_, 0, 0, 0, true};
    }
    return lawState(T, slopes);
}


Foam::pendularMedium::saturationState
Foam::pendularMedium::saturationValues(const scalar T) const
{
    return saturation(T, false);
}


Foam::scalar Foam::pendularMedium::kinkWater
(
    const scalar phi,
    const scalar T
) const
{
    // 0 outside the laws' range (NaN included) and at or above T_d
    if (!(T >= minimumTemperature_ && T < dryOutTemperature_))
    {
        return 0;
    }
    // p_wsat(T) alone (saturation(T)'s, without the other laws: the Newton
    // engine asks for it per cell and iteration)
    return phi*Mw()*kelvin_.saturationPressure().pSat(T)/(R()*T);
}


Foam::scalar Foam::pendularMedium::saturationPressure(const scalar T) const
{
    if (std::isnan(T) || T < minimumTemperature_)
    {
        return kelvin_.saturationPressure().pSat(minimumTemperature_);
    }
    if (T >= dryOutTemperature_)
    {
        return pSatDryOut_;
    }
    return kelvin_.saturationPressure().pSat(T);
}


Foam::scalar Foam::pendularMedium::vapourDensity
(
    const scalar W,
    const scalar alphaL,
    const saturationState& sat,
    const scalar porosity
) const
{
    if (alphaL > 0)
    {
        return vapourDensity(alphaL, sat);
    }
    return max(W, scalar(0))/porosity;
}


bool Foam::pendularMedium::liquidNearCritical
(
    const scalar W,
    const scalar alphaL,
    const saturationState& sat,
    const scalar porosity
) const
{
    if (sat.liquidFree)
    {
        // More water than the saturated vapour at T_d holds: liquid just
        // below T_d
        return
            W/porosity
          > Mw()*pSatDryOut_/(R()*dryOutTemperature_);
    }
    return
        sat.T > dryOutTemperature_ - criticalMargin
     && alphaL > alphaLCritical;
}


void Foam::pendularMedium::checkInitialCapillaryPressure
(
    const volScalarField& T,
    const volScalarField& p,
    const volScalarField& alphaL,
    const label celli
) const
{
    const capillaryPressureModel& law = liquidFlow_->capillaryPressure();
    const dictionary& lfDict = closures_.subDict("liquidFlow");
    const scalar a = alphaL[celli];
    dictionary fieldDict;
    fieldDict.name() = alphaL.objectPath();
    const word who("capillaryPressureModel " + law.type());

    // At or below S_wr a law unbounded there has no p_c (checkedSe's
    // FatalError at the first step, naming no file, before)
    if (a <= law.saturation().Swr() && !law.finiteAtResidual())
    {
        FatalIOErrorInFunction(fieldDict)
            << "Field '" << alphaL.name() << "' (keyword 'internalField') = "
            << a << " in cell " << celli << " is at or below the residual"
            << " saturation Swr = " << law.saturation().Swr() << " of "
            << who.c_str() << " in " << lfDict.name() << ", whose capillary"
            << " pressure is unbounded there, in file "
            << alphaL.objectPath() << nl
            << "    Valid: alphaL in (Swr, 1] where it is not 0, or"
            << " pcLinearBelowSe (in (0, 0.5]) in " << lfDict.name()
            << ", or a law bounded at Swr (leverettJ, pendular)"
            << exit(FatalIOError);
    }
    // p_c beyond the floating-point range (van Genuchten's n near 1)
    if (!law.finite(a))
    {
        FatalIOErrorInFunction(fieldDict)
            << "Field '" << alphaL.name() << "' (keyword 'internalField') = "
            << a << " in cell " << celli << ": the capillary pressure of "
            << who.c_str() << " (" << lfDict.name() << ") there exceeds"
            << " 1e300 Pa, beyond the floating-point range, in file "
            << alphaL.objectPath() << nl
            << "    Valid: p_l = p_g - p_c(alphaL) in p_l's range ["
            << Foam::name(liquidFlow::plMin()) << ", 1e+08] Pa: check the"
            << " law's coefficients (van Genuchten: n not so close to 1)"
            << exit(FatalIOError);
    }
    // p_l = p_g - p_c in p_l's range (the law at T held in its range, as
    // in the steps)
    const scalar Tc =
        min(max(T[celli], minimumTemperature_), dryOutTemperature_);
    const scalar pc = law.pc(a, Tc);
    if (!(p[celli] - pc >= liquidFlow::plMin()))
    {
        FatalIOErrorInFunction(fieldDict)
            << "Field '" << alphaL.name() << "' (keyword 'internalField') = "
            << a << " in cell " << celli << ": the capillary pressure of "
            << who.c_str() << " (" << lfDict.name() << ") there, p_c = "
            << pc << " Pa, gives p_l = p_g - p_c = " << p[celli] - pc
            << " Pa, in file " << alphaL.objectPath() << nl
            << "    Valid: p_l in p_l's range ["
            << Foam::name(liquidFlow::plMin()) << ", 1e+08] Pa (the Kelvin"
            << " limit of an oven-dry soil): a wetter start, or the law's"
            << " coefficients (van Genuchten: n not so close to 1)"
            << exit(FatalIOError);
    }
}


void Foam::pendularMedium::checkInitialState
(
    const volScalarField& T,
    const volScalarField& p,
    const volScalarField& alphaL
) const
{
    // Gas pressure p_g > 0: in the cells and where a patch fixes it
    checkedRead::check
    (
        p.objectPath(), p.name(), p.primitiveField(), checkedRead::positive()
    );
    forAll(p.boundaryField(), patchi)
    {
        const fvPatchScalarField& pp = p.boundaryField()[patchi];
        if (!pp.fixesValue())
        {
            continue;
        }
        forAll(pp, facei)
        {
            if (!(pp[facei] > 0))
            {
                dictionary fieldDict;
                fieldDict.name() = p.objectPath();
                FatalIOErrorInFunction(fieldDict)
                    << "Field '" << p.name() << "', patch "
                    << pp.patch().name() << " (keyword 'value') = "
                    << pp[facei] << " Pa on face " << facei
                    << " is outside its valid range (0, inf): the gas"
                    << " pressure p_g must be positive, in file "
                    << p.objectPath() << nl << exit(FatalIOError);
            }
        }
    }

    // The laws' range from below (T <= 0 is checked by the solver)
    forAll(T, celli)
    {
        if (T[celli] > 0 && T[celli] < minimumTemperature_)
        {
            dictionary fieldDict;
            fieldDict.name() = T.objectPath();
            FatalIOErrorInFunction(fieldDict)
                << "Field '" << T.name() << "' (keyword 'internalField') = "
                << T[celli] << " K in cell " << celli << " is outside the"
                << " valid range [" << minimumTemperature_ << ", inf) of"
                << " the saturation laws (supercooled water to -25 C; ice"
                << " is not modelled), in file " << T.objectPath() << nl
                << exit(FatalIOError);
        }
    }

    // The liquid's fixedPressure faces not over-pressured at the start
    if (liquidFlow_.valid())
    {
        liquidFlow_->checkStart(p);
    }

    // The liquid: none near (or above) the critical point, and a vapour
    // pressure of the menisci that leaves air (p_w <= p_g)
    forAll(alphaL, celli)
    {
        const scalar a = alphaL[celli];
        if (a <= 0 || !(T[celli] > 0))
        {
            continue;
        }
        dictionary fieldDict;
        fieldDict.name() = alphaL.objectPath();
        // The guard's threshold (liquidNearCritical): a state the solver
        // wrote, its last liquid evaporated to round-off, restarts
        if
        (
            T[celli] > dryOutTemperature_ - criticalMargin
         && a > alphaLCritical
        )
        {
            FatalIOErrorInFunction(fieldDict)
                << "Field '" << alphaL.name() << "' (keyword"
                << " 'internalField') = " << a << " in cell " << celli
                << " at T = " << T[celli] << " K: liquid water within "
                << criticalMargin << " K of the critical point ("
                << dryOutTemperature_ << " K), in file "
                << alphaL.objectPath() << nl
                << "    Valid: alphaL <= " << alphaLCritical << " above "
                << dryOutTemperature_ - criticalMargin
                << " K (the liquid vanishes at the critical point)"
                << exit(FatalIOError);
        }
        if (liquidFlow_.valid())
        {
            checkInitialCapillaryPressure(T, p, alphaL, celli);
        }
        const saturationState sat = saturation(T[celli]);
        const scalar pw = vapourDensity(a, sat)*R()*T[celli]/Mw();
        if (pw > p[celli])
        {
            FatalIOErrorInFunction(fieldDict)
                << "Field '" << alphaL.name() << "' (keyword"
                << " 'internalField') = " << a << " in cell " << celli
                << " at T = " << T[celli] << " K: the vapour pressure of the"
                << " menisci p_w = " << pw << " Pa exceeds the gas pressure"
                << " p = " << p[celli] << " Pa of " << p.objectPath()
                << " (negative air pressure), in file "
                << alphaL.objectPath() << nl
                << "    Valid: p_w(alphaL, T) <= p (wetter soil holds its"
                << " water at p_w close to p_wsat(T) = " << sat.pSat
                << " Pa: raise p, or start cooler)"
                << exit(FatalIOError);
        }
    }
}


void Foam::pendularMedium::report
(
    const volScalarField& T,
    const volScalarField& p,
    const volScalarField& alphaL
) const
{
    const label n = mesh_.nCells();
    const scalarField& phi = porosity().primitiveField();
    const scalarField& alpha0 = alphaL.primitiveField();
    const scalar TL = latentHeatTemperature_;

    // The initial state as pendularFoam derives it (updateState.H):
    // W from alpha_l and T, the vapour in equilibrium, p_a = p_g - p_w
    scalarField theta0(n), W0(n), w0(n), rhoCpDry(n), rhoCpWet(n), Lw(n);
    scalarField kDry(n), kWet(n), kSat(n);
    bool dryDefined = true, wetDefined = true, satDefined = true;
    const effectiveConductivityModel& law = conductivityModel();
    forAll(W0, celli)
    {
        const scalar Tc = T[celli];
        const scalar ph = phi[celli];
        const scalar a = alpha0[celli];
        const saturationState sat = saturation(Tc);
        const scalar W = waterContent(a, sat, ph);
        const scalar rhoW = vapourDensity(W, a, sat, ph);
        const scalar pa = p[celli] - rhoW*R()*Tc/Mw();

        theta0[celli] = ph*a;
        W0[celli] = W;
        w0[celli] = W/((1 - ph)*rhoSolid_);

        // Dried: no water, the pores full of air at p_g
        rhoCpDry[celli] = sensibleCapacity(Tc, 0, 0, 0, p[celli], ph);
        rhoCpWet[celli] = sensibleCapacity(Tc, W, a, rhoW, pa, ph);

        // Energy to evaporate the liquid at T_L: E(all the water vapour)
        // - E(initial state), both at T_L
        Lw[celli] =
            energy(TL, W, 0, W/ph, pa, ph) - energy(TL, W, a, rhoW, pa, ph);

        dryDefined = dryDefined && law.definedAt(0);
        wetDefined = wetDefined && law.definedAt(a);
        satDefined = satDefined && law.definedAt(1);
        kDry[celli] = dryDefined ? kappa(0, ph) : 0;
        kWet[celli] = wetDefined ? kappa(a, ph) : 0;
        kSat[celli] = satDefined ? kappa(1, ph) : 0;
    }

    startupReport table("pendularFoam");
    table.add("T_0", T.primitiveField(), "K", "initial temperature");
    table.add("p_0", p.primitiveField(), "Pa", "initial gas pressure p_g");
    table.add("phi", phi, "-", "porosity");
    table.add
    (
        "alpha_l_0", alpha0, "-", "initial liquid fraction of the pores"
    );
    table.add
    (
        "theta_0", theta0, "-",
        "initial liquid water, volume fraction of the soil: phi alpha_l_0"
    );
    table.add
    (
        "W_0", W0, "kg/m3",
        "initial water (liquid and vapour) per volume of soil"
    );
    table.add
    (
        "w_0", w0, "kg/kg",
        "initial water, mass per mass of dry solid: W_0/((1 - phi) rho_s)"
    );
    table.add
    (
        "rhoCp_dry", rhoCpDry, "J/m3/K",
        "(rho C) of the dried soil (pores full of air at p_g) at T_0"
    );
    table.add
    (
        "rhoCp_wet", rhoCpWet, "J/m3/K",
        "(rho C) of the initial state at fixed water, latent heat excluded"
    );
    table.addConductivities
    (
        kDry, dryDefined, kWet, wetDefined, kSat, satDefined,
        rhoCpDry, rhoCpWet
    );
    table.add
    (
        "L_water", Lw, "J/m3",
        "latent heat of the initial liquid per volume of soil, at T_L = "
      + Foam::name(TL) + " K"
    );
    table.add
    (
        "alpha_l_max", pendularLimit(), "-",
        "validity: pendular range alpha_l <= alphaLMax of the meniscus"
        " model (cells above it are counted at each write)"
    );
    table.add
    (
        "T_min", minimumTemperature_, "K",
        "validity: lowest T of the saturation laws (initial T below it:"
        " error; later: step rejected)"
    );
    table.add
    (
        "T_liquid_max", dryOutTemperature_ - criticalMargin, "K",
        "validity: no liquid (alpha_l > " + Foam::name(alphaLCritical)
      + ") above it (T_d - " + Foam::name(criticalMargin) + " K)"
    );
    table.add
    (
        "T_d", dryOutTemperature_, "K",
        "dry-out temperature of the laws: liquid-free at and above it"
    );

    boolList wet(n, false);
    forAll(wet, celli)
    {
        wet[celli] = alpha0[celli] > pendularLimit();
    }
    table.warn
    (
        wet,
        "initial state outside the validity range: alpha_l up to "
      + Foam::name(gMax(alpha0)) + " above the pendular range alpha_l <= "
      + Foam::name(pendularLimit()) + " of the meniscus model"
    );

    table.write(Info);
}


void Foam::pendularMedium::readSaturatedZone(const dictionary& liquidDict)
{
    if (!liquidDict.isDict("saturatedZone"))
    {
        FatalIOErrorInFunction(liquidDict)
            << "saturatedZone in " << liquidDict.name() << " must be a"
            << " sub-dictionary { henry { Hcp <mol/(m3 Pa)>; vantHoff <K>;"
            << " T0 <K>; } storage <1/Pa>; }" << exit(FatalIOError);
    }
    const dictionary& dict = liquidDict.subDict("saturatedZone");
    checkedRead::checkKeywords(dict, wordList({"henry", "storage"}));
    if (vapourPressure_ != vapourPressureLaw::kelvin)
    {
        FatalIOErrorInFunction(dict)
            << "saturatedZone in " << dict.name() << " needs vapourPressure"
            << " kelvin in " << liquidDict.name() << " (valid: kelvin):"
            << " the menisci's law ends at alphaLMax "
            << pendularLimit() << ", short of S = 1 where the gas"
            << " vanishes" << exit(FatalIOError);
    }
    const scalar pc1Low = kelvinPc_->pc(1, minimumTemperature_);
    const scalar pc1High = kelvinPc_->pc(1, dryOutTemperature_);
    if (!std::isfinite(pc1Low) || !std::isfinite(pc1High))
    {
        FatalIOErrorInFunction(dict)
            << "saturatedZone in " << dict.name() << ": capillaryPressure"
            << "Model " << kelvinPc_->type() << " has an unbounded p_c at"
            << " S = 1 (the bubble point of a saturated cell); valid: a"
            << " law finite at S = 1 (vanGenuchten, brooksCorey, leverettJ)"
            << exit(FatalIOError);
    }
    storage_ =
        checkedRead::getOrDefault
        (
            dict, "storage", dimless/dimPressure, 4.5e-10,
            checkedRead::positive()
        ).value();
    dictionary henryDict;
    if (dict.found("henry"))
    {
        if (!dict.isDict("henry"))
        {
            FatalIOErrorInFunction(dict)
                << "henry in " << dict.name() << " must be a sub-dictionary"
                << " { Hcp <mol/(m3 Pa)>; vantHoff <K>; T0 <K>; }"
                << exit(FatalIOError);
        }
        henryDict = dict.subDict("henry");
        checkedRead::checkKeywords
        (
            henryDict, wordList({"Hcp", "vantHoff", "T0"})
        );
    }
    henryHcp_ =
        checkedRead::getOrDefault
        (
            henryDict, "Hcp", dimMoles/dimVolume/dimPressure, 7.8e-6,
            checkedRead::positive()
        ).value();
    henryVantHoff_ =
        checkedRead::getOrDefault
        (
            henryDict, "vantHoff", dimTemperature, 1350,
            checkedRead::closed(-1e4, 1e4)
        ).value();
    henryT0_ =
        checkedRead::getOrDefault
        (
            henryDict, "T0", dimTemperature, 298.15,
            checkedRead::closed(200, 700)
        ).value();
    saturatedZone_ = true;
    // Its cells can turn liquid-only: a fixedPressure face above p_g too
    liquidFlow_->allowPonding();
    Info<< "Saturated zone: Henry's law of the air, H^cp " << henryHcp_
        << " mol/(m3 Pa) at " << henryT0_ << " K, van 't Hoff "
        << henryVantHoff_ << " K; storage c_s " << storage_ << " 1/Pa"
        << endl;
}


Foam::scalar Foam::pendularMedium::henry(const scalar T) const
{
    const scalar Tc =
        min(max(T, minimumTemperature_), dryOutTemperature_);
    return henryHcp_*std::exp(henryVantHoff_*(1/Tc - 1/henryT0_));
}


Foam::scalar Foam::pendularMedium::dissolvedAir
(
    const scalar pa,
    const scalar T
) const
{
    return saturatedZone_ ? Ma_*henry(T)*pa/rhoL() : 0;
}


Foam::scalar Foam::pendularMedium::airPressure
(
    const scalar X,
    const scalar T
) const
{
    return X*rhoL()/(Ma_*henry(T));
}


Foam::scalar Foam::pendularMedium::pcSaturated(const scalar T) const
{
    return
        liquidFlow_->capillaryPressure().pc
        (
            1, min(max(T, minimumTemperature_), dryOutTemperature_)
        );
}


Foam::scalar Foam::pendularMedium::saturatedVapourPressure
(
    const scalar T
) const
{
    const saturationState sat(saturationValues(T));
    return sat.pSat*std::exp(lnRelativeHumidity(1, sat));
}


Foam::scalar Foam::pendularMedium::lnRelativeHumidity
(
    const scalar alphaL,
    const saturationState& sat
) const
{
    if (!kelvinPc_)
    {
        return sat.kelvinLength*kelvin_.meniscus().K(alphaL);
    }
    // Kelvin's law with the liquid's p_c, at T within the laws' range (as
    // kelvinLength, computed at minimumTemperature below it)
    const scalar T =
        min(max(sat.T, minimumTemperature_), dryOutTemperature_);
    return
       -kelvinPc_->pc(min(alphaL, scalar(1)), T)*kelvin_.Vm()/(R()*T);
}


Foam::scalar Foam::pendularMedium::dLnRelativeHumiditydAlphaL
(
    const scalar alphaL,
    const saturationState& sat
) const
{
    if (!kelvinPc_)
    {
        return sat.kelvinLength*kelvin_.meniscus().dKdAlphaL(alphaL);
    }
    if (alphaL >= 1)
    {
        return 0;
    }
    const scalar T =
        min(max(sat.T, minimumTemperature_), dryOutTemperature_);
    return -kelvinPc_->dpcdS(alphaL, T)*kelvin_.Vm()/(R()*T);
}


Foam::scalar Foam::pendularMedium::vapourSlope
(
    const scalar rho,
    const scalar alphaL,
    const saturationState& sat
) const
{
    // meniscus: the products in the order of the law before the choice
    // (bit for bit the same states)
    if (!kelvinPc_)
    {
        return rho*sat.kelvinLength*kelvin_.meniscus().dKdAlphaL(alphaL);
    }
    return rho*dLnRelativeHumiditydAlphaL(alphaL, sat);
}


Foam::scalar Foam::pendularMedium::dLnRelativeHumiditydT
(
    const scalar alphaL,
    const saturationState& sat
) const
{
    if (!kelvinPc_)
    {
        return sat.dKelvinLengthdT*kelvin_.meniscus().K(alphaL);
    }
    // Below the laws' range (NaN included) the law at minimumTemperature:
    // no slope, as saturation(T)'s
    const scalar T = sat.T;
    if (!(T >= minimumTemperature_ && T < dryOutTemperature_))
    {
        return 0;
    }
    // d/dT [-p_c Vm/(R T)] = -Vm (dp_c/dT - p_c/T)/(R T)
    const scalar S = min(alphaL, scalar(1));
    return
       -kelvin_.Vm()/(R()*T)
       *(kelvinPc_->dpcdT(S, T) - kelvinPc_->pc(S, T)/T);
}


Foam::scalar Foam::pendularMedium::vapourDensity
(
    const scalar alphaL,
    const saturationState& sat
) const
{
    if (alphaL <= 0)
    {
        return 0;
    }
    return
        Mw()*sat.pSat*std::exp(lnRelativeHumidity(alphaL, sat))
       /(R()*sat.T);
}


Foam::scalar Foam::pendularMedium::dVapourDensitydAlphaL
(
    const scalar alphaL,
    const saturationState& sat
) const
{
    if (alphaL <= 0)
    {
        return 0;
    }
    return vapourSlope(vapourDensity(alphaL, sat), alphaL, sat);
}


Foam::scalar Foam::pendularMedium::waterContent
(
    const scalar alphaL,
    const saturationState& sat,
    const scalar porosity
) const
{
    return
        porosity*(alphaL*rhoL() + (1 - alphaL)*vapourDensity(alphaL, sat));
}


Foam::scalar Foam::pendularMedium::vapourDensity
(
    const scalar alphaL,
    const scalar T
) const
{
    return vapourDensity(alphaL, saturation(T));
}


Foam::scalar Foam::pendularMedium::dVapourDensitydT
(
    const scalar alphaL,
    const saturationState& sat
) const
{
    if (alphaL <= 0)
    {
        return 0;
    }
    // rho_w = M_w p_wsat exp(kelvinLength K)/(R T)
    return
        vapourDensity(alphaL, sat)
       *(
            sat.dLnPSatdT
          + dLnRelativeHumiditydT(alphaL, sat)
          - 1/sat.T
        );
}


Foam::scalar Foam::pendularMedium::dVapourDensitydT
(
    const scalar alphaL,
    const scalar T
) const
{
    return dVapourDensitydT(alphaL, saturation(T));
}


Foam::scalar Foam::pendularMedium::vapourSlopeTAtFixedW
(
    const scalar alphaL,
    const saturationState& sat,
    const scalar rhoW
) const
{
    // 0 = dW = W_alpha d alpha + phi (1 - alpha) rho_w,T dT, with
    // rho_w,alpha (dVapourDensitydAlphaL) and rho_w,T (dVapourDensitydT)
    // from rhoW = rho_w(alpha) (the vapour evaluated once)
    const scalar rhoWAlpha =
        alphaL > 0 ? vapourSlope(rhoW, alphaL, sat) : 0;
    const scalar rhoWT =
        alphaL > 0
      ? rhoW*(sat.dLnPSatdT + dLnRelativeHumiditydT(alphaL, sat) - 1/sat.T)
      : 0;
    return rhoWT*(rhoL() - rhoW)/(rhoL() - rhoW + (1 - alphaL)*rhoWAlpha);
}


Foam::scalar Foam::pendularMedium::dVapourDensitydTAtFixedW
(
    const scalar alphaL,
    const saturationState& sat,
    const scalar porosity
) const
{
    return vapourSlopeTAtFixedW(alphaL, sat, vapourDensity(alphaL, sat));
}


Foam::scalar Foam::pendularMedium::dVapourDensitydTAtFixedW
(
    const scalar alphaL,
    const scalar T,
    const scalar porosity
) const
{
    return dVapourDensitydTAtFixedW(alphaL, saturation(T), porosity);
}


Foam::scalar Foam::pendularMedium::dVapourDensitydAlphaL
(
    const scalar alphaL,
    const scalar T
) const
{
    return dVapourDensitydAlphaL(alphaL, saturation(T));
}


Foam::scalar Foam::pendularMedium::waterContent
(
    const scalar alphaL,
    const scalar T,
    const scalar porosity
) const
{
    return waterContent(alphaL, saturation(T), porosity);
}


Foam::scalar Foam::pendularMedium::dWaterContentdAlphaL
(
    const scalar alphaL,
    const saturationState& sat,
    const scalar porosity
) const
{
    // d rho_w/d alpha = rho_w kelvinLength dK/d alpha
    const scalar rhoW = vapourDensity(alphaL, sat);
    const scalar dRhoWdAlpha =
        alphaL > 0
      ? vapourSlope(rhoW, alphaL, sat)
      : 0;
    return porosity*(rhoL() - rhoW + (1 - alphaL)*dRhoWdAlpha);
}


Foam::scalar Foam::pendularMedium::dWaterContentdAlphaL
(
    const scalar alphaL,
    const scalar T,
    const scalar porosity
) const
{
    return dWaterContentdAlphaL(alphaL, saturation(T), porosity);
}


Foam::scalar Foam::pendularMedium::alphaL
(
    const scalar W,
    const saturationState& sat,
    const scalar porosity,
    const scalar alphaGuess
) const
{
    if (W <= 0 || sat.liquidFree)
    {
        return 0;
    }

    // Bracket [lo, hi] in s = ln(alpha): W(alpha) increases with alpha
    // from 0 (dry: the vapour vanishes with the menisci) to phi rho_l.
    // Below alphaLDry the cell is dry (all its water vapour): near a zero
    // of the surface tension alpha would underflow, dK/d alpha overflow
    const scalar lnAlphaDry = std::log(alphaLDry);
    bool dryTested = false;
    scalar lo = lnAlphaDry;
    scalar hi = 0;
    scalar s =
        alphaGuess > 0
      ? std::log(alphaGuess)
      : std::log(max(W/(porosity*rhoL()), 1e-300));
    s = min(max(s, lo), hi);

    for (label iter = 0; iter < 200; ++iter)
    {
        // W(alpha) and its slope with one evaluation of the vapour
        const scalar alpha = std::exp(s);
        const scalar rhoW = vapourDensity(alpha, sat);
        const scalar g = porosity*(alpha*rhoL() + (1 - alpha)*rhoW) - W;

        if (s <= lnAlphaDry)
        {
            // At the dry limit: still too much water there, the cell is dry
            if (g >= 0)
            {
                return 0;
            }
            dryTested = true;
        }

        // dg/ds = alpha dW/d alpha
        const scalar dgds =
            alpha*porosity
           *(
                rhoL() - rhoW
              + vapourSlope((1 - alpha)*rhoW, alpha, sat)
            );

        if (mag(g) <= 1e-14*W)
        {
            // Converged: one more Newton step on g from here, in alpha
            // itself, alpha (1 - g/(dg/ds)) (not exp(s - g/(dg/ds)), whose
            // resolution is that of s = ln(alpha), |s| epsilon relative:
            // 16 units of round-off of alpha at 1e-12), so that the result
            // is the root to the round-off of alpha and of g whatever the
            // guess. Returning alpha itself made alpha_l(W) a staircase in
            // W within 1e-14 W of the guess: in a nearly full two-phase
            // cell, 1 - S_l ~ 1e-7, the gas residual jumped by ~126
            // tolerances across 2 ulps of W and Newton stalled (issue 14)
            return
                dgds > 0
              ? min(max(alpha*(1 - g/dgds), alphaLDry), scalar(1))
              : alpha;
        }
        if (g > 0)
        {
            hi = s;
        }
        else
        {
            lo = s;
        }

        // Newton in s on ln(W(alpha)/W) (the same step as on g near the
        // root; far from it, exact where the water is all liquid, so that
        // a guess orders of magnitude off costs one step, not one per unit
        // of s); bisection when it leaves the bracket
        const scalar Walpha = g + W;
        scalar sNew =
            dgds > 0 && Walpha > 0
          ? s - std::log(Walpha/W)*Walpha/dgds
          : 0.5*(lo + hi);
        if (!(sNew > lo) && !dryTested && lo == lnAlphaDry)
        {
            // Below the bracket, whose lower end is still the untried dry
            // limit: try it
            sNew = lnAlphaDry;
        }
        else if (!(sNew > lo && sNew < hi))
        {
            sNew = 0.5*(lo + hi);
        }
        if (mag(sNew - s) < 1e-15*max(mag(s), 1.0) || hi - lo < 1e-14)
        {
            return std::exp(sNew);
        }
        s = sNew;
    }

    return std::exp(s);
}


bool Foam::pendularMedium::alphaLNear
(
    const scalar W,
    const saturationState& sat,
    const scalar porosity,
    const scalar alphaB,
    const scalar rhoWB,
    const scalar TB,
    scalar& alpha,
    scalar& rhoW
) const
{
    if (!(alphaB > alphaLDry && alphaB < 1) || sat.liquidFree)
    {
        return false;
    }
    // g and g' at alphaB (waterContent, dWaterContentdAlphaL)
    const scalar rho0 = sat.T == TB ? rhoWB : vapourDensity(alphaB, sat);
    const scalar rhoAlpha = vapourSlope(rho0, alphaB, sat);
    const scalar g = porosity*(alphaB*rhoL() + (1 - alphaB)*rho0) - W;
    const scalar dgdAlpha = porosity*(rhoL() - rho0 + (1 - alphaB)*rhoAlpha);
    if (!(dgdAlpha > 0 && rho0 > 0))
    {
        return false;
    }
    const scalar dAlpha = -g/dgdAlpha;
    const scalar k = 1 + mag(rhoAlpha)*alphaB/rho0;
    if (!(k*mag(dAlpha) <= nearRootTol*alphaB))
    {
        return false;
    }
    alpha = alphaB + dAlpha;
    rhoW = rho0 + rhoAlpha*dAlpha;
    return true;
}


Foam::scalar Foam::pendularMedium::alphaL
(
    const scalar W,
    const scalar T,
    const scalar porosity,
    const scalar alphaGuess
) const
{
    return alphaL(W, saturation(T), porosity, alphaGuess);
}


Foam::scalar Foam::pendularMedium::energy
(
    const scalar T,
    const scalar W,
    const scalar alphaL,
    const scalar pa,
    const scalar porosity
) const
{
    return
        energy
        (
            T, W, alphaL,
            vapourDensity(W, alphaL, saturation(T), porosity), pa, porosity
        );
}


Foam::scalar Foam::pendularMedium::energy
(
    const scalar T,
    const scalar W,
    const scalar alphaL,
    const scalar rhoW,
    const scalar pa,
    const scalar porosity
) const
{
    const scalar th = T - latentHeatTemperature_;
    return
        ((1 - porosity)*rhoSolid_*CpSolid_ + CpLiquid_*W)*th
      + porosity*(1 - alphaL)
       *(
            airDensity(pa, T)*CpAir_*th
          + rhoW*((CpVapour_ - CpLiquid_)*th + latentHeat_)
        );
}


Foam::scalar Foam::pendularMedium::energyCapacity
(
    const saturationState& sat,
    const scalar W,
    const scalar alphaL,
    const scalar pa,
    const scalar porosity
) const
{
    const scalar th = sat.T - latentHeatTemperature_;
    // The Kelvin-Laplace vapour at alpha, evaluated once (0 if dry)
    const scalar rhoWK = vapourDensity(alphaL, sat);
    return
        sensibleCapacity
        (
            sat.T, W, alphaL,
            alphaL > 0 ? rhoWK : max(W, scalar(0))/porosity, pa, porosity
        )
      + porosity*(1 - alphaL)
       *vapourSlopeTAtFixedW(alphaL, sat, rhoWK)
       *((CpVapour_ - CpLiquid_)*th + latentHeat_);
}


Foam::scalar Foam::pendularMedium::sensibleCapacity
(
    const scalar T,
    const scalar W,
    const scalar alphaL,
    const scalar rhoW,
    const scalar pa,
    const scalar porosity
) const
{
    const scalar th = T - latentHeatTemperature_;
    return
        (1 - porosity)*rhoSolid_*CpSolid_ + CpLiquid_*W
      + porosity*(1 - alphaL)
       *(
            airDensity(pa, T)*CpAir_*(1 - th/T)
          + rhoW*(CpVapour_ - CpLiquid_)
        );
}


Foam::scalar Foam::pendularMedium::energyCapacity
(
    const scalar T,
    const scalar W,
    const scalar alphaL,
    const scalar pa,
    const scalar porosity
) const
{
    return energyCapacity(saturation(T), W, alphaL, pa, porosity);
}


Foam::scalar Foam::pendularMedium::kappa
(
    const scalar alphaL,
    const scalar porosity
) const
{
    return conductivityModel().kappaPartiallySaturated
    (
        kappaSolid_, kappaLiquid_, kappaGas_, alphaL, porosity
    );
}

// ************************************************************************* //
