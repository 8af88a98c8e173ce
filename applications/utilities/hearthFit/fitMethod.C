/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "fitMethod.H"
#include "checkedRead.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * //

hearthFit::FitOptions Foam::readFitMethod(const dictionary& fitDict)
{
    if (fitDict.isDict("method"))
    {
        checkedRead::checkKeywords
        (
            fitDict.subDict("method"),
            wordList
            ({
                "type", "difference", "solverNoise", "relativeStep",
                "maxIterations", "tolStep", "tolGradient", "tolCost",
                "initialDamping", "confidence"
            })
        );
    }

    hearthFit::FitOptions opts;
    const dictionary methodDict
    (
        fitDict.found("method") ? fitDict.subDict("method") : dictionary()
    );
    {
        const word type
        (
            methodDict.lookupOrDefault<word>("type", "levenbergMarquardt")
        );
        if (type == "gaussNewton") opts.method = hearthFit::Method::gaussNewton;
        else if (type != "levenbergMarquardt")
        {
            FatalIOErrorInFunction(methodDict) << "method type " << type
                << ": valid are levenbergMarquardt, gaussNewton"
                << exit(FatalIOError);
        }
        const word diff(methodDict.lookupOrDefault<word>("difference", "forward"));
        if (diff == "central") opts.difference = hearthFit::Difference::central;
        else if (diff != "forward")
        {
            FatalIOErrorInFunction(methodDict) << "difference " << diff
                << ": valid are forward, central" << exit(FatalIOError);
        }
        const scalar noise =
            methodDict.lookupOrDefault<scalar>("solverNoise", 1e-6);
        opts.hRel = methodDict.lookupOrDefault<scalar>
        (
            "relativeStep",
            hearthFit::levenbergMarquardt::recommendedRelativeStep
            (
                noise, opts.difference
            )
        );
        opts.tolStep = methodDict.lookupOrDefault<scalar>("tolStep", 1e-6);
        opts.tolGradient =
            methodDict.lookupOrDefault<scalar>("tolGradient", 1e-6);
        opts.tolCost = methodDict.lookupOrDefault<scalar>("tolCost", 1e-10);
        opts.maxIterations =
            methodDict.lookupOrDefault<label>("maxIterations", 30);
        opts.initialDamping =
            methodDict.lookupOrDefault<scalar>("initialDamping", 1e-3);
        opts.confidence =
            methodDict.lookupOrDefault<scalar>("confidence", 0.95);
    }

    return opts;
}


// ************************************************************************* //
