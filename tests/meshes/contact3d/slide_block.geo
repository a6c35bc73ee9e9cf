// A block [-L, s + L] x [0, W] x [-W, 0] under slide_ball.geo's half ball,
// which slides from x = 0 to x = s along its top (the sliding scene,
// tests/test_contact3d_parallel.py). Tet10, of size h (-mesh_size) within
// rc of the path (the segment from the origin to (s, 0, 0)), growing to hf
// over 2 rc. Its top is "top" ([-c, s + c] x [0, c], the contact surface)
// and "topout". Groups: symy (y = 0), bottom (z = -W), top, topout; the
// volume "body". Parameters: s, L, W, h, rc, hf, c.
SetFactory("OpenCASCADE");
If (!Exists(s)) s = 0.4; EndIf
If (!Exists(L)) L = 1; EndIf
If (!Exists(W)) W = 1; EndIf
If (!Exists(h)) h = 0.05; EndIf
If (!Exists(rc)) rc = 0.15; EndIf
If (!Exists(hf)) hf = 0.3; EndIf
If (!Exists(c)) c = 0.3; EndIf

Box(1) = {-L, 0, -W, s + 2 * L, W, W};
Box(2) = {-c, 0, -c, s + 2 * c, c, c};
v[] = BooleanFragments{Volume{1}; Delete;}{Volume{2}; Delete;};
e = 1e-6 * W;
Physical Surface("symy") = Surface In BoundingBox{-L - e, -e, -W - e, s + L + e, e, e};
Physical Surface("bottom") = Surface In BoundingBox{-L - e, -e, -W - e, s + L + e, W + e, -W + e};
top[] = Surface In BoundingBox{-c - e, -e, -e, s + c + e, c + e, e};
topout[] = Surface In BoundingBox{-L - e, -e, -e, s + L + e, W + e, e};
topout[] -= {top[]};
Physical Surface("top") = {top[]};
Physical Surface("topout") = {topout[]};
Physical Volume("body") = {v[]};

Field[1] = Box;
Field[1].VIn = h;
Field[1].VOut = hf;
Field[1].XMin = -rc;
Field[1].XMax = s + rc;
Field[1].YMin = -rc;
Field[1].YMax = rc;
Field[1].ZMin = -rc;
Field[1].ZMax = rc;
Field[1].Thickness = 2 * rc;
Background Field = 1;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;
Mesh.MshFileVersion = 2.2;
