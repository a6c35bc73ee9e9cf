// Flat punch: the rectangle [-b, b] x [0, Hp] on a structured Quad9 grid of
// size h, symmetric about x = 0, its flat face on y = 0 with square corners.
// Boundary groups: "contact" (the flat face y = 0), "push" (y = Hp), "side"
// (x = +-b).
// Parameters (gmsh -setnumber NAME VALUE): h, b, Hp.
If (!Exists(h))  h = 0.0125; EndIf
If (!Exists(b))  b = 0.25;   EndIf
If (!Exists(Hp)) Hp = 0.25;  EndIf

nx = 2 * Ceil(b / h - 1e-9);
ny = Ceil(Hp / h - 1e-9);

Point(1) = {-b, 0, 0, h};
Point(2) = {b, 0, 0, h};
Point(3) = {b, Hp, 0, h};
Point(4) = {-b, Hp, 0, h};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = nx + 1;
Transfinite Curve{2, 4} = ny + 1;
Transfinite Surface{1};
Recombine Surface{1};

Physical Curve("contact") = {1};
Physical Curve("push") = {3};
Physical Curve("side") = {2, 4};
Physical Surface("body") = {1};

Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;
Mesh.MshFileVersion = 2.2;
