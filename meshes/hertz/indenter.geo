// Indenter: a full disc of radius R centred at (xc, yc), meshed with Tri6.
// Boundary arcs are split at x = xclamp (arc x < xclamp is "clamp") and at
// x = xcontact (arc x > xcontact is "contact"); the rest is "free".
// Parameters (gmsh -setnumber NAME VALUE): h, R, xc, yc, xclamp, xcontact.
If (!Exists(h))        h = 0.1;   EndIf
If (!Exists(R))        R = 1.0;   EndIf
If (!Exists(xc))       xc = -1.0; EndIf
If (!Exists(yc))       yc = 0.0;  EndIf
If (!Exists(xclamp))   xclamp = -1.8; EndIf
If (!Exists(xcontact)) xcontact = -0.5; EndIf

tc = Acos((xcontact - xc) / R);   // half-angle of the contact arc
tk = Acos((xclamp - xc) / R);     // angle where the clamp arc starts

Point(1) = {xc, yc, 0, h};
Point(2) = {xc + R*Cos(-tc), yc + R*Sin(-tc), 0, h};
Point(3) = {xc + R*Cos(tc),  yc + R*Sin(tc),  0, h};
Point(4) = {xc + R*Cos(tk),  yc + R*Sin(tk),  0, h};
Point(5) = {xc + R*Cos(-tk), yc + R*Sin(-tk), 0, h};
Point(6) = {xc + R, yc, 0, h};
Point(7) = {xc - R, yc, 0, h};

Circle(1) = {2, 1, 6};   // contact, lower half
Circle(2) = {6, 1, 3};   // contact, upper half
Circle(3) = {3, 1, 4};   // free, upper
Circle(4) = {4, 1, 7};   // clamp, upper half
Circle(5) = {7, 1, 5};   // clamp, lower half
Circle(6) = {5, 1, 2};   // free, lower
Curve Loop(1) = {1, 2, 3, 4, 5, 6};
Plane Surface(1) = {1};

Physical Curve("contact") = {1, 2};
Physical Curve("clamp") = {4, 5};
Physical Curve("free") = {3, 6};
Physical Surface("body") = {1};

Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;
Mesh.MshFileVersion = 2.2;
