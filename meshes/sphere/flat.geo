// A flat cylinder in r-z (x = r, y = z): the section [0, W] x [-H, 0], its
// top face at y = 0. Quad9 on a mesh graded like ball.geo: size h within dp
// of the origin, growing to hfar over a further dc (never finer than h),
// unstructured quadrilaterals (Blossom recombination). Boundary groups:
// "contact" (the top face for r < rc), "top" (the rest of it), "side"
// (r = W), "bottom" (y = -H), "axis" (x = 0).
// Parameters (gmsh -setnumber NAME VALUE): h, W, H, rc, hfar, dp, dc.
If (!Exists(h))    h = 0.01;  EndIf
If (!Exists(W))    W = 2.0;   EndIf
If (!Exists(H))    H = 2.0;   EndIf
If (!Exists(rc))   rc = 0.5;  EndIf
If (!Exists(hfar)) hfar = 0.25; EndIf
If (!Exists(dp))   dp = 0.2;  EndIf
If (!Exists(dc))   dc = 0.5;  EndIf
If (hfar < h) hfar = h; EndIf

Point(1) = {0, 0, 0, h};
Point(2) = {rc, 0, 0, hfar};
Point(3) = {W, 0, 0, hfar};
Point(4) = {W, -H, 0, hfar};
Point(5) = {0, -H, 0, hfar};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 1};
Curve Loop(1) = {1, 2, 3, 4, 5};
Plane Surface(1) = {1};

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
Recombine Surface{1};
Mesh.RecombinationAlgorithm = 2;

Physical Curve("contact") = {1};
Physical Curve("top") = {2};
Physical Curve("side") = {3};
Physical Curve("bottom") = {4};
Physical Curve("axis") = {5};
Physical Surface("body") = {1};

Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;
Mesh.MshFileVersion = 2.2;
