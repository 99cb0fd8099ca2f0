// Single-edge-notch tension (SENT, SE(T)) specimen with clamped grips: the mesh of the global
// (XFEM) solver. The crack is not part of the mesh; the solver enriches across it.
//
// Units: m. Width W = 0.1 (x from 0, the cracked edge, to W), daylight length between the grips
// H = 10 W (y from -H/2 to H/2; the proportions of BS 8571 and DNV-RP-F108). The crack plane is
// y = 0, the crack mouth on the left edge.
//
// Mesh: first-order quadrilaterals only. gmsh meshes triangles of size 2 h, recombines them
// (blossom) and subdivides every element once (Mesh.SubdivisionAlgorithm = 1): quads of edge
// about h in the band |y| < W around the crack plane, graded to grip_factor h towards the grips
// over W.
//
// Variables (override with gmsh -setnumber <name> <value>):
//   h            quad edge length in the crack band, m (default 0.0025)
//   grip_factor  cell size near the grips relative to h (default 4)
//
// Physical groups, named for the scene files (prm/sent*.prm refer to them by name):
//   Surface "specimen"
//   Curves "bottom grip" (y = -H/2), "right" (x = W), "top grip" (y = H/2), "left" (x = 0)
//
// Example: gmsh -2 -setnumber h 0.00125 -format msh2 sent.geo -o sent.msh

If (!Exists(h))
  h = 0.0025;
EndIf
If (!Exists(grip_factor))
  grip_factor = 4;
EndIf

width  = 0.1;
length = 10 * width;

// Triangle sizes before the subdivision halves every edge.
lc = 2 * h;

Point(1) = {0, -length / 2, 0, grip_factor * lc};
Point(2) = {width, -length / 2, 0, grip_factor * lc};
Point(3) = {width, length / 2, 0, grip_factor * lc};
Point(4) = {0, length / 2, 0, grip_factor * lc};

Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};

Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

// Cells of lc in the band |y| < W, graded to grip_factor lc over W.
Field[1] = Box;
Field[1].VIn = lc;
Field[1].VOut = grip_factor * lc;
Field[1].XMin = -1;
Field[1].XMax = 1;
Field[1].YMin = -width;
Field[1].YMax = width;
Field[1].Thickness = width;
Background Field = 1;
Mesh.CharacteristicLengthExtendFromBoundary = 0;

Physical Curve("bottom grip", 1) = {1};
Physical Curve("right", 2) = {2};
Physical Curve("top grip", 3) = {3};
Physical Curve("left", 4) = {4};

Mesh.ElementOrder = 1;
Mesh.Algorithm = 6;               // Frontal-Delaunay (8, Frontal-Delaunay for quads, crashes in 4.8.4)
Mesh.RecombineAll = 1;
Mesh.RecombinationAlgorithm = 1;  // blossom
Mesh.SubdivisionAlgorithm = 1;    // all quadrangles
Mesh.Smoothing = 5;
Mesh.MshFileVersion = 2.2;        // what dealii::GridIn<2>::read_msh is called with
