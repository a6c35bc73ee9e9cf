// Upper half (y >= yc) of the hertz indenter (disc of radius R, centre
// (xc, yc), Tri6), for the hertz-half scene that uses the y = yc symmetry.
// Adapted from tests/meshes/half_indenter.geo, with the cut as a group.
// Groups: "contact" (arc x > xcontact), "free", "clamp" (arc x < xclamp),
// "symmetry" (the cut y = yc, from (xc - R, yc) to (xc + R, yc)).
// Parameters (gmsh -setnumber NAME VALUE): h, R, xc, yc, xclamp, xcontact.
If (!Exists(h))        h = 0.1;   EndIf
If (!Exists(R))        R = 1.0;   EndIf
If (!Exists(xc))       xc = -1.0; EndIf
If (!Exists(yc))       yc = 0.0;  EndIf
If (!Exists(xclamp))   xclamp = -1.8; EndIf
If (!Exists(xcontact)) xcontact = -0.5; EndIf
tc = Acos((xcontact - xc) / R);
tk = Acos((xclamp - xc) / R);
Point(1) = {xc, yc, 0, h};
Point(2) = {xc + R, yc, 0, h};
Point(3) = {xc + R*Cos(tc), yc + R*Sin(tc), 0, h};
Point(4) = {xc + R*Cos(tk), yc + R*Sin(tk), 0, h};
Point(5) = {xc - R, yc, 0, h};
Circle(1) = {2, 1, 3};   // contact
Circle(2) = {3, 1, 4};   // free
Circle(3) = {4, 1, 5};   // clamp
Line(4) = {5, 2};        // symmetry cut
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Curve("contact") = {1};
Physical Curve("free") = {2};
Physical Curve("clamp") = {3};
Physical Curve("symmetry") = {4};
Physical Surface("body") = {1};
Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;
Mesh.MshFileVersion = 2.2;
