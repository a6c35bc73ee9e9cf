// Graded block for the hertz-graded scene: the rectangle [x0, x0+W] x
// [-H/2, H/2] meshed with quadrilaterals (Quad9, unstructured, recombined) of
// size h within a distance dp of the first contact point (x0, 0), growing
// linearly to hfar over a further distance dc. So -mesh_size h sets the
// resolution of the contact patch and the rest stays at hfar (never finer than
// h). Edges as in meshes/hertz/block.geo: "contact" (left), "push" (right),
// "top", "bottom".
// Parameters (gmsh -setnumber NAME VALUE): h, x0, W, H, hfar, dp, dc.
If (!Exists(h))    h = 0.1;   EndIf
If (!Exists(x0))   x0 = 0.0;  EndIf
If (!Exists(W))    W = 1.0;   EndIf
If (!Exists(H))    H = 2.0;   EndIf
If (!Exists(hfar)) hfar = 0.2; EndIf
If (!Exists(dp))   dp = 0.5;  EndIf
If (!Exists(dc))   dc = 0.5;  EndIf
If (hfar < h) hfar = h; EndIf

Point(1) = {x0, -H/2, 0, hfar};
Point(2) = {x0 + W, -H/2, 0, hfar};
Point(3) = {x0 + W, H/2, 0, hfar};
Point(4) = {x0, H/2, 0, hfar};
Point(5) = {x0, 0, 0, h};
Line(1) = {1, 2};   // bottom
Line(2) = {2, 3};   // right
Line(3) = {3, 4};   // top
Line(4) = {4, 5};   // left, upper
Line(5) = {5, 1};   // left, lower
Curve Loop(1) = {1, 2, 3, 4, 5};
Plane Surface(1) = {1};

Field[1] = Distance;
Field[1].PointsList = {5};
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
Mesh.Algorithm = 6;              // frontal-Delaunay
Mesh.RecombinationAlgorithm = 3; // blossom full-quad: no triangle left
Recombine Surface{1};

Physical Curve("contact") = {4, 5};
Physical Curve("push") = {2};
Physical Curve("top") = {3};
Physical Curve("bottom") = {1};
Physical Surface("body") = {1};

Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;
Mesh.MshFileVersion = 2.2;
