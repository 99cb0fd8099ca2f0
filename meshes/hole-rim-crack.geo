// Square plate with a central hole, for a crack that leaves the hole's rim (prm/hole-rim-crack.prm:
// the crack's mouth on the rim at 3 o'clock, its tip 10 mm out towards the right edge): the mesh
// of the global (XFEM) solver. The crack is not part of the mesh; the solver enriches across it.
//
// Units: m. Origin at the bottom-left corner; the plate is [0, 0.2] x [0, 0.2] minus the hole of
// radius 0.02 centred at (0.1, 0.1).
//
// Mesh: first-order quadrilaterals only. gmsh meshes triangles of size 2 h, recombines them
// (blossom) and subdivides every element once (Mesh.SubdivisionAlgorithm = 1): an all-quad mesh
// with edges of about h. Cells are h * crack_zone_factor in the band 0.06 < y < 0.14 right of
// the hole, where the crack runs; the solver refines further near the tip. The hole's rim is a
// polygon of at least hole_segments straight edges whose vertices lie on the circle (the body
// recovers the circle from them, basics/body.h): four quarter arcs through the points east, north,
// west and south of the centre, so that the crack's mouth (0.12, 0.1) is a mesh vertex.
//
// Variables (override with gmsh -setnumber <name> <value>):
//   h                  quad edge length away from the crack band, m (default 0.008)
//   crack_zone_factor  cell size in the crack band relative to h (default 0.5; 1 = uniform)
//   hole_segments      minimum number of mesh edges on the hole's rim (default 32)
//
// Physical groups, named for the scene files:
//   Surface "plate"
//   Curves "bottom" (y = 0), "right" (x = 0.2), "top" (y = 0.2), "left" (x = 0), "hole" (the rim)
//   Points "anchor" (0, 0), the bottom-left corner
//
// Example: gmsh -2 -setnumber h 0.004 -format msh2 hole-rim-crack.geo -o hole-rim-crack.msh

If (!Exists(h))
  h = 0.008;
EndIf
If (!Exists(crack_zone_factor))
  crack_zone_factor = 0.5;
EndIf
If (!Exists(hole_segments))
  hole_segments = 32;
EndIf

side = 0.2;
hole_x = 0.1;
hole_y = 0.1;
hole_radius = 0.02;

// Triangle sizes before the subdivision halves every edge.
lc = 2 * h;
lc_hole = Min(crack_zone_factor * lc, 2 * (2 * Pi * hole_radius / hole_segments));

Point(1) = {0, 0, 0, lc};
Point(2) = {side, 0, 0, lc};
Point(3) = {side, side, 0, lc};
Point(4) = {0, side, 0, lc};

Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};

// The rim: four quarter arcs through the points east, north, west and south of the centre.
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

// Finer cells in the band where the crack runs, graded to lc over 0.02 m.
Field[1] = Box;
Field[1].VIn = crack_zone_factor * lc;
Field[1].VOut = lc;
Field[1].XMin = hole_x;
Field[1].XMax = 1;
Field[1].YMin = hole_y - 0.04;
Field[1].YMax = hole_y + 0.04;
Field[1].Thickness = 0.02;
Background Field = 1;

Physical Surface("plate", 1) = {1};
Physical Curve("bottom", 1) = {1};
Physical Curve("right", 2) = {2};
Physical Curve("top", 3) = {3};
Physical Curve("left", 4) = {4};
Physical Curve("hole", 5) = {11, 12, 13, 14};
Physical Point("anchor", 11) = {1};

Mesh.ElementOrder = 1;
Mesh.Algorithm = 6;               // Frontal-Delaunay (8, Frontal-Delaunay for quads, crashes in 4.8.4)
Mesh.RecombineAll = 1;
Mesh.RecombinationAlgorithm = 1;  // blossom
Mesh.SubdivisionAlgorithm = 1;    // all quadrangles
Mesh.Smoothing = 5;
Mesh.MshFileVersion = 2.2;        // what dealii::GridIn<2>::read_msh is called with
