// A whole disc of radius R centred at the origin, Tri6 of size h,
// second-order nodes on the circle. Groups: "upper" (the half circle
// y >= 0), "lower" (the half circle y <= 0).
// Parameters (gmsh -setnumber NAME VALUE): h, R.
If (!Exists(h)) h = 0.1; EndIf
If (!Exists(R)) R = 1.0; EndIf

Point(1) = {0, 0, 0, h};
Point(2) = {R, 0, 0, h};
Point(3) = {0, R, 0, h};
Point(4) = {-R, 0, 0, h};
Point(5) = {0, -R, 0, h};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Circle(3) = {4, 1, 5};
Circle(4) = {5, 1, 2};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

Physical Curve("upper") = {1, 2};
Physical Curve("lower") = {3, 4};
Physical Surface("body") = {1};

Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;
Mesh.MshFileVersion = 2.2;
