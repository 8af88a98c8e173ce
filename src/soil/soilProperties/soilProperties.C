/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "soilProperties.H"
#include "propertyField.H"
#include "checkedRead.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(soilProperties, 0);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::word Foam::soilProperties::fileName(const layout l)
{
    switch (l)
    {
        case layout::porousAlias: return "porousProperties";
        case layout::pendularAlias: return "pendularProperties";
        default: return "soilProperties";
    }
}


Foam::soilProperties::layout Foam::soilProperties::findLayout
(
    const fvMesh& mesh,
    const layout alias
)
{
    auto present = [&](const layout l)
    {
        return
            IOobject
            (
                fileName(l),
                mesh.time().constant(),
                mesh,
                IOobject::MUST_READ,
                IOobject::NO_WRITE,
                false
            ).typeHeaderOk<IOdictionary>(true);
    };

    const bool soil = present(layout::soil);
    const bool old = present(alias);

    if (soil && old)
    {
        dictionary fileDict;
        fileDict.name() =
            mesh.time().constant()/fileName(alias);
        FatalIOErrorInFunction(fileDict)
            << "Both constant/" << fileName(layout::soil) << " and its"
            << " deprecated alias constant/" << fileName(alias)
            << " describe the soil: keep constant/"
            << fileName(layout::soil) << " only (README, \"The soil"
            << " dictionary\")" << nl << exit(FatalIOError);
    }

    // Neither: the IOdictionary's MUST_READ names constant/soilProperties
    return old ? alias : layout::soil;
}


Foam::phaseProperties Foam::soilProperties::readPhase(const word& phase) const
{
    if (layout_ == layout::soil)
    {
        return phaseProperties(*this, phase);
    }
    if (layout_ == layout::porousAlias)
    {
        return phaseProperties(*this, phase == "gas" ? word("vapour") : phase);
    }

    // pendularProperties: flat keywords with the report's defaults
    const auto positive = checkedRead::positive();
    const dimensionSet dimCp(dimEnergy/dimMass/dimTemperature);
    const dimensionSet dimKappa(dimPower/dimLength/dimTemperature);
    const auto read =
        [&](const word& key, const dimensionSet& dims, scalar deflt)
        {
            return checkedRead::getOrDefault
            (
                *this, key, dims, deflt, positive
            ).value();
        };

    // A phase from three flat keywords, read in this order
    const auto flat =
        [&]
        (
            const word& rhoKey, const scalar rho0,
            const word& CpKey, const scalar Cp0,
            const word& kappaKey, const scalar kappa0
        )
        {
            const scalar rho = read(rhoKey, dimDensity, rho0);
            const scalar Cp = read(CpKey, dimCp, Cp0);
            const scalar kappa = read(kappaKey, dimKappa, kappa0);
            return phaseProperties(phase, rho, Cp, kappa);
        };

    if (phase == "solid")
    {
        return flat("rhoSolid", 2600, "CpSolid", 800, "kappaSolid", 3.0);
    }
    if (phase == "liquid")
    {
        return flat("rhoL", 1000, "CpLiquid", 4200, "kappaLiquid", 0.6);
    }
    return phaseProperties(phase, 0, 0, read("kappaGas", dimKappa, 0.026));
}


Foam::dimensionedScalar Foam::soilProperties::readPorosity() const
{
    if (layout_ == layout::pendularAlias)
    {
        return checkedRead::getOrDefault
        (
            *this, "porosity", dimless, 0.26, checkedRead::closedOpen(0, 1)
        );
    }
    return checkedRead::get
    (
        *this, "porosity", dimless, checkedRead::closedOpen(0, 1)
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::soilProperties::soilProperties(const fvMesh& mesh, const layout aliasLayout)
:
    IOdictionary
    (
        IOobject
        (
            fileName(findLayout(mesh, aliasLayout)),
            mesh.time().constant(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    ),
    // (named after its file on every rank before anything is read from it:
    // checkedRead::nameAfterFile)
    mesh_((checkedRead::nameAfterFile(*this), mesh)),
    layout_
    (
        IOobject::name() == fileName(aliasLayout) ? aliasLayout : layout::soil
    ),
    solid_(readPhase("solid")),
    liquid_(readPhase("liquid")),
    gas_(readPhase("gas")),
    porosity_(propertyField(mesh, "porosity", readPorosity())),
    conductivity_(effectiveConductivityModel::New(*this))
{
    if (alias())
    {
        Info<< "Deprecated: the soil is read from constant/"
            << fileName(layout_) << "; its successor is constant/"
            << fileName(layout::soil) << " (README, \"The soil dictionary\")"
            << endl;
        return;
    }

    // Unknown keywords: a misspelt one would be ignored or take a default.
    // The file serves every solver: each checks its own closures.
    wordList allowed
    ({
        "porosity", "solid", "liquid", "gas",
        "waterContent", "saturation", "phaseChange",     // ahcFoam
        "pendular"                                        // pendularFoam
    });
    allowed.append
    (
        checkedRead::modelKeywords(*this, "conductivityModel", conductivity_())
    );
    checkedRead::checkKeywords(*this, allowed);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const Foam::dictionary& Foam::soilProperties::closures(const word& name) const
{
    if (alias())
    {
        return *this;
    }
    if (!isDict(name))
    {
        FatalIOErrorInFunction(*this)
            << "Missing sub-dictionary '" << name << "' in " << objectPath()
            << ": the closures of the " << name << " model (README, \"The"
            << " soil dictionary\")" << nl << exit(FatalIOError);
    }
    return subDict(name);
}

// ************************************************************************* //
