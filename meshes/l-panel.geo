// L-shaped panel after Winkler, Hofstetter & Niederwanger (2001), scaled as tested: the mesh of
// the global (XFEM) solver. A 0.5 m square without its lower-right quarter; the re-entrant corner
// at (0.25, 0.25) is where the crack starts (prm/l-panel.prm: a short pre-crack from the corner).
// The crack is not part of the mesh; the solver enriches across it.
//
// Units: m. Origin at the bottom-left corner. Outline, counter-clockwise: (0, 0), (0.25, 0),
// (0.25, 0.25) (the re-entrant corner), (0.5, 0.25), (0.5, 0.5), (0, 0.5).
// Mesh vertex (a geometry point splitting the arm's lower edge): the load point (0.47, 0.25),
// 30 mm from the arm's end, as in the test.
//
// Mesh: first-order quadrilaterals only. gmsh meshes triangles of size 2 h, recombines them
// (blossom) and subdivides every element once (Mesh.SubdivisionAlgorithm = 1): an all-quad mesh
// with edges of about h. Cells are h * crack_zone_factor within 0.1 m of the corner, to its
// left and above it, where the crack runs (towards the left edge, curving up); the solver refines
// further near the tip.
//
// Variables (override with gmsh -setnumber <name> <value>):
//   h                  quad edge length away from the crack zone, m (default 0.01)
//   crack_zone_factor  cell size in the crack zone relative to h (default 0.5; 1 = uniform)
//
// Physical groups, named for the scene files:
//   Surface "panel"
//   Curves "bottom" (y = 0, the held edge), "cutout-side" (x = 0.25, y < 0.25), "arm-bottom"
//          (y = 0.25, x > 0.25), "arm-end" (x = 0.5), "top" (y = 0.5), "left" (x = 0)
//   Points "corner" (0.25, 0.25), "load" (0.47, 0.25)
//
// Example: gmsh -2 -setnumber h 0.005 -format msh2 l-panel.geo -o l-panel.msh

If (!Exists(h))
  h = 0.01;
EndIf
If (!Exists(crack_zone_factor))
  crack_zone_factor = 0.5;
EndIf

side = 0.5;
leg = 0.25;
x_load = 0.47;

// Triangle size before the subdivision halves every edge.
lc = 2 * h;

Point(1) = {0, 0, 0, lc};
Point(2) = {leg, 0, 0, lc};
Point(3) = {leg, leg, 0, lc};
Point(4) = {x_load, leg, 0, lc};
Point(5) = {side, leg, 0, lc};
Point(6) = {side, side, 0, lc};
Point(7) = {0, side, 0, lc};

Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 6};
Line(6) = {6, 7};
Line(7) = {7, 1};

Curve Loop(1) = {1, 2, 3, 4, 5, 6, 7};
Plane Surface(1) = {1};

// Finer cells where the crack runs: left of the corner and above it, graded to lc over 0.05 m.
Field[1] = Box;
Field[1].VIn = crack_zone_factor * lc;
Field[1].VOut = lc;
Field[1].XMin = -1;
Field[1].XMax = leg + 0.05;
Field[1].YMin = leg - 0.05;
Field[1].YMax = leg + 0.1;
Field[1].Thickness = 0.05;
Background Field = 1;

Physical Surface("panel", 1) = {1};
Physical Curve("bottom", 1) = {1};
Physical Curve("cutout-side", 2) = {2};
Physical Curve("arm-bottom", 3) = {3, 4};
Physical Curve("arm-end", 4) = {5};
Physical Curve("top", 5) = {6};
Physical Curve("left", 6) = {7};
Physical Point("corner", 11) = {3};
Physical Point("load", 12) = {4};

Mesh.ElementOrder = 1;
Mesh.Algorithm = 6;               // Frontal-Delaunay (8, Frontal-Delaunay for quads, crashes in 4.8.4)
Mesh.RecombineAll = 1;
Mesh.RecombinationAlgorithm = 1;  // blossom
Mesh.SubdivisionAlgorithm = 1;    // all quadrangles
Mesh.Smoothing = 5;
Mesh.MshFileVersion = 2.2;        // what dealii::GridIn<2>::read_msh is called with
