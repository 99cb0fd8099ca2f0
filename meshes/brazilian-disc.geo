// The Brazilian disc: a disc compressed along a diameter over two short arcs, where a crack starts
// inside the body (prm/brazilian-disc.prm). The mesh of the global (XFEM) solver.
//
// Units: m. Origin at the disc's centre; radius 0.05 (D = 0.1). The loaded arcs span 2 alpha =
// 20 degrees about the top (0, 0.05) and the bottom (0, -0.05) of the disc; the loaded diameter is
// the y axis.
//
// Mesh: first-order quadrilaterals only. gmsh meshes triangles of size 2 h, recombines them
// (blossom) and subdivides every element once (Mesh.SubdivisionAlgorithm = 1): quads of edge about
// h, centre_factor h within a fifth of the radius of the centre, graded over another fifth. The
// centre is a mesh vertex (a point in the surface), where the tension across the loaded diameter
// peaks. The rim is a polygon whose vertices lie on the circle (the body recovers the circle from
// them, basics/body.h), through the ends of the two arcs and the points east and west.
//
// Variables (override with gmsh -setnumber <name> <value>):
//   h              quad edge length away from the centre, m (default 0.0025)
//   centre_factor  cell size at the centre relative to h (default 0.4)
//
// Physical groups, named for the scene files:
//   Surface "disc"
//   Curves "top arc", "bottom arc" (the loaded arcs), "rim" (the rest of the circle)
//   Points "west" (-0.05, 0), "east" (0.05, 0)
//
// Example: gmsh -2 -setnumber h 0.0025 -format msh2 brazilian-disc.geo -o brazilian-disc.msh

If (!Exists(h))
  h = 0.0025;
EndIf
If (!Exists(centre_factor))
  centre_factor = 0.4;
EndIf

radius = 0.05;
alpha = 10 * Pi / 180;

// Triangle sizes before the subdivision halves every edge.
lc = 2 * h;
lc_centre = centre_factor * lc;

Point(1) = {0, 0, 0, lc_centre};
Point(2) = {radius, 0, 0, lc};
Point(3) = {radius * Sin(alpha), radius * Cos(alpha), 0, lc};
Point(4) = {-radius * Sin(alpha), radius * Cos(alpha), 0, lc};
Point(5) = {-radius, 0, 0, lc};
Point(6) = {-radius * Sin(alpha), -radius * Cos(alpha), 0, lc};
Point(7) = {radius * Sin(alpha), -radius * Cos(alpha), 0, lc};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Circle(3) = {4, 1, 5};
Circle(4) = {5, 1, 6};
Circle(5) = {6, 1, 7};
Circle(6) = {7, 1, 2};
Curve Loop(1) = {1, 2, 3, 4, 5, 6};
Plane Surface(1) = {1};
Point{1} In Surface{1};

// lc_centre at the centre, growing linearly to lc between a fifth and two fifths of the radius.
Field[1] = Distance;
Field[1].PointsList = {1};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = lc_centre;
Field[2].SizeMax = lc;
Field[2].DistMin = 0.2 * radius;
Field[2].DistMax = 0.4 * radius;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;

Physical Surface("disc", 1) = {1};
Physical Curve("top arc", 1) = {2};
Physical Curve("bottom arc", 2) = {5};
Physical Curve("rim", 3) = {1, 3, 4, 6};
Physical Point("west", 11) = {5};
Physical Point("east", 12) = {2};

Mesh.ElementOrder = 1;
Mesh.Algorithm = 6;               // Frontal-Delaunay
Mesh.RecombineAll = 1;
Mesh.RecombinationAlgorithm = 1;  // blossom
Mesh.SubdivisionAlgorithm = 1;    // all quadrangles
Mesh.Smoothing = 5;
Mesh.MshFileVersion = 2.2;        // what dealii::GridIn<2>::read_msh is called with
