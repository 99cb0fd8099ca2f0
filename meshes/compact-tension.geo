// Compact tension specimen C(T), ASTM E399 proportions: the mesh of the global (XFEM) solver.
// The crack (the machined notch and the fatigue pre-crack) is not part of the mesh; the solver
// enriches across it.
//
// Units: m. Width W = 0.1 from the load line (x = 0, the pin holes' centres) to the back face
// (x = W); the front face (the notch mouth) at x = -0.25 W; height 1.2 W (y from -0.6 W to
// 0.6 W); pin holes of diameter 0.25 W centred at (0, +-0.275 W). The crack plane is y = 0.
//
// Mesh: first-order quadrilaterals only. gmsh meshes triangles of size 2 h, recombines them
// (blossom) and subdivides every element once (Mesh.SubdivisionAlgorithm = 1): quads of edge
// about h, at least hole_segments edges on each hole (a polygon inscribed in the circle: the mesh
// is first order).
//
// Variables (override with gmsh -setnumber <name> <value>):
//   h              quad edge length, m (default 0.0025)
//   hole_segments  minimum number of mesh edges on each hole boundary (default 32)
//
// Physical groups, named for the scene files (prm/compact-tension*.prm refer to them by name):
//   Surface "specimen"
//   Curves "front" (x = -0.25 W), "back" (x = W), "top" (y = 0.6 W), "bottom" (y = -0.6 W),
//          "top hole", "bottom hole"
//   Points "top back corner" (W, 0.6 W), "bottom back corner" (W, -0.6 W)
//
// Example: gmsh -2 -setnumber h 0.00125 -format msh2 compact-tension.geo -o ct.msh

If (!Exists(h))
  h = 0.0025;
EndIf
If (!Exists(hole_segments))
  hole_segments = 32;
EndIf

width       = 0.1;
front       = -0.25 * width;
half_height = 0.6 * width;
hole_radius = 0.125 * width;
hole_y[]    = {0.275 * width, -0.275 * width};

// Triangle sizes before the subdivision halves every edge.
lc      = 2 * h;
lc_hole = Min(lc, 2 * (2 * Pi * hole_radius / hole_segments));

Point(1) = {front, -half_height, 0, lc};
Point(2) = {width, -half_height, 0, lc};
Point(3) = {width, half_height, 0, lc};
Point(4) = {front, half_height, 0, lc};

Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};

Curve Loop(1) = {1, 2, 3, 4};

// Each hole: four quarter arcs through the points east, north, west, south of the centre.
For i In {0 : 1}
  centre = newp;
  Point(centre) = {0, hole_y[i], 0, lc_hole};
  east = newp;
  Point(east) = {hole_radius, hole_y[i], 0, lc_hole};
  north = newp;
  Point(north) = {0, hole_y[i] + hole_radius, 0, lc_hole};
  west = newp;
  Point(west) = {-hole_radius, hole_y[i], 0, lc_hole};
  south = newp;
  Point(south) = {0, hole_y[i] - hole_radius, 0, lc_hole};
  a1 = newc;
  Circle(a1) = {east, centre, north};
  a2 = newc;
  Circle(a2) = {north, centre, west};
  a3 = newc;
  Circle(a3) = {west, centre, south};
  a4 = newc;
  Circle(a4) = {south, centre, east};
  hole_loop[i] = newll;
  Curve Loop(hole_loop[i]) = {a1, a2, a3, a4};
  hole_arcs[i] = a1;
EndFor

Plane Surface(1) = {1, hole_loop[]};

Physical Surface("specimen", 1) = {1};
Physical Curve("bottom", 1) = {1};
Physical Curve("back", 2) = {2};
Physical Curve("top", 3) = {3};
Physical Curve("front", 4) = {4};
Physical Curve("top hole", 5) = {hole_arcs[0] : hole_arcs[0] + 3};
Physical Curve("bottom hole", 6) = {hole_arcs[1] : hole_arcs[1] + 3};
Physical Point("bottom back corner", 11) = {2};
Physical Point("top back corner", 12) = {3};

Mesh.ElementOrder = 1;
Mesh.Algorithm = 6;               // Frontal-Delaunay (8, Frontal-Delaunay for quads, crashes in 4.8.4)
Mesh.RecombineAll = 1;
Mesh.RecombinationAlgorithm = 1;  // blossom
Mesh.SubdivisionAlgorithm = 1;    // all quadrangles
Mesh.Smoothing = 5;
Mesh.MshFileVersion = 2.2;        // what dealii::GridIn<2>::read_msh is called with
