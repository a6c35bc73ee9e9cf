// A rigid flat punch: the rectangle [-b, b] x [0, Hp] given by its four
// sides alone (no surface: the punch is rigid, -punch_rigid), square
// corners, the face divided into elements of size h as the elastic punch's
// (meshes/punch/punch.geo). Groups: "contact" (the face y = 0), "push" (the
// top), "side" (the two sides).
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
Transfinite Curve{1, 3} = nx + 1;
Transfinite Curve{2, 4} = ny + 1;

Physical Curve("contact") = {1};
Physical Curve("push") = {3};
Physical Curve("side") = {2, 4};

Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;
Mesh.MshFileVersion = 2.2;
