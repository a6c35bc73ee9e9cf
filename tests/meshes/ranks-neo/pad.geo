// Pad under a cylinder: the rectangle [-W/2, W/2] x [-H, 0], its top face at
// y = 0. Tri6, graded: size h within dp of the origin, growing to hfar over a
// further dc (never finer than h). Boundary groups: "contact" (the whole top
// face), "base" (y = -H), "sides" (x = +-W/2).
// Parameters (gmsh -setnumber NAME VALUE): h, W, H, hfar, dp, dc.
If (!Exists(h))    h = 0.03;   EndIf
If (!Exists(W))    W = 6.0;    EndIf
If (!Exists(H))    H = 2.0;    EndIf
If (!Exists(hfar)) hfar = 0.5; EndIf
If (!Exists(dp))   dp = 0.3;   EndIf
If (!Exists(dc))   dc = 1.5;   EndIf
If (!Exists(line)) line = 0;   EndIf
If (hfar < h) hfar = h; EndIf

Point(1) = {-W/2, -H, 0, hfar};
Point(2) = {W/2, -H, 0, hfar};
Point(3) = {W/2, 0, 0, hfar};
Point(4) = {-W/2, 0, 0, hfar};
Point(5) = {0, 0, 0, h};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 5};
Line(4) = {5, 4};
Line(5) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4, 5};
Plane Surface(1) = {1};

Field[1] = Distance;
If (line) Field[1].CurvesList = {3, 4}; Else Field[1].PointsList = {5}; EndIf
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

Physical Curve("contact") = {3, 4};
Physical Curve("base") = {1};
Physical Curve("sides") = {2, 5};
Physical Surface("body") = {1};

Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;
Mesh.MshFileVersion = 2.2;
