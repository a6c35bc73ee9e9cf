// The lower half of a ball of radius R centred at (0, 0, R), touching the
// plane z = 0 at the origin: a quarter of it (x >= 0, y >= 0; whole = 0) or
// the whole half (whole = 1). Tet10 of size h (-mesh_size) within rc of the
// origin, growing to hf at rf (3 rc unless given); with ra > 0 also of size hr
// (h unless given) within wr (2 hr) of the circle of radius ra in the plane
// z = 0 (a ring around the contact's edge, r = a), growing to hf at rf
// (tests/test_whole3d.py). The ball is cut at z = zc
// so that its curved surface is two: "cap" (z <= zc, the contact surface) and "side".
// Groups: top (z = R), cap, side, and for the quarter symx (x = 0) and
// symy (y = 0); the volume "body".
// Parameters (gmsh -setnumber NAME VALUE): R, h, rc, hf, rf, zc, whole, ra, hr, wr.
SetFactory("OpenCASCADE");
If (!Exists(R)) R = 1; EndIf
If (!Exists(h)) h = 0.05; EndIf
If (!Exists(rc)) rc = 0.3; EndIf
If (!Exists(hf)) hf = 0.25; EndIf
If (!Exists(rf)) rf = 3 * rc; EndIf
If (!Exists(zc)) zc = 0.15; EndIf
If (!Exists(whole)) whole = 0; EndIf
If (!Exists(ra)) ra = 0; EndIf
If (!Exists(hr)) hr = h; EndIf
If (!Exists(wr)) wr = 2 * hr; EndIf
// the whole ball's surfaces (patches of the turned sphere) are picked by
// bounding boxes of their triangulations: OpenCASCADE's own boxes for them
// are wider than the patches, and no box picked the cap
If (whole) Geometry.OCCBoundsUseStl = 1; EndIf

x0 = whole ? -R : 0;
Sphere(1) = {0, 0, R, R};
// the whole ball: the sphere's poles (where its parametrisation degenerates,
// and Gmsh's cells with it) turned from the contact point onto the cut z = R
If (whole) Rotate {{1, 0, 0}, {0, 0, R}, Pi / 2} { Volume{1}; } EndIf
Box(2) = {x0, x0, 0, 2 * R, 2 * R, R};
BooleanIntersection(3) = {Volume{1}; Delete;}{Volume{2}; Delete;};
// the slab that cuts the cap off reaches past the ball's bounding box, so
// that its part outside the ball is not picked with the ball (the whole
// ball's slab of the ball's width was: a flat bottom z = 0 over [-R, R]^2)
If (whole)
  Box(4) = {-2 * R, -2 * R, 0, 4 * R, 4 * R, zc};
Else
  Box(4) = {x0, x0, 0, 2 * R, 2 * R, zc};
EndIf
BooleanFragments{Volume{3}; Delete;}{Volume{4}; Delete;}
e = whole ? 1e-2 * R : 1e-6 * R;  // the triangulations' boxes: a looser margin
all[] = Volume{:};
ball[] = Volume In BoundingBox{x0 - e, x0 - e, -e, R + e, R + e, R + e};
out[] = all[];
out[] -= {ball[]};
Recursive Delete{Volume{out[]};}
sym[] = {};
If (!whole)
  symx[] = Surface In BoundingBox{-e, -e, -e, e, R + e, R + e};
  symy[] = Surface In BoundingBox{-e, -e, -e, R + e, e, R + e};
  sym[] = {symx[], symy[]};
  Physical Surface("symx") = {symx[]};
  Physical Surface("symy") = {symy[]};
EndIf
top[] = Surface In BoundingBox{x0 - e, x0 - e, R - e, R + e, R + e, R + e};
cut[] = Surface In BoundingBox{x0 - e, x0 - e, zc - e, R + e, R + e, zc + e};
cap[] = Surface In BoundingBox{x0 - e, x0 - e, -e, R + e, R + e, zc + e};
cap[] -= {sym[], cut[]};
side[] = Surface{:};
side[] -= {sym[], top[], cut[], cap[]};
Physical Surface("top") = {top[]};
Physical Surface("cap") = {cap[]};
Physical Surface("side") = {side[]};
Physical Volume("body") = {ball[]};

Field[1] = MathEval;
Field[1].F = "Sqrt(x * x + y * y + z * z)";
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h;
Field[2].SizeMax = hf;
Field[2].DistMin = rc;
Field[2].DistMax = rf;
Background Field = 2;
If (ra > 0)
  Field[3] = MathEval;
  Field[3].F = Sprintf("Sqrt((Sqrt(x * x + y * y) - %g) * (Sqrt(x * x + y * y) - %g) + z * z)", ra, ra);
  Field[4] = Threshold;
  Field[4].InField = 3;
  Field[4].SizeMin = hr;
  Field[4].SizeMax = hf;
  Field[4].DistMin = wr;
  Field[4].DistMax = rf;
  Field[5] = Min;
  Field[5].FieldsList = {2, 4};
  Background Field = 5;
EndIf
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;
Mesh.MshFileVersion = 2.2;
