/*--------------------------------*- C++ -*----------------------------------*\
  hearthFoam mesh template: rectangularPit, 'symmetry full'
\*---------------------------------------------------------------------------*/
FoamFile
{
    version     2.0;
    format      ascii;
    class       dictionary;
    object      mirrorMeshDict;
}
// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

// Mirror the mesh about the plane through the origin normal to y
// (Allmesh: mirrorMesh -overwrite -dict system/mirrorMeshDict.y)

planeType       pointAndNormal;
pointAndNormalDict
{
    point       (0 0 0);
    normal      (0 1 0);
}
planeTolerance  1e-6;   // [m] points closer to the plane are merged

// ************************************************************************* //
