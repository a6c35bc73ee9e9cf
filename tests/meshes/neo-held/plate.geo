// A rigid flat plate: the line y = Y from x = x0 to x = x1 (no surface:
// the plate is rigid), divided into elements of size h. Group: "contact".
// Parameters (gmsh -setnumber NAME VALUE): h, Y, x0, x1.
If (!Exists(h))  h = 0.1;  EndIf
If (!Exists(Y))  Y = 1.0;  EndIf
If (!Exists(x0)) x0 = -1.5; EndIf
If (!Exists(x1)) x1 = 1.5; EndIf

Point(1) = {x0, Y, 0, h};
Point(2) = {x1, Y, 0, h};
Line(1) = {1, 2};
Transfinite Curve{1} = Ceil((x1 - x0) / h - 1e-9) + 1;

Physical Curve("contact") = {1};

Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;
Mesh.MshFileVersion = 2.2;
