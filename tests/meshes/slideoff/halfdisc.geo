// Lower half (y <= yc) of a disc of radius R centred at (xc, yc), Tri6: an
// ironing tool. Groups: "top" (the flat side y = yc, where the tool is
// driven) and "contact" (the arc). Parameters: h, R, xc, yc.
If (!Exists(h))  h = 0.05; EndIf
If (!Exists(R))  R = 0.5;  EndIf
If (!Exists(xc)) xc = 0.0; EndIf
If (!Exists(yc)) yc = 0.0; EndIf

Point(1) = {xc, yc, 0, h};
Point(2) = {xc + R, yc, 0, h};
Point(3) = {xc, yc - R, 0, h};
Point(4) = {xc - R, yc, 0, h};
Circle(1) = {4, 1, 3};
Circle(2) = {3, 1, 2};
Line(3) = {2, 4};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};

Physical Curve("contact") = {1, 2};
Physical Curve("top") = {3};
Physical Surface("body") = {1};

Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;
Mesh.MshFileVersion = 2.2;
