// A strip with a central circular hole, pulled along its length: where a crack starts with no
// crack there (prm/plate-hole.prm). The mesh of the global (XFEM) solver.
//
// Units: m. Origin at the bottom-left corner; the strip is [0, 0.1] x [0, 0.2] minus the hole of
// radius 0.01 centred at (0.05, 0.1): d / W = 0.2, ten radii of strip above and below the hole.
//
// Mesh: first-order quadrilaterals only. gmsh meshes triangles of size 2 h, recombines them
// (blossom) and subdivides every element once (Mesh.SubdivisionAlgorithm = 1): quads of edge about
// h away from the hole, hole_factor h on its rim, graded over one diameter. The rim is a polygon
// whose vertices lie on the circle (the body recovers the circle from them, basics/body.h): four
// quarter arcs through the points east, north, west and south of the centre, so that the points
// of the largest hoop stress under the tension (east and west) are mesh vertices.
//
// Variables (override with gmsh -setnumber <name> <value>):
//   h            quad edge length away from the hole, m (default 0.005)
//   hole_factor  cell size on the rim relative to h (default 0.2)
//
// Physical groups, named for the scene files:
//   Surface "plate"
//   Curves "bottom" (y = 0), "right" (x = 0.1), "top" (y = 0.2), "left" (x = 0), "hole" (the rim)
//   Points "bottom left" (0, 0), "bottom right" (0.1, 0)
//
// Example: gmsh -2 -setnumber h 0.005 -format msh2 plate-hole.geo -o plate-hole.msh

If (!Exists(h))
  h = 0.005;
EndIf
If (!Exists(hole_factor))
  hole_factor = 0.2;
EndIf

width = 0.1;
height = 0.2;
hole_x = 0.05;
hole_y = 0.1;
hole_radius = 0.01;

// Triangle sizes before the subdivision halves every edge.
lc = 2 * h;
lc_hole = hole_factor * lc;

Point(1) = {0, 0, 0, lc};
Point(2) = {width, 0, 0, lc};
Point(3) = {width, height, 0, lc};
Point(4) = {0, height, 0, lc};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};

Point(10) = {hole_x, hole_y, 0, lc_hole};
Point(11) = {hole_x + hole_radius, hole_y, 0, lc_hole};
Point(12) = {hole_x, hole_y + hole_radius, 0, lc_hole};
Point(13) = {hole_x - hole_radius, hole_y, 0, lc_hole};
Point(14) = {hole_x, hole_y - hole_radius, 0, lc_hole};
Circle(11) = {11, 10, 12};
Circle(12) = {12, 10, 13};
Circle(13) = {13, 10, 14};
Circle(14) = {14, 10, 11};
Curve Loop(2) = {11, 12, 13, 14};

Plane Surface(1) = {1, 2};

// lc_hole on the rim, growing linearly to lc over one diameter.
Field[1] = Distance;
Field[1].CurvesList = {11, 12, 13, 14};
Field[1].NumPointsPerCurve = 200;
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = lc_hole;
Field[2].SizeMax = lc;
Field[2].DistMin = 0;
Field[2].DistMax = 2 * hole_radius;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;

Physical Surface("plate", 1) = {1};
Physical Curve("bottom", 1) = {1};
Physical Curve("right", 2) = {2};
Physical Curve("top", 3) = {3};
Physical Curve("left", 4) = {4};
Physical Curve("hole", 5) = {11, 12, 13, 14};
Physical Point("bottom left", 11) = {1};
Physical Point("bottom right", 12) = {2};

Mesh.ElementOrder = 1;
Mesh.Algorithm = 6;               // Frontal-Delaunay (8, Frontal-Delaunay for quads, crashes in 4.8.4)
Mesh.RecombineAll = 1;
Mesh.RecombinationAlgorithm = 1;  // blossom
Mesh.SubdivisionAlgorithm = 1;    // all quadrangles
Mesh.Smoothing = 5;
Mesh.MshFileVersion = 2.2;        // what dealii::GridIn<2>::read_msh is called with
