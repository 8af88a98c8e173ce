/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "porousMedium.H"
#include "propertyField.H"
#include "startupReport.H"
#include "temperatureCheck.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(porousMedium, 0);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::volScalarField Foam::porousMedium::propertyField
(
    const word& name,
    const dimensionedScalar& uniformValue
) const
{
    return Foam::propertyField(mesh_, name, uniformValue);
}


inline Foam::scalar Foam::porousMedium::matrixCapacity
(
    const label celli
) const
{
    return matrixCapacity_[celli];
}


inline Foam::scalar Foam::porousMedium::kappaAt
(
    const label celli,
    const scalar alphaL
) const
{
    return conductivityModel().kappaPartiallySaturated
    (
        kappaSolid_[celli], liquid().kappa(), gas().kappa(), alphaL,
        porosity()[celli]
    );
}


inline void Foam::porousMedium::cellEnthalpy
(
    const label celli,
    const scalar T,
    const scalar TMax,
    scalar& H,
    scalar& C
) const
{
    const scalar theta0 = waterContent_[celli];
    const scalar rhoCpDry = matrixCapacity(celli);

    H = rhoCpDry*T;
    C = rhoCpDry;

    if (theta0 > 0)
    {
        scalar h, c;
        phaseChange_->enthalpyAndCapacity(T, TMax, h, c);
        H += theta0*h;
        C += theta0*c;
    }
}


inline Foam::scalar Foam::porousMedium::kappaCell
(
    const label celli,
    const scalar T,
    const scalar TMax
) const
{
    const scalar sigmaE = phaseChange_->evaporatedFraction(T, TMax);
    if (sigmaE == 0 && kappaUndried_[celli] >= 0)
    {
        // theta_l = theta_0 (1 - 0) = theta_0: the value below, to the bit
        return kappaUndried_[celli];
    }

    const scalar phi = porosity()[celli];
    const scalar thetaL = waterContent_[celli]*(1.0 - sigmaE);

    // Liquid fraction of the pores, alpha_l = theta_l/phi: the pore fluid
    // is alpha_l k_l + (1 - alpha_l) k_v (kappaPartiallySaturated), or
    // the table k_e(alpha_l) of conductivityModel tabulated
    return kappaAt(celli, phi > SMALL ? thetaL/phi : 0);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::porousMedium::porousMedium(const fvMesh& mesh)
:
    soilProperties(mesh, soilProperties::layout::porousAlias),
    mesh_(mesh),
    waterContent_
    (
        propertyField("waterContent", dimensionedScalar(dimless, Zero))
    ),
    rhoCpSolid_
    (
        propertyField
        (
            "rhoCpSolid",
            dimensionedScalar
            (
                "rhoCpSolid",
                dimEnergy/dimVolume/dimTemperature,
                solid().rhoCp()
            )
        )
    ),
    kappaSolid_
    (
        propertyField
        (
            "kappaSolid",
            dimensionedScalar
            (
                "kappaSolid",
                dimPower/dimLength/dimTemperature,
                solid().kappa()
            )
        )
    ),
    kappaUndried_(),
    matrixCapacity_(),
    phaseChange_(nullptr)
{
    // Unknown keywords: a misspelt one would be ignored or take a default
    // (constant/soilProperties: checked by soilProperties)
    if (alias())
    {
        wordList allowed
        ({
            "solid", "liquid", "vapour", "porosity", "waterContent",
            "saturation", "phaseChange"
        });
        allowed.append
        (
            checkedRead::modelKeywords
            (
                *this, "conductivityModel", conductivityModel()
            )
        );
        checkedRead::checkKeywords(*this, allowed);
    }

    const auto range01 = checkedRead::closedOpen(0, 1);
    const auto positive = checkedRead::positive();

    // Cell fields overriding uniform values
    checkedRead::check
    (
        porosity().objectPath(), "porosity", porosity(), range01
    );
    checkedRead::check
    (
        rhoCpSolid_.objectPath(), "rhoCpSolid", rhoCpSolid_, positive
    );
    checkedRead::check
    (
        kappaSolid_.objectPath(), "kappaSolid", kappaSolid_, positive
    );

    // Initial water: a cell field, a saturation or a volumetric content
    if (!waterContent_.headerOk())
    {
        if (found("saturation") == found("waterContent"))
        {
            FatalIOErrorInFunction(*this)
                << (
                       found("saturation")
                     ? "Both keywords 'waterContent' and 'saturation' given"
                     : "Missing keyword 'waterContent' (or 'saturation')"
                   )
                << " in dictionary "
                << name() << ": expected exactly one of waterContent"
                << " (volumetric, in the range [0, porosity = "
                << gMin(porosity().primitiveField()) << "]) or saturation"
                << " (in the range [0, 1]), or the cell field "
                << waterContent_.objectPath() << nl
                << exit(FatalIOError);
        }

        if (found("saturation"))
        {
            const scalar S =
                checkedRead::get
                (
                    *this, "saturation", dimless, checkedRead::closed(0, 1)
                ).value();
            waterContent_.primitiveFieldRef() = S*porosity().primitiveField();
        }
        else
        {
            const scalar theta0 =
                checkedRead::get
                (
                    *this, "waterContent", dimless, checkedRead::closed(0, 1)
                ).value();

            const scalar phiMin = gMin(porosity().primitiveField());
            if (theta0 > phiMin)
            {
                FatalIOErrorInFunction(*this)
                    << "Keyword 'waterContent' = " << theta0
                    << " is outside its valid range [0, porosity = "
                    << phiMin << "]: the volumetric water content cannot"
                    << " exceed the porosity" << nl
                    << exit(FatalIOError);
            }
            waterContent_.primitiveFieldRef() = theta0;
        }
        waterContent_.correctBoundaryConditions();
    }

    forAll(waterContent_, celli)
    {
        if
        (
            waterContent_[celli] < 0
         || waterContent_[celli] > porosity()[celli] + SMALL
        )
        {
            dictionary fieldDict;
            fieldDict.name() = waterContent_.objectPath();
            FatalIOErrorInFunction(fieldDict)
                << "Field 'waterContent' = " << waterContent_[celli]
                << " in cell " << celli << " is outside its valid range"
                << " [0, porosity = " << porosity()[celli] << "]" << nl
                << exit(FatalIOError);
        }
    }

    if (!isDict("phaseChange"))
    {
        FatalIOErrorInFunction(*this)
            << "Missing sub-dictionary 'phaseChange' in " << name()
            << ": expected { type energyConsistent|thesisCompatible;"
            << " Tv; dT; latentHeat; }" << nl
            << exit(FatalIOError);
    }
    phaseChange_ =
        apparentHeatCapacityModel::New(subDict("phaseChange"), liquid(), gas());

    // (-1 where the law is not defined at theta_0/phi, tabulated beyond its
    // table: kappaCell then calls the law, as before)
    matrixCapacity_.setSize(mesh.nCells());
    forAll(matrixCapacity_, celli)
    {
        const scalar phi = porosity()[celli];
        matrixCapacity_[celli] =
            (1.0 - phi)*rhoCpSolid_[celli]
          + (phi - waterContent_[celli])*gas().rhoCp();
    }

    kappaUndried_.setSize(mesh.nCells());
    forAll(kappaUndried_, celli)
    {
        const scalar phi = porosity()[celli];
        const scalar alpha0 = phi > SMALL ? waterContent_[celli]/phi : 0;
        kappaUndried_[celli] =
            conductivityModel().definedAt(alpha0) ? kappaAt(celli, alpha0) : -1;
    }

    Info<< "Porous medium: porosity " << gMin(porosity().primitiveField())
        << " to " << gMax(porosity().primitiveField())
        << ", water content " << gMin(waterContent_.primitiveField())
        << " to " << gMax(waterContent_.primitiveField()) << nl
        << "    conductivity model " << get<word>("conductivityModel")
        << ", phase change " << phaseChange_->type()
        << " (Tv = " << phaseChange_->Tv() << " K, dT = "
        << phaseChange_->dT() << " K, L = " << phaseChange_->latentHeat()
        << " J/kg, irreversible " << phaseChange_->irreversible() << ")"
        << nl << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::scalarField> Foam::porousMedium::enthalpy
(
    const scalarField& T,
    const scalarField& TMax
) const
{
    auto tH = tmp<scalarField>::New(T.size());
    scalarField& H = tH.ref();
    scalar C;

    forAll(H, celli)
    {
        cellEnthalpy(celli, T[celli], TMax[celli], H[celli], C);
    }
    return tH;
}


Foam::tmp<Foam::scalarField> Foam::porousMedium::capacity
(
    const scalarField& T,
    const scalarField& TMax
) const
{
    auto tC = tmp<scalarField>::New(T.size());
    scalarField& C = tC.ref();
    scalar H;

    forAll(C, celli)
    {
        cellEnthalpy(celli, T[celli], TMax[celli], H, C[celli]);
    }
    return tC;
}


void Foam::porousMedium::enthalpyAndCapacity
(
    const scalarField& T,
    const scalarField& TMax,
    scalarField& H,
    scalarField& C
) const
{
    forAll(T, celli)
    {
        cellEnthalpy(celli, T[celli], TMax[celli], H[celli], C[celli]);
    }
}


Foam::label Foam::porousMedium::temperature
(
    const scalarField& H,
    const scalarField& TMax,
    scalarField& T,
    scalarField& C
) const
{
    const scalar waterMinCapacity = phaseChange_->minimumCapacity();
    const label maxSteps = 100;
    label maxUsed = 0;

    forAll(T, celli)
    {
        scalar Ti = T[celli];
        scalar Hi, Ci;
        cellEnthalpy(celli, Ti, TMax[celli], Hi, Ci);

        // Most cells: H(T) is already H to the tolerance below (at least
        // 1e-12 |H|), as where the enthalpy is linear over the nonlinear
        // iteration's change: T as given, without the bracket (the same
        // values as the loop, which would not start)
        if (mag(Hi - H[celli]) <= 1e-12*mag(H[celli]))
        {
            C[celli] = Ci;
            continue;
        }

        const scalar minCapacity =
            matrixCapacity(celli) + waterContent_[celli]*waterMinCapacity;

        // |T - root| <= |H(T) - H|/minCapacity brackets the root
        const scalar width = mag(Hi - H[celli])/minCapacity;
        scalar lower = Ti - width;
        scalar upper = Ti + width;
        const scalar tolerance = 1e-12*max(mag(H[celli]), minCapacity);

        label step = 0;
        while (mag(Hi - H[celli]) > tolerance && step < maxSteps)
        {
            ++step;
            if (Hi > H[celli])
            {
                upper = Ti;
            }
            else
            {
                lower = Ti;
            }

            scalar Tnew = Ti - (Hi - H[celli])/Ci;
            if (Tnew <= lower || Tnew >= upper)
            {
                Tnew = 0.5*(lower + upper);
            }
            if (upper - lower < 1e-12*mag(Ti))
            {
                break;
            }
            Ti = Tnew;
            cellEnthalpy(celli, Ti, TMax[celli], Hi, Ci);
        }

        T[celli] = Ti;
        C[celli] = Ci;
        maxUsed = max(maxUsed, step);
    }

    return maxUsed;
}


Foam::tmp<Foam::scalarField> Foam::porousMedium::latentEnthalpy
(
    const scalarField& T,
    const scalarField& TMax
) const
{
    auto tHl = tmp<scalarField>::New(T.size());
    scalarField& Hl = tHl.ref();

    forAll(Hl, celli)
    {
        Hl[celli] =
            waterContent_[celli]
           *phaseChange_->latentEnthalpy
            (
                phaseChange_->evaporatedFraction(T[celli], TMax[celli])
            );
    }
    return tHl;
}


Foam::tmp<Foam::scalarField> Foam::porousMedium::liquidWater
(
    const scalarField& T,
    const scalarField& TMax
) const
{
    auto tTheta = tmp<scalarField>::New(T.size());
    scalarField& theta = tTheta.ref();

    forAll(theta, celli)
    {
        theta[celli] =
            waterContent_[celli]
           *(1.0 - phaseChange_->evaporatedFraction(T[celli], TMax[celli]));
    }
    return tTheta;
}


Foam::scalar Foam::porousMedium::liquidWaterMass
(
    const scalarField& T,
    const scalarField& TMax
) const
{
    return liquid().rho()*gSum(mesh_.V()*liquidWater(T, TMax));
}


Foam::tmp<Foam::volScalarField> Foam::porousMedium::kappa
(
    const volScalarField& T,
    const volScalarField& TMax
) const
{
    auto tkappa = tmp<volScalarField>::New
    (
        IOobject
        (
            "kappa",
            mesh_.time().timeName(),
            mesh_,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        ),
        mesh_,
        dimensionedScalar(dimPower/dimLength/dimTemperature, Zero)
    );
    correctKappa(tkappa.ref(), T, TMax);

    return tkappa;
}


void Foam::porousMedium::report
(
    const volScalarField& T,
    const volScalarField& TMax
) const
{
    const apparentHeatCapacityModel& pc = *phaseChange_;
    const label n = mesh_.nCells();
    const scalarField& phi = porosity().primitiveField();
    const scalarField& theta0 = waterContent_.primitiveField();

    scalarField alpha0(n), w0(n), rhoCpDry(n), rhoCpWet(n), Lw(n);
    forAll(alpha0, celli)
    {
        alpha0[celli] = phi[celli] > SMALL ? theta0[celli]/phi[celli] : 0;
        w0[celli] =
            theta0[celli]*liquid().rho()/((1 - phi[celli])*solid().rho());
        // Frozen composition: all the water liquid (sigma = 0) or vapour
        rhoCpWet[celli] =
            matrixCapacity(celli) + theta0[celli]*pc.sensibleCapacity(0);
        rhoCpDry[celli] =
            matrixCapacity(celli) + theta0[celli]*pc.sensibleCapacity(1);
        Lw[celli] =
            theta0[celli]*(pc.latentEnthalpy(1) - pc.latentEnthalpy(0));
    }

    // k_e where the law is defined (tabulated: its table's range)
    const effectiveConductivityModel& law = conductivityModel();
    bool dryDefined = true, wetDefined = true, satDefined = true;
    scalarField kDry(n, Zero), kWet(n, Zero), kSat(n, Zero);
    forAll(kDry, celli)
    {
        dryDefined = dryDefined && law.definedAt(0);
        wetDefined = wetDefined && law.definedAt(alpha0[celli]);
        satDefined = satDefined && law.definedAt(1);
        kDry[celli] = dryDefined ? kappaAt(celli, 0) : 0;
        kWet[celli] = wetDefined ? kappaAt(celli, alpha0[celli]) : 0;
        kSat[celli] = satDefined ? kappaAt(celli, 1) : 0;
    }

    startupReport table("ahcFoam");
    table.add("T_0", T.primitiveField(), "K", "initial temperature");
    table.add("phi", phi, "-", "porosity");
    table.add
    (
        "theta_0", theta0, "-",
        "initial water, volume fraction of the soil (waterContent)"
    );
    table.add
    (
        "w_0", w0, "kg/kg",
        "initial water, mass per mass of dry solid: theta_0 rho_l/((1 - phi)"
        " rho_s)"
    );
    table.add
    (
        "alpha_l_0", alpha0, "-", "liquid fraction of the pores, theta_0/phi"
    );
    table.add
    (
        "rhoCp_dry", rhoCpDry, "J/m3/K",
        "(rho C) of the dried soil (the initial water as vapour)"
    );
    table.add
    (
        "rhoCp_wet", rhoCpWet, "J/m3/K",
        "(rho C) of the soil with its initial water, latent heat excluded"
    );
    table.addConductivities
    (
        kDry, dryDefined, kWet, wetDefined, kSat, satDefined,
        rhoCpDry, rhoCpWet
    );
    table.add
    (
        "L_water", Lw, "J/m3",
        "latent heat of the initial water per volume of soil ("
      + pc.type() + ")"
    );
    const scalar TLow = pc.Tv() - 2*pc.dT();
    const scalar THigh = pc.Tv() + 2*pc.dT();
    table.add("T_v", pc.Tv(), "K", "evaporation temperature");
    table.add("T_evap_low", TLow, "K", "T_v - 2 dT: evaporation window (95 % of L)");
    table.add("T_evap_high", THigh, "K", "T_v + 2 dT");
    table.add
    (
        "T_min", scalar(0), "K",
        "validity: T > 0 K in every cell and on every patch, at every step"
    );
    table.add
    (
        "T_0_min", temperatureCheck::celsiusThreshold, "K",
        "validity: initial soil at or above it (else Celsius typed as"
        " kelvin); no upper bound (constant phase properties)"
    );

    // A cell starting in (or above) the window has lost part of its water
    // before the first step. Not a warning when TMax was read (a restart,
    // or a soil heated before): the loss is then the history given
    IOobject TMaxFile(TMax);
    const bool fresh = !TMaxFile.typeHeaderOk<volScalarField>(true);
    const scalar sigmaLow = pc.sigma(TLow);
    boolList early(n, false);
    scalar sigmaMax = 0;
    forAll(early, celli)
    {
        const scalar sigma0 =
            pc.evaporatedFraction(T[celli], TMax[celli]);
        early[celli] = fresh && theta0[celli] > 0 && sigma0 >= sigmaLow;
        if (early[celli])
        {
            sigmaMax = max(sigmaMax, sigma0);
        }
    }
    reduce(sigmaMax, maxOp<scalar>());
    table.warn
    (
        early,
        "initial state outside the validity range: water at or above the"
        " evaporation window (T_v - 2 dT = " + Foam::name(TLow)
      + " K): up to a fraction " + Foam::name(sigmaMax) + " of"
        " theta_0 counts as already evaporated"
    );

    table.write(Info);
}


void Foam::porousMedium::correctKappa
(
    volScalarField& kappa,
    const volScalarField& T,
    const volScalarField& TMax
) const
{
    forAll(kappa, celli)
    {
        kappa[celli] = kappaCell(celli, T[celli], TMax[celli]);
    }

    // Coupled patches (processor, cyclic) take the neighbour cell values
    kappa.correctBoundaryConditions();

    // Other patches: the adjacent cell's material at the boundary temperature
    volScalarField::Boundary& kappaBf = kappa.boundaryFieldRef();
    forAll(kappaBf, patchi)
    {
        fvPatchScalarField& kappap = kappaBf[patchi];
        if (kappap.coupled())
        {
            continue;
        }

        const labelUList& faceCells = kappap.patch().faceCells();
        const fvPatchScalarField& Tp = T.boundaryField()[patchi];

        forAll(kappap, facei)
        {
            const label celli = faceCells[facei];
            kappap[facei] =
                kappaCell(celli, Tp[facei], max(Tp[facei], TMax[celli]));
        }
    }
}

void Foam::porousMedium::correctKappaDerivative
(
    volScalarField& dKappadT,
    const volScalarField& kappa,
    const volScalarField& T,
    const volScalarField& TMax
) const
{
    const scalar h = 1e-4;

    forAll(dKappadT, celli)
    {
        dKappadT[celli] =
            (kappaCell(celli, T[celli] + h, TMax[celli]) - kappa[celli])/h;
    }

    // Coupled patches (processor, cyclic) take the neighbour cell values;
    // the others are not used (their conductivity follows the boundary
    // temperature)
    dKappadT.correctBoundaryConditions();
    volScalarField::Boundary& dKappadTBf = dKappadT.boundaryFieldRef();
    forAll(dKappadTBf, patchi)
    {
        if (!dKappadTBf[patchi].coupled())
        {
            dKappadTBf[patchi] = 0;
        }
    }
}


// ************************************************************************* //
