/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "fitMethod.H"
#include "checkedRead.H"
#include "Switch.H"

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
                "initialDamping", "confidence", "jacobianUpdates",
                "noiseStop"
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
        // Every number finite and in its range (FatalIOError naming the
        // keyword and the range; levenbergMarquardt's own checks would
        // throw without the file)
        const validRange fraction{0, 1, true, true};
        const scalar noise =
            checkedRead::getOrDefault
            (
                methodDict, "solverNoise", dimless, 1e-6, fraction
            ).value();
        opts.hRel =
            checkedRead::getOrDefault
            (
                methodDict, "relativeStep", dimless,
                hearthFit::levenbergMarquardt::recommendedRelativeStep
                (
                    noise, opts.difference
                ),
                validRange{0, 0.5, true, true}
            ).value();
        auto tolerance = [&](const word& key, const scalar deflt)
        {
            return
                checkedRead::getOrDefault
                (
                    methodDict, key, dimless, deflt,
                    checkedRead::nonNegative()
                ).value();
        };
        opts.tolStep = tolerance("tolStep", 1e-6);
        opts.tolGradient = tolerance("tolGradient", 1e-6);
        opts.tolCost = tolerance("tolCost", 1e-10);
        // Stop at the model's precision (levenbergMarquardt.H, "Stopping
        // at the model's precision"): on by default, the noise declared
        // by solverNoise; noiseStop off leaves the tolerances alone
        opts.solverNoise =
            methodDict.getOrDefault<Switch>("noiseStop", true) ? noise : 0;
        opts.maxIterations =
            checkedRead::getLabelOrDefault
            (
                methodDict, "maxIterations", 30, 1
            );
        // Broyden-updated Jacobians after each finite-difference one
        opts.jacobianUpdates =
            checkedRead::getLabelOrDefault
            (
                methodDict, "jacobianUpdates", 0, 0
            );
        opts.initialDamping =
            checkedRead::getOrDefault
            (
                methodDict, "initialDamping", dimless, 1e-3,
                validRange{0, opts.maxDamping, true, true}
            ).value();
        opts.confidence =
            checkedRead::getOrDefault
            (
                methodDict, "confidence", dimless, 0.95, fraction
            ).value();
    }

    return opts;
}


// ************************************************************************* //
