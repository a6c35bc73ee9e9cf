// A quarter block [0, W] x [0, W] x [-W, 0] standing in for a half-space
// under a punch at the origin: Tet10 of size h (-mesh_size) within rc of
// the origin, growing in proportion to the distance beyond it (size
// h + g (r - rc)), so that a block many times the punch costs little more.
// Its top is two surfaces: "top" ([0, c]^2, the contact surface) and
// "topout". Groups: symx (x = 0), symy (y = 0), xmax, ymax, bottom
// (z = -W), top, topout; the volume "body". Parameters: W, h, rc, g, c.
SetFactory("OpenCASCADE");
If (!Exists(W)) W = 1.5; EndIf
If (!Exists(h)) h = 0.05; EndIf
If (!Exists(rc)) rc = 0.3; EndIf
If (!Exists(g)) g = 0.3; EndIf
If (!Exists(c)) c = 0.5; EndIf

Box(1) = {0, 0, -W, W, W, W};
Box(2) = {0, 0, -c, c, c, c};
v[] = BooleanFragments{Volume{1}; Delete;}{Volume{2}; Delete;};
e = 1e-6 * W;
Physical Surface("symx") = Surface In BoundingBox{-e, -e, -W - e, e, W + e, e};
Physical Surface("xmax") = Surface In BoundingBox{W - e, -e, -W - e, W + e, W + e, e};
Physical Surface("symy") = Surface In BoundingBox{-e, -e, -W - e, W + e, e, e};
Physical Surface("ymax") = Surface In BoundingBox{-e, W - e, -W - e, W + e, W + e, e};
Physical Surface("bottom") = Surface In BoundingBox{-e, -e, -W - e, W + e, W + e, -W + e};
top[] = Surface In BoundingBox{-e, -e, -e, c + e, c + e, e};
topout[] = Surface In BoundingBox{-e, -e, -e, W + e, W + e, e};
topout[] -= {top[]};
Physical Surface("top") = {top[]};
Physical Surface("topout") = {topout[]};
Physical Volume("body") = {v[]};

Field[1] = MathEval;
Field[1].F = Sprintf("%g + %g * Max(0, Sqrt(x * x + y * y + z * z) - %g)", h, g, rc);
Background Field = 1;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;
Mesh.MshFileVersion = 2.2;
