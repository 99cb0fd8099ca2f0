// A square plate, large against the centre cracks of the tests (short-crack.prm and its kin in
// tests/coupling/bad_prm): quads of edge about h in the square |x|, |y| < 0.01 at the centre,
// graded to far_factor h at the edges.
//
// Units: m. The plate is [-0.1, 0.1] x [-0.1, 0.1].
//
// Variables (override with gmsh -setnumber <name> <value>):
//   h           quad edge length at the centre, m (default 0.001)
//   far_factor  cell size at the edges relative to h (default 10)
//
// Physical groups: Surface "plate"; Curves "bottom", "right", "top", "left"; Point "anchor"
// (-0.1, -0.1), the bottom-left corner.

If (!Exists(h))
  h = 0.001;
EndIf
If (!Exists(far_factor))
  far_factor = 10;
EndIf

half = 0.1;
lc   = 2 * h; // triangle size before the subdivision halves every edge

Point(1) = {-half, -half, 0, far_factor * lc};
Point(2) = {half, -half, 0, far_factor * lc};
Point(3) = {half, half, 0, far_factor * lc};
Point(4) = {-half, half, 0, far_factor * lc};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

Field[1] = Box;
Field[1].VIn = lc;
Field[1].VOut = far_factor * lc;
Field[1].XMin = -0.01;
Field[1].XMax = 0.01;
Field[1].YMin = -0.01;
Field[1].YMax = 0.01;
Field[1].Thickness = 0.04;
Background Field = 1;
Mesh.CharacteristicLengthExtendFromBoundary = 0;

Physical Surface("plate", 1) = {1};
Physical Curve("bottom", 1) = {1};
Physical Curve("right", 2) = {2};
Physical Curve("top", 3) = {3};
Physical Curve("left", 4) = {4};
Physical Point("anchor", 11) = {1};

Mesh.ElementOrder = 1;
Mesh.Algorithm = 6;
Mesh.RecombineAll = 1;
Mesh.RecombinationAlgorithm = 1;
Mesh.SubdivisionAlgorithm = 1;
Mesh.Smoothing = 5;
Mesh.MshFileVersion = 2.2;
