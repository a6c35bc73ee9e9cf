// A block [-W, W] x [0, W] x [-H, 0] under the half ball (halfball.geo):
// Tet10, of size h (-mesh_size) within rc of the origin, growing to hf at
// 3 rc, the distance stretched zs times along z, and at most hm within rm of
// the origin (halfball.geo's). Its top is two surfaces: "top" ([-c, c] x [0, c], the contact
// surface) and "topout". Groups: symy (y = 0), bottom (z = -H), top,
// topout, sides (x = -W, x = W, y = W); the volume "body".
// Parameters: W, H, h, rc, hf, zs, hm, rm, c.
SetFactory("OpenCASCADE");
If (!Exists(W)) W = 0.6; EndIf
If (!Exists(H)) H = 0.6; EndIf
If (!Exists(h)) h = 0.05; EndIf
If (!Exists(rc)) rc = 0.15; EndIf
If (!Exists(hf)) hf = 0.2; EndIf
If (!Exists(zs)) zs = 1; EndIf
If (!Exists(hm)) hm = hf; EndIf
If (!Exists(rm)) rm = 3 * rc; EndIf
If (!Exists(c)) c = 0.2; EndIf

Box(1) = {-W, 0, -H, 2 * W, W, H};
Box(2) = {-c, 0, -c, 2 * c, c, c};
v[] = BooleanFragments{Volume{1}; Delete;}{Volume{2}; Delete;};
e = 1e-6 * W;
Physical Surface("symy") = Surface In BoundingBox{-W - e, -e, -H - e, W + e, e, e};
Physical Surface("bottom") = Surface In BoundingBox{-W - e, -e, -H - e, W + e, W + e, -H + e};
top[] = Surface In BoundingBox{-c - e, -e, -e, c + e, c + e, e};
topout[] = Surface In BoundingBox{-W - e, -e, -e, W + e, W + e, e};
topout[] -= {top[]};
Physical Surface("top") = {top[]};
Physical Surface("topout") = {topout[]};
Physical Volume("body") = {v[]};

Field[1] = MathEval;
Field[1].F = Sprintf("Sqrt(x * x + y * y + %g * z * z)", zs * zs);
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h;
Field[2].SizeMax = hf;
Field[2].DistMin = rc;
Field[2].DistMax = 3 * rc;
Field[3] = MathEval;
Field[3].F = "Sqrt(x * x + y * y + z * z)";
Field[4] = Threshold;
Field[4].InField = 3;
Field[4].SizeMin = hm;
Field[4].SizeMax = hf;
Field[4].DistMin = rm;
Field[4].DistMax = 3 * rm;
Field[5] = Min;
Field[5].FieldsList = {2, 4};
Background Field = 5;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;
Mesh.MshFileVersion = 2.2;
