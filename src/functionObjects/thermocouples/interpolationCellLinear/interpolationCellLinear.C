/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "interpolationCellLinear.H"
#include "gaussGrad.H"
#include "linear.H"
#include "polyPatch.H"
#include "zeroGradientFvPatchField.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class Type>
void Foam::interpolationCellLinear<Type>::calcGrad()
{
    const GeometricField<Type, fvPatchField, volMesh>& psi = this->psi_;
    const fvMesh& mesh = psi.mesh();

    // Gauss gradient: linear face values inside and across processor
    // faces, the patch values on boundary faces (empty patches have none)
    grad_ =
        fv::gaussGrad<Type>::gradf
        (
            linearInterpolate(psi),
            "cellLinear(" + psi.name() + ')'
        )().primitiveField();

    const volVectorField& C = mesh.C();

    boundaryNormals_.setSize(mesh.nCells());

    for (const fvPatchField<Type>& pf : psi.boundaryField())
    {
        const fvPatch& p = pf.patch();

        if
        (
            p.coupled()
         || pf.empty()
         || polyPatch::constraintType(p.patch().type())
        )
        {
            continue;
        }

        const labelUList& faceCells = p.faceCells();

        // A zeroGradient patch (adiabatic side or far boundary) does not
        // make its cells boundary cells: its face values are the cell
        // values, as cellPoint's point values there
        const vectorField nf(p.nf());

        if (!isA<zeroGradientFvPatchField<Type>>(pf))
        {
            forAll(faceCells, i)
            {
                boundaryNormals_[faceCells[i]].append(nf[i]);
            }
        }

        const vectorField& Cf = p.Cf();

        forAll(pf, i)
        {
            const label celli = faceCells[i];
            const vector& n = nf[i];
            const scalar d = n & (Cf[i] - C[celli]);

            if (d > ROOTVSMALL)
            {
                GradType& g = grad_[celli];
                g += n*((pf[i] - psi[celli])/d - (n & g));
            }
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class Type>
Foam::interpolationCellLinear<Type>::interpolationCellLinear
(
    const GeometricField<Type, fvPatchField, volMesh>& psi
)
:
    interpolation<Type>(psi),
    cellPoint_(psi),
    boundaryNormals_(),
    grad_()
{
    calcGrad();
}


// * * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

template<class Type>
Type Foam::interpolationCellLinear<Type>::interpolate
(
    const vector& position,
    const label celli,
    const label facei
) const
{
    const vector dx(position - this->pMesh_.cellCentres()[celli]);

    // Linear between the cell centre and a physical boundary face of the
    // cell (the point on the face's side of the centre)
    for (const vector& n : boundaryNormals_[celli])
    {
        if ((n & dx) >= 0)
        {
            return this->psi_[celli] + (dx & grad_[celli]);
        }
    }

    return cellPoint_.interpolate(position, celli, facei);
}


// ************************************************************************* //
