// Ingraffea & Grigoriu three-point-bending PMMA beam without holes (Case I): the mesh of the
// global (XFEM) solver. The initial crack is not part of the mesh; the solver enriches across it.
//
// Units: m. Origin at the bottom-left corner; the beam is [0, 0.508] x [0, 0.2032].
// Mesh vertices (geometry points splitting the edges): supports at x = 0.0254 and x = 0.4826
// on the bottom edge, load point at x = 0.254 on the top edge (DESIGN.md, "Units and conventions").
//
// Mesh: first-order quadrilaterals only. gmsh meshes triangles of size 2 h, recombines them
// (blossom) and subdivides every element once (Mesh.SubdivisionAlgorithm = 1), which
// guarantees an all-quad mesh with edges of about h. Cells are h * crack_zone_factor in the band
// x in [0.0762, 0.2667] where the cracks of Cases I-III run (from the notches at x = 0.1016 and
// 0.127 towards the holes and the load point); the solver refines further near the tips.
//
// Variables (override with gmsh -setnumber <name> <value>):
//   h                  quad edge length away from the crack band, m (default 0.008)
//   crack_zone_factor  cell size in the crack band relative to h (default 0.5; 1 = uniform)
//
// Physical groups, named for the scene files (prm/ingraffea-*.prm refer to them by name):
//   Surface "beam"
//   Curves "bottom" (y = 0), "right" (x = 0.508), "top" (y = 0.2032), "left" (x = 0)
//   Points "pin" (0.0254, 0), "roller" (0.4826, 0), "load" (0.254, 0.2032)
//
// Example: gmsh -2 -setnumber h 0.004 -format msh2 ingraffea-beam.geo -o beam.msh

If (!Exists(h))
  h = 0.008;
EndIf
If (!Exists(crack_zone_factor))
  crack_zone_factor = 0.5;
EndIf

length = 0.508;
height = 0.2032;
x_support_left = 0.0254;
x_support_right = 0.4826;
x_load = 0.254;

// Triangle size before the subdivision halves every edge.
lc = 2 * h;

Point(1) = {0, 0, 0, lc};
Point(2) = {x_support_left, 0, 0, lc};
Point(3) = {x_support_right, 0, 0, lc};
Point(4) = {length, 0, 0, lc};
Point(5) = {length, height, 0, lc};
Point(6) = {x_load, height, 0, lc};
Point(7) = {0, height, 0, lc};

Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 6};
Line(6) = {6, 7};
Line(7) = {7, 1};

Curve Loop(1) = {1, 2, 3, 4, 5, 6, 7};
Plane Surface(1) = {1};

// Finer cells in the band where the cracks run, graded to lc over 0.0254 m.
Field[1] = Box;
Field[1].VIn = crack_zone_factor * lc;
Field[1].VOut = lc;
Field[1].XMin = 0.0762;
Field[1].XMax = 0.2667;
Field[1].YMin = -1;
Field[1].YMax = 1;
Field[1].Thickness = 0.0254;
Background Field = 1;

Physical Surface("beam", 1) = {1};
Physical Curve("bottom", 1) = {1, 2, 3};
Physical Curve("right", 2) = {4};
Physical Curve("top", 3) = {5, 6};
Physical Curve("left", 4) = {7};
Physical Point("pin", 11) = {2};
Physical Point("roller", 12) = {3};
Physical Point("load", 13) = {6};

Mesh.ElementOrder = 1;
Mesh.Algorithm = 6;               // Frontal-Delaunay (8, Frontal-Delaunay for quads, crashes in 4.8.4)
Mesh.RecombineAll = 1;
Mesh.RecombinationAlgorithm = 1;  // blossom
Mesh.SubdivisionAlgorithm = 1;    // all quadrangles
Mesh.Smoothing = 5;
Mesh.MshFileVersion = 2.2;        // what dealii::GridIn<2>::read_msh is called with
