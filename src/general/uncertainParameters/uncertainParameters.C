/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "uncertainParameters.H"
#include "checkedRead.H"
#include "scratchCase.H"
#include "IFstream.H"
#include "OSspecific.H"

#include <Eigen/Dense>
#include <gsl/gsl_cdf.h>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::uncertainParameters::readParameters
(
    const dictionary& parsDict,
    const bool fromFit
)
{
    DynamicList<scalar> values;
    DynamicList<scalar> sds;
    for (const entry& e : parsDict)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(parsDict)
                << "uncertainty/parameters: '" << e.keyword() << "' is not"
                << " a dictionary: expected " << e.keyword() << " { file"
                << " <file>; entry <keyword path>; sd <sd>; }" << nl
                << exit(FatalIOError);
        }
        const dictionary& d = e.dict();
        const word name(e.keyword());
        checkedRead::checkKeywords
        (
            d,
            fromFit
          ? wordList({"file", "entry", "value", "sd"})
          : wordList({"file", "entry", "sd"}),
            "uncertain parameter " + name
        );

        fileName file(d.get<fileName>("file"));
        file.clean();
        const string entryPath(d.get<fileName>("entry"));

        // Only constant or system: the forward runs rewrite the start
        // time's T, system/controlDict and constant/fireHistory of the copy
        const wordList parts(file.components());
        if
        (
            parts.size() < 2
         || (parts[0] != "constant" && parts[0] != "system")
         || file.find("..") != string::npos
         || file == "system/controlDict"
         || file == "constant/fireHistory"
        )
        {
            FatalIOErrorInFunction(d)
                << "uncertain parameter " << name << ": keyword 'file' = "
                << file << ": expected a file of the case's constant or"
                << " system directory (relative to the case), other than"
                << " system/controlDict and constant/fireHistory (written"
                << " by the forward runs)" << nl
                << exit(FatalIOError);
        }

        // One case entry, one parameter: a second would double its variance
        forAll(names_, k)
        {
            if (files_[k] == file && entries_[k] == entryPath)
            {
                FatalIOErrorInFunction(d)
                    << "uncertain parameter " << name << ": the entry '"
                    << entryPath.c_str() << "' of " << file << " is already"
                    << " uncertain parameter " << names_[k] << ": one"
                    << " parameter per case entry" << nl
                    << exit(FatalIOError);
            }
        }

        if (!caseDicts_.found(file))
        {
            IFstream is(casePath_/file);
            if (!is.good())
            {
                FatalIOErrorInFunction(d)
                    << "uncertain parameter " << name << ": keyword 'file':"
                    << " cannot read " << casePath_/file << nl
                    << exit(FatalIOError);
            }
            dictionary cd(is);
            cd.remove("FoamFile");
            caseDicts_.insert(file, cd);
        }

        word key;
        dictionary* parent =
            scratchCase::parentDict(caseDicts_[file], entryPath, key);
        if (!parent || !parent->found(key) || parent->isDict(key))
        {
            FatalIOErrorInFunction(d)
                << "uncertain parameter " << name << ": keyword 'entry' = "
                << entryPath.c_str() << ": no such keyword path (of a"
                << " number; '/' between sub-dictionaries) in "
                << casePath_/file << nl
                << exit(FatalIOError);
        }
        checkedRead::checkNumbers
        (
            *parent, key,
            "a number (the value of uncertain parameter " + name + ")"
        );
        ITstream& is = parent->lookup(key);
        if (is.size() != 1)
        {
            FatalIOErrorInFunction(*parent)
                << "uncertain parameter " << name << ": the entry '"
                << entryPath.c_str() << "' of " << casePath_/file << " is "
                << is.size() << " tokens: expected a single number" << nl
                << exit(FatalIOError);
        }
        const scalar value = parent->get<scalar>(key);
        const scalar sd =
            checkedRead::get(d, "sd", dimless, checkedRead::positive())
           .value();

        // The fit's estimate must be the case's value (to 1e-3 sd): the
        // propagation linearises about the case's value
        if (fromFit)
        {
            checkedRead::checkNumbers(d, "value", "a number (the estimate)");
            const scalar estimate = d.get<scalar>("value");
            if (mag(value - estimate) > 1e-3*sd)
            {
                FatalIOErrorInFunction(d)
                    << "uncertain parameter " << name << ": keyword 'value'"
                    << " = " << estimate << " (the fit's estimate) differs"
                    << " from the case's " << entryPath.c_str() << " = "
                    << value << " in " << casePath_/file << " by more than"
                    << " 1e-3 sd (" << 1e-3*sd << "): the fit's covariance"
                    << " holds about its estimates; write them into the"
                    << " case (hearthFit -writeCase DIR)" << nl
                    << exit(FatalIOError);
            }
        }

        names_.append(name);
        files_.append(file);
        entries_.append(entryPath);
        values.append(value);
        sds.append(sd);
    }
    if (names_.empty())
    {
        FatalIOErrorInFunction(parsDict)
            << "uncertainty: keyword 'parameters' is empty: expected name"
            << " { file <file>; entry <keyword path>; sd <sd>; } entries"
            << nl << exit(FatalIOError);
    }
    values_.transfer(values);
    sds_.transfer(sds);
}


void Foam::uncertainParameters::readCorrelation(const dictionary& dict)
{
    const label n = names_.size();
    correlation_ = scalarSquareMatrix(n, Zero);
    for (label i = 0; i < n; ++i)
    {
        correlation_(i, i) = 1;
    }
    if (!dict.found("correlation"))
    {
        return;
    }

    checkedRead::checkNumbers
    (
        dict, "correlation",
        "the correlation matrix ((1 r12 ...) (r12 1 ...) ...) in the"
        " order of the parameters"
    );
    const List<scalarList> rows(dict.get<List<scalarList>>("correlation"));
    bool square = rows.size() == n;
    for (const scalarList& row : rows)
    {
        square = square && row.size() == n;
    }
    if (!square)
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 'correlation': expected a " << n << " x " << n
            << " matrix (one row per parameter, in the order "
            << names_ << ")" << nl << exit(FatalIOError);
    }
    for (label i = 0; i < n; ++i)
    {
        for (label j = 0; j < n; ++j)
        {
            const scalar r = rows[i][j];
            if
            (
                (i == j && r != 1)
             || mag(r - rows[j][i]) > 1e-12
             || mag(r) > 1 + 1e-12
            )
            {
                FatalIOErrorInFunction(dict)
                    << "Keyword 'correlation': element (" << i + 1 << ", "
                    << j + 1 << ") = " << r << ": expected a symmetric"
                    << " matrix with 1 on its diagonal and elements in"
                    << " [-1, 1] (parameters " << names_ << ")" << nl
                    << exit(FatalIOError);
            }
            correlation_(i, j) = min(max(r, scalar(-1)), scalar(1));
        }
    }

    Eigen::MatrixXd R(n, n);
    for (label i = 0; i < n; ++i)
    {
        for (label j = 0; j < n; ++j)
        {
            R(i, j) = correlation_(i, j);
        }
    }
    const scalar minEigen =
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>
        (
            R, Eigen::EigenvaluesOnly
        ).eigenvalues().minCoeff();
    if (minEigen < -1e-12)
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 'correlation': not positive semi-definite"
            << " (smallest eigenvalue " << minEigen << " < 0): not a"
            << " correlation matrix" << nl << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::uncertainParameters::uncertainParameters
(
    const dictionary& dict,
    const fileName& casePath
)
:
    casePath_(casePath),
    names_(),
    files_(),
    entries_(),
    values_(),
    sds_(),
    correlation_(),
    confidence_(0.95),
    stepFraction_(1),
    caseDicts_()
{
    const bool fromFit = dict.found("fitPosterior");
    if (fromFit && (dict.found("parameters") || dict.found("correlation")))
    {
        FatalIOErrorInFunction(dict)
            << "uncertainty: keyword 'fitPosterior' (the parameters and"
            << " their correlation from a hearthFit posterior file) or"
            << " keywords 'parameters' and 'correlation' (written here),"
            << " not both" << nl << exit(FatalIOError);
    }
    checkedRead::checkKeywords
    (
        dict,
        fromFit
      ? wordList({"fitPosterior", "confidence", "stepFraction"})
      : wordList({"parameters", "correlation", "confidence", "stepFraction"}),
        "uncertainty"
    );

    if (fromFit)
    {
        fileName file(dict.get<fileName>("fitPosterior"));
        file.expand();
        if (!file.isAbsolute())
        {
            file = casePath/file;
        }
        file.clean();
        if (!isFile(file))
        {
            FatalIOErrorInFunction(dict)
                << "Keyword 'fitPosterior': cannot read " << file
                << " (hearthFit writes <workDir>/posterior.dict; a path"
                << " relative to the case or absolute)" << nl
                << exit(FatalIOError);
        }
        // Duplicate keywords refused, an overflowing number (1e400) read
        // as inf and refused by checkNumbers below (not a SIGFPE)
        const dictionary post(checkedRead::readWithoutDuplicates(file));
        checkedRead::checkKeywords
        (
            post,
            wordList({"converged", "parameters", "correlation"}),
            "hearthFit posterior"
        );
        if (!post.get<bool>("converged"))
        {
            FatalIOErrorInFunction(post)
                << "hearthFit posterior " << file << ": keyword 'converged'"
                << " is false: the fit did not converge, its covariance is"
                << " not a posterior (rerun or resume the fit until it"
                << " converges)" << nl << exit(FatalIOError);
        }
        if (!post.isDict("parameters") || !post.found("correlation"))
        {
            FatalIOErrorInFunction(post)
                << "hearthFit posterior " << file << ": missing keyword '"
                << (post.isDict("parameters") ? "correlation" : "parameters")
                << "' (expected parameters { name { file ...; entry ...;"
                << " value ...; sd ...; } ... } and correlation (...);"
                << " as hearthFit writes them)" << nl
                << exit(FatalIOError);
        }
        readParameters(post.subDict("parameters"), true);
        readCorrelation(post);
    }
    else
    {
        if (!dict.isDict("parameters"))
        {
            FatalIOErrorInFunction(dict)
                << "uncertainty: missing sub-dictionary 'parameters' (name"
                << " { file <relative to the case>; entry <keyword path>;"
                << " sd <standard deviation>; } entries) or keyword"
                << " fitPosterior (a hearthFit posterior file)" << nl
                << exit(FatalIOError);
        }
        readParameters(dict.subDict("parameters"), false);
        readCorrelation(dict);
    }

    confidence_ =
        checkedRead::getOrDefault
        (
            dict, "confidence", dimless, 0.95, validRange{0, 1, true, true}
        ).value();
    stepFraction_ =
        checkedRead::getOrDefault
        (
            dict, "stepFraction", dimless, 1, validRange{0, 1, true, false}
        ).value();

    // The first-order propagation differentiates over value -/+
    // stepFraction sd: a step across zero (an sd of the size of the value)
    // would run the model with a property of the wrong sign, and a
    // linearisation over it means nothing
    forAll(names_, j)
    {
        const scalar step = stepFraction_*sds_[j];
        if (values_[j] != 0 && step >= mag(values_[j]))
        {
            FatalIOErrorInFunction(dict)
                << "uncertain parameter " << names_[j] << ": value "
                << values_[j] << " -/+ stepFraction x sd = " << step
                << " changes sign (sd " << sds_[j] << ", stepFraction "
                << stepFraction_ << "): a first-order interval needs an sd"
                << " well below the value; lower keyword 'stepFraction'"
                << " in (0, " << mag(values_[j])/sds_[j] << ") or"
                << " constrain the parameter better" << nl
                << exit(FatalIOError);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalarSquareMatrix Foam::uncertainParameters::covariance() const
{
    const label n = size();
    scalarSquareMatrix C(n, Zero);
    for (label i = 0; i < n; ++i)
    {
        for (label j = 0; j < n; ++j)
        {
            C(i, j) = sds_[i]*sds_[j]*correlation_(i, j);
        }
    }
    return C;
}


Foam::scalar Foam::uncertainParameters::variance(const scalarField& g) const
{
    const scalarSquareMatrix C(covariance());
    scalar v = 0;
    for (label i = 0; i < size(); ++i)
    {
        for (label j = 0; j < size(); ++j)
        {
            v += g[i]*C(i, j)*g[j];
        }
    }
    return v;
}


Foam::scalar Foam::uncertainParameters::quantile() const
{
    return gsl_cdf_ugaussian_Pinv(0.5*(1 + confidence_));
}


void Foam::uncertainParameters::write
(
    const fileName& copyPath,
    const label j,
    const scalar value
) const
{
    dictionary d(caseDicts_[files_[j]]);
    word key;
    scratchCase::parentDict(d, entries_[j], key)->set(key, value);
    scratchCase::writeDictionary
    (
        copyPath/files_[j],
        d,
        "The case's file with the uncertain parameter " + names_[j]
      + " perturbed"
    );
}


void Foam::uncertainParameters::restore(const fileName& copyPath) const
{
    for (const fileName& file : caseDicts_.toc())
    {
        if (!cp(casePath_/file, copyPath/file))
        {
            FatalErrorInFunction
                << "Cannot copy " << casePath_/file << " to "
                << copyPath/file << exit(FatalError);
        }
    }
}


// ************************************************************************* //
