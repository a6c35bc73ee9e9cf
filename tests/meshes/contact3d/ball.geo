// A quarter of the lower half of a ball of radius R centred at (0, 0, R):
// x >= 0, y >= 0, z <= R, touching the plane z = 0 at the origin. Tet10,
// of size h (-mesh_size) within rc of the origin, growing to hf at 3 rc.
// The ball is cut at z = zc so that its curved surface is two: "cap"
// (z <= zc, the contact surface) and "side". Groups: symx (x = 0), symy
// (y = 0), top (z = R), cap, side; the volume "body".
// Parameters (gmsh -setnumber NAME VALUE): R, h, rc, hf, zc.
SetFactory("OpenCASCADE");
If (!Exists(R)) R = 1; EndIf
If (!Exists(h)) h = 0.05; EndIf
If (!Exists(rc)) rc = 0.3; EndIf
If (!Exists(hf)) hf = 0.25; EndIf
If (!Exists(zc)) zc = 0.15; EndIf

Sphere(1) = {0, 0, R, R};
Box(2) = {0, 0, 0, 2 * R, 2 * R, R};
BooleanIntersection(3) = {Volume{1}; Delete;}{Volume{2}; Delete;};
Box(4) = {0, 0, 0, 2 * R, 2 * R, zc};
BooleanFragments{Volume{3}; Delete;}{Volume{4}; Delete;}
e = 1e-6 * R;
all[] = Volume{:};
low[] = Volume In BoundingBox{-e, -e, -e, R + e, R + e, zc + e};
ball[] = Volume In BoundingBox{-e, -e, -e, R + e, R + e, R + e};
out[] = all[];
out[] -= {ball[]};
Recursive Delete{Volume{out[]};}
symx[] = Surface In BoundingBox{-e, -e, -e, e, R + e, R + e};
symy[] = Surface In BoundingBox{-e, -e, -e, R + e, e, R + e};
top[] = Surface In BoundingBox{-e, -e, R - e, R + e, R + e, R + e};
cut[] = Surface In BoundingBox{-e, -e, zc - e, R + e, R + e, zc + e};
cap[] = Surface In BoundingBox{-e, -e, -e, R + e, R + e, zc + e};
cap[] -= {symx[], symy[], cut[]};
side[] = Surface{:};
side[] -= {symx[], symy[], top[], cut[], cap[]};
Physical Surface("symx") = {symx[]};
Physical Surface("symy") = {symy[]};
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
Field[2].DistMax = 3 * rc;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;
Mesh.MshFileVersion = 2.2;
