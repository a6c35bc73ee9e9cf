// A flat seat in r-z (x = r, y = z): the rectangle [x0, x0 + L] x [-H, 0],
// its top face the contact, refined about the point (rc, 0) where a ring
// (tests/meshes/ring.geo) touches it: Tri6, size h within dp of that point,
// hfar beyond dp + 0.3. Groups: "top", "bottom", "sides". Parameters: h, x0,
// L, H, rc, hfar, dp.
If (!Exists(h))    h = 0.02;  EndIf
If (!Exists(x0))   x0 = 9.7;  EndIf
If (!Exists(L))    L = 3.0;   EndIf
If (!Exists(H))    H = 1.0;   EndIf
If (!Exists(rc))   rc = 11.2; EndIf
If (!Exists(hfar)) hfar = 0.2; EndIf
If (!Exists(dp))   dp = 0.2;  EndIf
If (hfar < h) hfar = h; EndIf

Point(1) = {x0, -H, 0, hfar};
Point(2) = {x0 + L, -H, 0, hfar};
Point(3) = {x0 + L, 0, 0, hfar};
Point(4) = {rc, 0, 0, h};
Point(5) = {x0, 0, 0, hfar};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 1};
Curve Loop(1) = {1, 2, 3, 4, 5};
Plane Surface(1) = {1};

Field[1] = Distance;
Field[1].PointsList = {4};
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

Physical Curve("top") = {3, 4};
Physical Curve("bottom") = {1};
Physical Curve("sides") = {2, 5};
Physical Surface("seat") = {1};

Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;
Mesh.MshFileVersion = 2.2;
