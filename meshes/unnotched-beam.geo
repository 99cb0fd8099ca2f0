// An unnotched beam in three-point bending: where a crack starts with no crack there
// (prm/unnotched-beam.prm). The mesh of the global (XFEM) solver.
//
// Units: m. Origin at the bottom-left corner; the beam is [0, 0.44] x [0, 0.05]: span S = 0.4
// between the supports at x = 0.02 and 0.42 on the bottom edge, depth D = 0.05 (S / D = 8), the
// load point at mid-span on the top edge, x = 0.22. Supports and load point are mesh vertices.
//
// Mesh: a structured grid of square quadrilaterals of edge h (transfinite): round(D / h) cells
// over the depth, the supports and the load point on grid lines.
//
// Variables (override with gmsh -setnumber <name> <value>):
//   h  quad edge length, m (default 0.0025; 0.02 / h and 0.2 / h whole numbers keep the cells square)
//
// Physical groups, named for the scene files:
//   Surface "beam"
//   Curves "bottom" (y = 0), "right" (x = 0.44), "top" (y = 0.05), "left" (x = 0)
//   Points "pin" (0.02, 0), "roller" (0.42, 0), "load" (0.22, 0.05)
//
// Example: gmsh -2 -setnumber h 0.0025 -format msh2 unnotched-beam.geo -o beam.msh

If (!Exists(h))
  h = 0.0025;
EndIf

overhang = 0.02;
span = 0.4;
depth = 0.05;
length = span + 2 * overhang;

Point(1) = {0, 0, 0};
Point(2) = {overhang, 0, 0};
Point(3) = {overhang + span, 0, 0};
Point(4) = {length, 0, 0};
Point(5) = {length, depth, 0};
Point(6) = {length / 2, depth, 0};
Point(7) = {0, depth, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 6};
Line(6) = {6, 7};
Line(7) = {7, 1};
Curve Loop(1) = {1, 2, 3, 4, 5, 6, 7};
Plane Surface(1) = {1};

// Cells per piece: the bottom's pieces and the top's halves hold the same number in all.
n_overhang = Floor(overhang / h + 0.5);
n_half_span = Floor(span / 2 / h + 0.5);
n_depth = Floor(depth / h + 0.5);
Transfinite Curve{1, 3} = n_overhang + 1;
Transfinite Curve{2} = 2 * n_half_span + 1;
Transfinite Curve{5, 6} = n_overhang + n_half_span + 1;
Transfinite Curve{4, 7} = n_depth + 1;
Transfinite Surface{1} = {1, 4, 5, 7};
Recombine Surface{1};

Physical Surface("beam", 1) = {1};
Physical Curve("bottom", 1) = {1, 2, 3};
Physical Curve("right", 2) = {4};
Physical Curve("top", 3) = {5, 6};
Physical Curve("left", 4) = {7};
Physical Point("pin", 11) = {2};
Physical Point("roller", 12) = {3};
Physical Point("load", 13) = {6};

Mesh.ElementOrder = 1;
Mesh.MshFileVersion = 2.2;        // what dealii::GridIn<2>::read_msh is called with
