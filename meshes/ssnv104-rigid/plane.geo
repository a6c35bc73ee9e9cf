// A rigid plane y = 0 in r-z (x = r, y = z): the line from the axis to
// r = W, given alone (no surface: the plane is rigid, -plane_rigid). Size h
// within dp of the axis, growing linearly to hfar over a further dc.
// Groups: "contact" (0 <= r <= rc), "rest" (rc <= r <= W).
// Parameters (gmsh -setnumber NAME VALUE): h, W, rc, hfar, dp, dc.
If (!Exists(h))    h = 0.5;   EndIf
If (!Exists(W))    W = 60;    EndIf
If (!Exists(rc))   rc = 25;   EndIf
If (!Exists(hfar)) hfar = 10; EndIf
If (!Exists(dp))   dp = 15;   EndIf
If (!Exists(dc))   dc = 20;   EndIf
If (hfar < h) hfar = h; EndIf
Point(1) = {0, 0, 0, h};
Point(2) = {rc, 0, 0, hfar};
Point(3) = {W, 0, 0, hfar};
Line(1) = {1, 2};
Line(2) = {2, 3};
Field[1] = Distance;
Field[1].PointsList = {1};
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
Physical Curve("contact") = {1};
Physical Curve("rest") = {2};
Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;
Mesh.MshFileVersion = 2.2;
