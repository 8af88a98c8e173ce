/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "constantGasPermeability.H"
#include "addToRunTimeSelectionTable.H"
#include "checkedRead.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace gasPermeabilityModels
{
    defineTypeNameAndDebug(constant, 0);
    addToRunTimeSelectionTable(gasPermeabilityModel, constant, dictionary);
}
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::gasPermeabilityModels::constant::constant(const dictionary& coeffs)
:
    gasPermeabilityModel(coeffs),
    Kg_
    (
        checkedRead::get(coeffs, "Kg", dimArea, checkedRead::positive())
       .value()
    )
{}

// ************************************************************************* //
