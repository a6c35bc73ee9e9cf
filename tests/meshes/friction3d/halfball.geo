// The half y >= 0 of the lower part z <= zt of a ball of radius R centred
// at (0, 0, R), touching the plane z = 0 at the origin: Tet10, of size h
// (-mesh_size) within rc of the origin, growing to hf at 3 rc, the distance
// stretched zs times along z (zs > 1: a layer of size h along the contact
// plane, rc/zs thick), and at most hm within rm of the origin (growing to hf
// at 3 rm; hm = hf: no such zone). Its curved surface is two: "cap" (z <= zc,
// the contact surface) and "side". Groups: symy (y = 0), top (z = zt), cap,
// side; the volume "body". dir = -1 mirrors it about the plane z = 0 (the
// ball centred at (0, 0, -R), its top z = -zt, its cap z >= -zc: the lower of
// two identical balls touching at the origin; the size field is even in z).
// With ra > 0 also of size hr within wr of the circle of radius ra on the
// ball's surface (at |z| = R - sqrt(R^2 - ra^2): a ring over the contact's
// edge or Mindlin's slip annulus, tests/test_ring3d.py), growing to hf at
// wr + gr from it (the distance even in z as the rest). Parameters (gmsh -setnumber NAME VALUE):
// R, zt, h, rc, hf, zs, hm, rm, zc, dir, ra, hr, wr, gr.
SetFactory("OpenCASCADE");
If (!Exists(R)) R = 1; EndIf
If (!Exists(zt)) zt = 0.5; EndIf
If (!Exists(h)) h = 0.05; EndIf
If (!Exists(rc)) rc = 0.15; EndIf
If (!Exists(hf)) hf = 0.2; EndIf
If (!Exists(zs)) zs = 1; EndIf
If (!Exists(hm)) hm = hf; EndIf
If (!Exists(rm)) rm = 3 * rc; EndIf
If (!Exists(zc)) zc = 0.05; EndIf
If (!Exists(dir)) dir = 1; EndIf
If (!Exists(ra)) ra = 0; EndIf
If (!Exists(hr)) hr = h; EndIf
If (!Exists(wr)) wr = 2 * hr; EndIf
If (!Exists(gr)) gr = rc; EndIf

Sphere(1) = {0, 0, R, R};
Box(2) = {-2 * R, 0, 0, 4 * R, 2 * R, zt};
BooleanIntersection(3) = {Volume{1}; Delete;}{Volume{2}; Delete;};
Box(4) = {-2 * R, 0, 0, 4 * R, 2 * R, zc};
BooleanFragments{Volume{3}; Delete;}{Volume{4}; Delete;}
e = 1e-6 * R;
all[] = Volume{:};
ball[] = Volume In BoundingBox{-R - e, -e, -e, R + e, R + e, zt + e};
out[] = all[];
out[] -= {ball[]};
Recursive Delete{Volume{out[]};}
s = 1;
If (dir < 0)
  Symmetry {0, 0, 1, 0} { Volume{ball[]}; }
  s = -1;
EndIf
// z in [a, b] mirrored: [Min(s a, s b), Max(s a, s b)]
symy[] = Surface In BoundingBox{-R - e, -e, Min(-s * e, s * (zt + e)), R + e, e, Max(-s * e, s * (zt + e))};
top[] = Surface In BoundingBox{-R - e, -e, Min(s * (zt - e), s * (zt + e)), R + e, R + e, Max(s * (zt - e), s * (zt + e))};
cut[] = Surface In BoundingBox{-R - e, -e, Min(s * (zc - e), s * (zc + e)), R + e, R + e, Max(s * (zc - e), s * (zc + e))};
cap[] = Surface In BoundingBox{-R - e, -e, Min(-s * e, s * (zc + e)), R + e, R + e, Max(-s * e, s * (zc + e))};
cap[] -= {symy[], cut[]};
side[] = Surface{:};
side[] -= {symy[], top[], cut[], cap[]};
Physical Surface("symy") = {symy[]};
Physical Surface("top") = {top[]};
Physical Surface("cap") = {cap[]};
Physical Surface("side") = {side[]};
Physical Volume("body") = {ball[]};

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
If (ra > 0)
  Field[6] = MathEval;
  zr = R - Sqrt(R * R - ra * ra);
  Field[6].F = Sprintf("Sqrt((Sqrt(x * x + y * y) - %g) * (Sqrt(x * x + y * y) - %g) + (Sqrt(z * z) - %g) * (Sqrt(z * z) - %g))", ra, ra, zr, zr);
  Field[7] = Threshold;
  Field[7].InField = 6;
  Field[7].SizeMin = hr;
  Field[7].SizeMax = hf;
  Field[7].DistMin = wr;
  Field[7].DistMax = wr + gr;
  Field[8] = Min;
  Field[8].FieldsList = {2, 4, 7};
  Background Field = 8;
  // the default Frontal-Delaunay meshes the cap (about the sphere's pole) at
  // 2-3 times hr; MeshAdapt keeps to the field
  Mesh.Algorithm = 1;
EndIf
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;
Mesh.MshFileVersion = 2.2;
