// A rigid disc of radius R centred at (xc, yc): its curves alone (no
// surface: the body is rigid, -indenter_rigid). "contact" is the arc in
// front of x = xcontact (facing +x), "back" the rest of the circle.
// Optional grading: size hc at the front point.
// Parameters (gmsh -setnumber NAME VALUE): h, R, xc, yc, xcontact, hc.
If (!Exists(h))        h = 0.1;   EndIf
If (!Exists(R))        R = 1.0;   EndIf
If (!Exists(xc))       xc = -1.0; EndIf
If (!Exists(yc))       yc = 0.0;  EndIf
If (!Exists(xcontact)) xcontact = -0.5; EndIf
If (!Exists(hc))       hc = h;    EndIf
tc = Acos((xcontact - xc) / R);
Point(1) = {xc, yc, 0, h};
Point(2) = {xc + R*Cos(-tc), yc + R*Sin(-tc), 0, h};
Point(3) = {xc + R*Cos(tc),  yc + R*Sin(tc),  0, h};
Point(4) = {xc + R, yc, 0, hc};
Point(5) = {xc - R, yc, 0, h};
Circle(1) = {2, 1, 4};
Circle(2) = {4, 1, 3};
Circle(3) = {3, 1, 5};
Circle(4) = {5, 1, 2};
Physical Curve("contact") = {1, 2};
Physical Curve("back") = {3, 4};
Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;
Mesh.MshFileVersion = 2.2;
