// Semicircular bend (SCB) specimen: a half disc of radius 0.1 m on its diameter, in three-point
// bending (two supports on the diameter, a load on the top of the arc), for an inclined edge crack
// from the middle of the diameter (prm/semicircular-bend.prm): the mesh of the global (XFEM)
// solver. The crack is not part of the mesh; the solver enriches across it.
//
// Units: m. Origin at the middle of the diameter; the body is x^2 + y^2 <= 0.1^2, y >= 0.
// Mesh vertices (geometry points): the supports at x = -0.06 and x = 0.06 on the diameter
// (span 2 s = 0.12 m, s / R = 0.6), the load point at the top of the arc (0, 0.1).
//
// Mesh: first-order quadrilaterals only. gmsh meshes triangles of size 2 h, recombines them
// (blossom) and subdivides every element once (Mesh.SubdivisionAlgorithm = 1): an all-quad mesh
// with edges of about h. Cells are h * crack_zone_factor in the middle, |x| < 0.04, where the
// crack runs from the diameter towards the load point; the solver refines further near the tip.
// The arc is a polygon whose vertices lie on the circle (the body recovers the arc from them,
// basics/body.h), at least arc_segments edges from end to end.
//
// Variables (override with gmsh -setnumber <name> <value>):
//   h                  quad edge length away from the crack zone, m (default 0.006)
//   crack_zone_factor  cell size in the crack zone relative to h (default 0.5; 1 = uniform)
//   arc_segments       minimum number of mesh edges on the arc (default 48)
//
// Physical groups, named for the scene files:
//   Surface "disc"
//   Curves "diameter" (y = 0), "arc"
//   Points "left-support" (-0.06, 0), "right-support" (0.06, 0), "load" (0, 0.1)
//
// Example: gmsh -2 -setnumber h 0.003 -format msh2 semicircular-bend.geo -o scb.msh

If (!Exists(h))
  h = 0.006;
EndIf
If (!Exists(crack_zone_factor))
  crack_zone_factor = 0.5;
EndIf
If (!Exists(arc_segments))
  arc_segments = 48;
EndIf

radius = 0.1;
support = 0.06;

// Triangle sizes before the subdivision halves every edge.
lc = 2 * h;
lc_arc = Min(lc, 2 * (Pi * radius / arc_segments));

Point(1) = {0, 0, 0, lc};
Point(2) = {-radius, 0, 0, lc_arc};
Point(3) = {-support, 0, 0, lc};
Point(4) = {support, 0, 0, lc};
Point(5) = {radius, 0, 0, lc_arc};
Point(6) = {0, radius, 0, lc_arc};

Line(1) = {2, 3};
Line(2) = {3, 4};
Line(3) = {4, 5};
Circle(4) = {5, 1, 6};
Circle(5) = {6, 1, 2};
Curve Loop(1) = {1, 2, 3, 4, 5};
Plane Surface(1) = {1};

// Finer cells in the middle, where the crack runs, graded to lc over 0.02 m.
Field[1] = Box;
Field[1].VIn = crack_zone_factor * lc;
Field[1].VOut = lc;
Field[1].XMin = -0.04;
Field[1].XMax = 0.04;
Field[1].YMin = -1;
Field[1].YMax = 1;
Field[1].Thickness = 0.02;
Background Field = 1;

Physical Surface("disc", 1) = {1};
Physical Curve("diameter", 1) = {1, 2, 3};
Physical Curve("arc", 2) = {4, 5};
Physical Point("left-support", 11) = {3};
Physical Point("right-support", 12) = {4};
Physical Point("load", 13) = {6};

Mesh.ElementOrder = 1;
Mesh.Algorithm = 6;               // Frontal-Delaunay (8, Frontal-Delaunay for quads, crashes in 4.8.4)
Mesh.RecombineAll = 1;
Mesh.RecombinationAlgorithm = 1;  // blossom
Mesh.SubdivisionAlgorithm = 1;    // all quadrangles
Mesh.Smoothing = 5;
Mesh.MshFileVersion = 2.2;        // what dealii::GridIn<2>::read_msh is called with
