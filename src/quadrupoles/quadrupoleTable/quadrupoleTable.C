/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "quadrupoleTable.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "error.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::quadrupoleTable::quadrupoleTable(const quadrupoleInput& input)
:
    input_(input),
    nPairs_(0)
{
    const quadrupole::layeredSoil soil
    (
        input.layers(), input.substrate(), input.depths()
    );
    const quadrupole::historyResponse response
    (
        soil, input.condition(), input.inversion()
    );
    try
    {
        rise_ = response.rise(input.history(), input.times(), nPairs_);
    }
    catch (const std::exception& err)
    {
        FatalErrorInFunction
            << "Laplace inversion failed: " << err.what() << nl
            << exit(FatalError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::quadrupoleTable::write(const fileName& file) const
{
    const auto sig = &quadrupoleInput::sig;
    const std::vector<quadrupole::real>& times = input_.times();

    mkDir(file.path());
    OFstream os(file);
    if (!os.good())
    {
        FatalErrorInFunction
            << "Cannot write " << file << nl << exit(FatalError);
    }
    os  << "time_s,T_surface";
    for (const quadrupole::real d : input_.depths())
    {
        os  << ",T_" << sig(d, 10).c_str() << 'm';
    }
    os  << nl;
    for (size_t n = 0; n < times.size(); ++n)
    {
        os  << sig(times[n], 12).c_str();
        for (size_t j = 0; j < rise_.size(); ++j)
        {
            os  << ','
                << sig(input_.initialTemperature() + rise_[j][n], 12).c_str();
        }
        os  << nl;
    }
}


// ************************************************************************* //
