// Double cantilever beam (DCB): the mesh of the global (XFEM) solver. The crack between the two
// arms is not part of the mesh; the solver enriches across it.
//
// Units: m. Length L = 0.12 (x from 0, the loaded end, to L), two arms of height h_arm = 0.01
// (y from -h_arm to h_arm); the crack plane is y = 0, the crack mouth at (0, 0). The loaded end
// is split at the mouth into the arms' end faces.
//
// Mesh: first-order quadrilaterals only. gmsh meshes triangles of size 2 h, recombines them
// (blossom) and subdivides every element once (Mesh.SubdivisionAlgorithm = 1): quads of edge
// about h.
//
// Variables (override with gmsh -setnumber <name> <value>):
//   h  quad edge length, m (default 0.001: ten cells over an arm's height)
//
// Physical groups, named for the scene files (prm/double-cantilever-beam*.prm refer to them by name):
//   Surface "beam"
//   Curves "top end" (x = 0, 0 < y < h_arm), "bottom end" (x = 0, -h_arm < y < 0),
//          "top" (y = h_arm), "bottom" (y = -h_arm), "back" (x = L)
//   Points "top back corner" (L, h_arm), "bottom back corner" (L, -h_arm)
//
// Example: gmsh -2 -setnumber h 0.0005 -format msh2 double-cantilever-beam.geo -o dcb.msh

If (!Exists(h))
  h = 0.001;
EndIf

length = 0.12;
arm    = 0.01;

// Triangle sizes before the subdivision halves every edge.
lc = 2 * h;

Point(1) = {0, -arm, 0, lc};
Point(2) = {length, -arm, 0, lc};
Point(3) = {length, arm, 0, lc};
Point(4) = {0, arm, 0, lc};
Point(5) = {0, 0, 0, lc};

Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 1};

Curve Loop(1) = {1, 2, 3, 4, 5};
Plane Surface(1) = {1};

Physical Surface("beam", 1) = {1};
Physical Curve("bottom", 1) = {1};
Physical Curve("back", 2) = {2};
Physical Curve("top", 3) = {3};
Physical Curve("top end", 4) = {4};
Physical Curve("bottom end", 5) = {5};
Physical Point("bottom back corner", 11) = {2};
Physical Point("top back corner", 12) = {3};

Mesh.ElementOrder = 1;
Mesh.Algorithm = 6;               // Frontal-Delaunay (8, Frontal-Delaunay for quads, crashes in 4.8.4)
Mesh.RecombineAll = 1;
Mesh.RecombinationAlgorithm = 1;  // blossom
Mesh.SubdivisionAlgorithm = 1;    // all quadrangles
Mesh.Smoothing = 5;
Mesh.MshFileVersion = 2.2;        // what dealii::GridIn<2>::read_msh is called with
