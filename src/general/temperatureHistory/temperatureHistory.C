/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "temperatureHistory.H"
#include "error.H"
#include "OFstream.H"

#include <algorithm>
#include <cmath>
#include <sstream>

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::temperatureHistory::clear()
{
    times_.clear();
    temperatures_.clear();
    lines_.clear();
}


Foam::temperatureHistory::check Foam::temperatureHistory::append
(
    const scalar t,
    const scalar T,
    const label line
)
{
    if (!std::isfinite(t) || !std::isfinite(T))
    {
        return check::notFinite;
    }
    if (!(T > 0))
    {
        return check::notAboveZero;
    }
    const label n = times_.size();
    if (n && !(t > times_[n - 1]))
    {
        return t == times_[n - 1] ? check::sameTime : check::timeBefore;
    }

    times_.append(t);
    temperatures_.append(T);
    lines_.append(line);
    return check::ok;
}


Foam::scalar Foam::temperatureHistory::value(const scalar t) const
{
    const label n = times_.size();

    if (!n)
    {
        FatalErrorInFunction
            << "Empty temperature history" << exit(FatalError);
    }

    if (t <= times_[0])
    {
        return temperatures_[0];
    }
    if (t >= times_[n - 1])
    {
        return temperatures_[n - 1];
    }

    // times_[i] <= t < times_[i+1]
    const label i =
        label(std::upper_bound(times_.cbegin(), times_.cend(), t)
      - times_.cbegin()) - 1;

    if (t == times_[i])
    {
        return temperatures_[i];
    }

    const scalar s = (t - times_[i])/(times_[i + 1] - times_[i]);
    return temperatures_[i] + s*(temperatures_[i + 1] - temperatures_[i]);
}


void Foam::temperatureHistory::writeTableFile
(
    const fileName& file,
    const std::string& comment,
    const scalar timeShift,
    const label precision
) const
{
    OFstream os(file);
    os.precision(precision);

    std::istringstream lines(comment);
    std::string line;
    while (std::getline(lines, line))
    {
        os  << "// " << line.c_str() << nl;
    }

    os  << times_.size() << nl << '(' << nl;
    forAll(times_, i)
    {
        os  << "    (" << timeShift + times_[i] << ' ' << temperatures_[i]
            << ')' << nl;
    }
    os  << ')' << nl;
}


// ************************************************************************* //
