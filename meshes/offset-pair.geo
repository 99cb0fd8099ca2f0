// Offset pair of edge cracks: the mesh of the global (XFEM) solver. The cracks are not part of
// the mesh; the solver enriches across them (prm/offset-pair.prm gives them).
//
// Units: m. A plate of width 0.2 (x from 0 to 0.2) and height 0.1 (y from 0 to 0.1).
//
// Mesh: first-order quadrilaterals only. gmsh meshes triangles of size 2 h, recombines them
// (blossom) and subdivides every element once (Mesh.SubdivisionAlgorithm = 1): quads of edge
// about h everywhere.
//
// Variables (override with gmsh -setnumber <name> <value>):
//   h   quad edge length, m (default 0.004)
//
// Physical groups, named for the scene file:
//   Surface "plate"
//   Curves "bottom" (y = 0), "right" (x = 0.2), "top" (y = 0.1), "left" (x = 0)
//
// Example: gmsh -2 -setnumber h 0.002 -format msh2 offset-pair.geo -o offset-pair.msh

If (!Exists(h))
  h = 0.004;
EndIf

width  = 0.2;
height = 0.1;
lc     = 2 * h;

Point(1) = {0, 0, 0, lc};
Point(2) = {width, 0, 0, lc};
Point(3) = {width, height, 0, lc};
Point(4) = {0, height, 0, lc};

Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};

Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

Physical Surface("plate", 1) = {1};
Physical Curve("bottom", 1) = {1};
Physical Curve("right", 2) = {2};
Physical Curve("top", 3) = {3};
Physical Curve("left", 4) = {4};

Mesh.ElementOrder = 1;
Mesh.Algorithm = 6;               // Frontal-Delaunay
Mesh.RecombineAll = 1;
Mesh.RecombinationAlgorithm = 1;  // blossom
Mesh.SubdivisionAlgorithm = 1;    // all quadrangles
Mesh.Smoothing = 5;
Mesh.MshFileVersion = 2.2;        // what dealii::GridIn<2>::read_msh is called with
