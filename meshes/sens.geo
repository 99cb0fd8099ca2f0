// Single-edge-notch shear (SENS) square, after Miehe, Hofacker & Welschinger (2010) scaled to
// 0.1 m: the mesh of the global (XFEM) solver. The notch is not part of the mesh; the solver
// enriches across the crack of the scene file (prm/sens.prm: from the middle of the left edge to
// the centre).
//
// Units: m. Origin at the bottom-left corner; the plate is [0, 0.1] x [0, 0.1].
//
// Mesh: first-order quadrilaterals only. gmsh meshes triangles of size 2 h, recombines them
// (blossom) and subdivides every element once (Mesh.SubdivisionAlgorithm = 1): an all-quad mesh
// with edges of about h. Cells are h * crack_zone_factor in the lower right quarter around the
// centre, where the crack runs (down to the right, towards the bottom-right corner); the solver
// refines further near the tip.
//
// Variables (override with gmsh -setnumber <name> <value>):
//   h                  quad edge length away from the crack zone, m (default 0.004)
//   crack_zone_factor  cell size in the crack zone relative to h (default 0.5; 1 = uniform)
//
// Physical groups, named for the scene files:
//   Surface "plate"
//   Curves "bottom" (y = 0), "right" (x = 0.1), "top" (y = 0.1), "left" (x = 0)
//
// Example: gmsh -2 -setnumber h 0.002 -format msh2 sens.geo -o sens.msh

If (!Exists(h))
  h = 0.004;
EndIf
If (!Exists(crack_zone_factor))
  crack_zone_factor = 0.5;
EndIf

side = 0.1;

// Triangle size before the subdivision halves every edge.
lc = 2 * h;

Point(1) = {0, 0, 0, lc};
Point(2) = {side, 0, 0, lc};
Point(3) = {side, side, 0, lc};
Point(4) = {0, side, 0, lc};

Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};

Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

// Finer cells where the crack runs: from the centre down to the right, graded to lc over 0.01 m.
Field[1] = Box;
Field[1].VIn = crack_zone_factor * lc;
Field[1].VOut = lc;
Field[1].XMin = 0.04;
Field[1].XMax = 1;
Field[1].YMin = -1;
Field[1].YMax = 0.06;
Field[1].Thickness = 0.01;
Background Field = 1;

Physical Surface("plate", 1) = {1};
Physical Curve("bottom", 1) = {1};
Physical Curve("right", 2) = {2};
Physical Curve("top", 3) = {3};
Physical Curve("left", 4) = {4};

Mesh.ElementOrder = 1;
Mesh.Algorithm = 6;               // Frontal-Delaunay (8, Frontal-Delaunay for quads, crashes in 4.8.4)
Mesh.RecombineAll = 1;
Mesh.RecombinationAlgorithm = 1;  // blossom
Mesh.SubdivisionAlgorithm = 1;    // all quadrangles
Mesh.Smoothing = 5;
Mesh.MshFileVersion = 2.2;        // what dealii::GridIn<2>::read_msh is called with
