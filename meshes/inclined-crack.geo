// Plate with an inclined centre crack, pulled by clamped grips: the mesh of the global (XFEM)
// solver. The crack is not part of the mesh; the solver enriches across it.
//
// Units: m. Width W = 0.1 (x from -W/2 to W/2), length H = 2 W between the grips (y from -W to
// W); the crack's centre at the origin (prm/inclined-crack.prm).
//
// Mesh: first-order quadrilaterals only. gmsh meshes triangles of size 2 h, recombines them
// (blossom) and subdivides every element once: quads of edge about h in the band |y| < W/4 where
// the crack runs, graded to grip_factor h towards the grips.
//
// Variables (override with gmsh -setnumber <name> <value>):
//   h            quad edge length in the crack band, m (default 0.0025)
//   grip_factor  cell size near the grips relative to h (default 2)
//
// Physical groups, named for the scene files:
//   Surface "plate"
//   Curves "bottom grip" (y = -W), "right" (x = W/2), "top grip" (y = W), "left" (x = -W/2)

If (!Exists(h))
  h = 0.0025;
EndIf
If (!Exists(grip_factor))
  grip_factor = 2;
EndIf

width = 0.1;
lc    = 2 * h;

Point(1) = {-width / 2, -width, 0, grip_factor * lc};
Point(2) = {width / 2, -width, 0, grip_factor * lc};
Point(3) = {width / 2, width, 0, grip_factor * lc};
Point(4) = {-width / 2, width, 0, grip_factor * lc};

Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};

Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

Field[1] = Box;
Field[1].VIn = lc;
Field[1].VOut = grip_factor * lc;
Field[1].XMin = -1;
Field[1].XMax = 1;
Field[1].YMin = -width / 4;
Field[1].YMax = width / 4;
Field[1].Thickness = width / 2;
Background Field = 1;
Mesh.CharacteristicLengthExtendFromBoundary = 0;

Physical Surface("plate", 1) = {1};
Physical Curve("bottom grip", 1) = {1};
Physical Curve("right", 2) = {2};
Physical Curve("top grip", 3) = {3};
Physical Curve("left", 4) = {4};

Mesh.ElementOrder = 1;
Mesh.Algorithm = 6;
Mesh.RecombineAll = 1;
Mesh.RecombinationAlgorithm = 1;
Mesh.SubdivisionAlgorithm = 1;
Mesh.Smoothing = 5;
Mesh.MshFileVersion = 2.2;
