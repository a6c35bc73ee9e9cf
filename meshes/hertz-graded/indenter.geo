// Graded indenter for the hertz-graded scene: the hertz disc (radius R, centre
// (xc, yc), Tri6) whose mesh has size h within a distance dp of the first
// contact point (xc + R, yc), growing linearly to hfar over a further distance
// dc. So -mesh_size h sets the resolution of the contact patch (the hertz
// scene's contact half-width is about 0.36) and the rest of the disc stays at
// hfar (never finer than h). Boundary groups as in meshes/hertz/indenter.geo:
// "contact" (x > xcontact), "clamp" (x < xclamp), "free".
// Parameters (gmsh -setnumber NAME VALUE): h, R, xc, yc, xclamp, xcontact,
// hfar, dp, dc.
If (!Exists(h))        h = 0.1;   EndIf
If (!Exists(R))        R = 1.0;   EndIf
If (!Exists(xc))       xc = -1.0; EndIf
If (!Exists(yc))       yc = 0.0;  EndIf
If (!Exists(xclamp))   xclamp = -1.8; EndIf
If (!Exists(xcontact)) xcontact = -0.5; EndIf
If (!Exists(hfar))     hfar = 0.2; EndIf
If (!Exists(dp))       dp = 0.5;  EndIf
If (!Exists(dc))       dc = 0.5;  EndIf
If (hfar < h) hfar = h; EndIf

tc = Acos((xcontact - xc) / R);   // half-angle of the contact arc
tk = Acos((xclamp - xc) / R);     // angle where the clamp arc starts

Point(1) = {xc, yc, 0, hfar};
Point(2) = {xc + R*Cos(-tc), yc + R*Sin(-tc), 0, hfar};
Point(3) = {xc + R*Cos(tc),  yc + R*Sin(tc),  0, hfar};
Point(4) = {xc + R*Cos(tk),  yc + R*Sin(tk),  0, hfar};
Point(5) = {xc + R*Cos(-tk), yc + R*Sin(-tk), 0, hfar};
Point(6) = {xc + R, yc, 0, h};
Point(7) = {xc - R, yc, 0, hfar};

Circle(1) = {2, 1, 6};   // contact, lower half
Circle(2) = {6, 1, 3};   // contact, upper half
Circle(3) = {3, 1, 4};   // free, upper
Circle(4) = {4, 1, 7};   // clamp, upper half
Circle(5) = {7, 1, 5};   // clamp, lower half
Circle(6) = {5, 1, 2};   // free, lower
Curve Loop(1) = {1, 2, 3, 4, 5, 6};
Plane Surface(1) = {1};

Field[1] = Distance;
Field[1].PointsList = {6};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h;
Field[2].SizeMax = hfar;
Field[2].DistMin = dp;
Field[2].DistMax = dp + dc;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;

Physical Curve("contact") = {1, 2};
Physical Curve("clamp") = {4, 5};
Physical Curve("free") = {3, 6};
Physical Surface("body") = {1};

Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;
Mesh.MshFileVersion = 2.2;
