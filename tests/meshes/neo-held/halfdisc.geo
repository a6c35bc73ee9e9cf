// The half x >= 0 of a disc of radius R centred at the origin, Tri6 of size
// h, second-order nodes on the arc. Groups: "upper" (the arc y >= 0),
// "lower" (the arc y <= 0), "symx" (the edge x = 0, the symmetry line).
// Parameters (gmsh -setnumber NAME VALUE): h, R.
If (!Exists(h)) h = 0.1; EndIf
If (!Exists(R)) R = 1.0; EndIf

Point(1) = {0, 0, 0, h};
Point(2) = {0, -R, 0, h};
Point(3) = {R, 0, 0, h};
Point(4) = {0, R, 0, h};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Line(3) = {4, 2};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};

Physical Curve("lower") = {1};
Physical Curve("upper") = {2};
Physical Curve("symx") = {3};
Physical Surface("body") = {1};

Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;
Mesh.MshFileVersion = 2.2;
