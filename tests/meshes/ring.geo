// The lower half of a ring's round section in r-z (an axisymmetric scene:
// x = r, y = z): a half disc of radius rho centred at (rc, rho), its lowest
// point (rc, 0), its flat top the cut y = rho. Away from the axis (rc > rho),
// it is an O-ring's lower half: pressed on a flat, its contact is a band
// about r = rc. Tri6, size h within dp of the lowest point, hfar elsewhere.
// Groups: "contact" (the arc within tc degrees of the lowest point), "free"
// (the rest of the arc), "top" (the cut). Parameters: h, rc, rho, tc, hfar, dp.
If (!Exists(h))    h = 0.02;  EndIf
If (!Exists(rc))   rc = 11.2; EndIf
If (!Exists(rho))  rho = 0.6; EndIf
If (!Exists(tc))   tc = 45;   EndIf
If (!Exists(hfar)) hfar = 0.1; EndIf
If (!Exists(dp))   dp = 0.2;  EndIf
If (hfar < h) hfar = h; EndIf
t = tc * Pi / 180;

Point(1) = {rc, rho, 0, hfar};                             // centre
Point(2) = {rc, 0, 0, h};                                  // lowest point
Point(3) = {rc + rho * Sin(t), rho - rho * Cos(t), 0, hfar};
Point(4) = {rc + rho, rho, 0, hfar};
Point(5) = {rc - rho * Sin(t), rho - rho * Cos(t), 0, hfar};
Point(6) = {rc - rho, rho, 0, hfar};
Circle(1) = {6, 1, 5};
Circle(2) = {5, 1, 2};
Circle(3) = {2, 1, 3};
Circle(4) = {3, 1, 4};
Line(5) = {4, 6};
Curve Loop(1) = {1, 2, 3, 4, 5};
Plane Surface(1) = {1};

Field[1] = Distance;
Field[1].PointsList = {2};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h;
Field[2].SizeMax = hfar;
Field[2].DistMin = dp;
Field[2].DistMax = dp + 0.3;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;

Physical Curve("contact") = {2, 3};
Physical Curve("free") = {1, 4};
Physical Curve("top") = {5};
Physical Surface("ring") = {1};

Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;
Mesh.MshFileVersion = 2.2;
