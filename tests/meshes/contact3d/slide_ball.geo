// Half of the lower half of a ball of radius R centred at (0, 0, R):
// y >= 0, z <= R, touching the plane z = 0 at the origin (the sliding
// scene, tests/test_contact3d_parallel.py: the ball slid along x). Tet10,
// of size h (-mesh_size) within rc of the origin, growing to hf at 3 rc.
// Its curved surface is "cap" (z <= zc, the contact surface) and "side".
// Groups: symy (y = 0), top (z = R), cap, side; the volume "body".
// Parameters (gmsh -setnumber NAME VALUE): R, h, rc, hf, zc.
SetFactory("OpenCASCADE");
If (!Exists(R)) R = 1; EndIf
If (!Exists(h)) h = 0.05; EndIf
If (!Exists(rc)) rc = 0.3; EndIf
If (!Exists(hf)) hf = 0.25; EndIf
If (!Exists(zc)) zc = 0.15; EndIf

Sphere(1) = {0, 0, R, R};
Box(2) = {-R, 0, -R, 2 * R, R, 2 * R}; // below z = 0 too: no face tangent to the sphere at its lowest point
BooleanIntersection(3) = {Volume{1}; Delete;}{Volume{2}; Delete;};
Box(4) = {-R, 0, -R, 2 * R, R, R + zc};
BooleanFragments{Volume{3}; Delete;}{Volume{4}; Delete;}
e = 1e-6 * R;
all[] = Volume{:};
ball[] = Volume In BoundingBox{-R - e, -e, -e, R + e, R + e, R + e};
out[] = all[];
out[] -= {ball[]};
Recursive Delete{Volume{out[]};}
symy[] = Surface In BoundingBox{-R - e, -e, -e, R + e, e, R + e};
top[] = Surface In BoundingBox{-R - e, -e, R - e, R + e, R + e, R + e};
cut[] = Surface In BoundingBox{-R - e, -e, zc - e, R + e, R + e, zc + e};
cap[] = Surface In BoundingBox{-R - e, -e, -e, R + e, R + e, zc + e};
cap[] -= {symy[], cut[]};
side[] = Surface{:};
side[] -= {symy[], top[], cut[], cap[]};
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
