// A square with a square hole and a smaller square inside the hole, not joined to the rest: a mesh
// of two pieces (refused: a scene is one body).
If (!Exists(h)) h = 0.01; EndIf
Point(1) = {0, 0, 0, h}; Point(2) = {0.3, 0, 0, h}; Point(3) = {0.3, 0.3, 0, h}; Point(4) = {0, 0.3, 0, h};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Point(5) = {0.1, 0.1, 0, h}; Point(6) = {0.2, 0.1, 0, h}; Point(7) = {0.2, 0.2, 0, h}; Point(8) = {0.1, 0.2, 0, h};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Point(9) = {0.13, 0.13, 0, h}; Point(10) = {0.17, 0.13, 0, h}; Point(11) = {0.17, 0.17, 0, h};
Point(12) = {0.13, 0.17, 0, h};
Line(9) = {9, 10}; Line(10) = {10, 11}; Line(11) = {11, 12}; Line(12) = {12, 9};
Curve Loop(1) = {1, 2, 3, 4}; Curve Loop(2) = {5, 6, 7, 8}; Curve Loop(3) = {9, 10, 11, 12};
Plane Surface(1) = {1, 2}; Plane Surface(2) = {3};
Physical Surface("specimen") = {1, 2};
Physical Curve("bottom") = {1}; Physical Curve("top") = {3};
Mesh.RecombineAll = 1; Mesh.SubdivisionAlgorithm = 1; Mesh.MshFileVersion = 2.2;
