// A plate 1 m x 0.5 m whose physical names a scene can mistake: "bottom" names both its lower
// edge and the corner at the origin, and "top  edge" (two spaces) its upper edge.
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Point(3) = {1, 0.5, 0};
Point(4) = {0, 0.5, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 21;
Transfinite Curve{2, 4} = 11;
Transfinite Surface{1};
Recombine Surface{1};
Physical Surface("plate") = {1};
Physical Curve("bottom") = {1};
Physical Curve("base") = {1};
Physical Curve("top  edge") = {3};
Physical Point("bottom") = {1};
Physical Point("origin") = {1};
Mesh.MshFileVersion = 2.2;
