// A block under the ball (ball.geo): [0, W]^2 x [-W, 0] for the quarter
// (whole = 0), [-W, W]^2 x [-W, 0] for the whole (whole = 1). Tet10 of
// size h (-mesh_size) within rc of the origin, growing to hf at 3 rc. Its
// top is two surfaces: "top" (the square [0, c]^2, or [-c, c]^2: the
// contact surface) and "topout". Groups: bottom (z = -W), top, topout, and
// for the quarter symx (x = 0) and symy (y = 0); the volume "body".
// Parameters: W, h, rc, hf, c, whole.
SetFactory("OpenCASCADE");
If (!Exists(W)) W = 1.5; EndIf
If (!Exists(h)) h = 0.05; EndIf
If (!Exists(rc)) rc = 0.3; EndIf
If (!Exists(hf)) hf = 0.4; EndIf
If (!Exists(c)) c = 0.5; EndIf
If (!Exists(whole)) whole = 0; EndIf

x0 = whole ? -W : 0;
xc = whole ? -c : 0;
Box(1) = {x0, x0, -W, W - x0, W - x0, W};
Box(2) = {xc, xc, -c, c - xc, c - xc, c};
v[] = BooleanFragments{Volume{1}; Delete;}{Volume{2}; Delete;};
e = 1e-6 * W;
If (!whole)
  Physical Surface("symx") = Surface In BoundingBox{-e, -e, -W - e, e, W + e, e};
  Physical Surface("symy") = Surface In BoundingBox{-e, -e, -W - e, W + e, e, e};
EndIf
Physical Surface("bottom") = Surface In BoundingBox{x0 - e, x0 - e, -W - e, W + e, W + e, -W + e};
top[] = Surface In BoundingBox{xc - e, xc - e, -e, c + e, c + e, e};
topout[] = Surface In BoundingBox{x0 - e, x0 - e, -e, W + e, W + e, e};
topout[] -= {top[]};
Physical Surface("top") = {top[]};
Physical Surface("topout") = {topout[]};
Physical Volume("body") = {v[]};

Field[1] = MathEval;
Field[1].F = "Sqrt(x * x + y * y + z * z)";
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h;
Field[2].SizeMax = hf;
Field[2].DistMin = rc;
Field[2].DistMax = 3 * rc;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;
Mesh.MshFileVersion = 2.2;
