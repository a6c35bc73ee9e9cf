// Race: the rectangle [-W/2, W/2] x [y0 - H, y0] (dir = 1, a lower race, its
// face up) or [-W/2, W/2] x [y0, y0 + H] (dir = -1, an upper race, its face
// down). Quad9, graded: size h within dp of the face's centre (0, y0),
// growing to hfar over a further dc (never finer than h), unstructured
// quadrilaterals (Blossom recombination). Boundary groups: "contact" (the
// face y = y0), "back" (the opposite face), "sides" (x = +-W/2).
// Parameters (gmsh -setnumber NAME VALUE): h, W, H, y0, dir, hfar, dp, dc.
If (!Exists(h))    h = 0.02;  EndIf
If (!Exists(W))    W = 10.0;  EndIf
If (!Exists(H))    H = 5.0;   EndIf
If (!Exists(y0))   y0 = 0.0;  EndIf
If (!Exists(dir))  dir = 1;   EndIf
If (!Exists(hfar)) hfar = 1.0; EndIf
If (!Exists(dp))   dp = 0.5;  EndIf
If (!Exists(dc))   dc = 2.0;  EndIf
If (hfar < h) hfar = h; EndIf
yb = y0 - dir * H;

Point(1) = {-W/2, yb, 0, hfar};
Point(2) = {W/2, yb, 0, hfar};
Point(3) = {W/2, y0, 0, hfar};
Point(4) = {0, y0, 0, h};
Point(5) = {-W/2, y0, 0, hfar};
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
Field[2].DistMax = dp + dc;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Recombine Surface{1};
Mesh.RecombinationAlgorithm = 2;

Physical Curve("contact") = {3, 4};
Physical Curve("back") = {1};
Physical Curve("sides") = {2, 5};
Physical Surface("body") = {1};

Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;
Mesh.MshFileVersion = 2.2;
