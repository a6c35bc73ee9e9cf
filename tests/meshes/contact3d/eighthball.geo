// An eighth of a ball of radius R centred at the origin (x, y, z >= 0), Tet10
// of size h within rc of its top (0, 0, R), where a plate pressed down on it
// touches, growing to hf at 2 rc (hf = h: uniform, the default), second-order
// nodes on the sphere. The sphere is cut
// at z = zc so that its surface is two: "cap" (z >= zc, the contact surface
// of a plate pressed down on the ball's top) and "side". Groups: symx
// (x = 0), symy (y = 0), symz (z = 0), cap, side; the volume "body".
// Parameters (gmsh -setnumber NAME VALUE): R, h, hf, rc, zc.
SetFactory("OpenCASCADE");
If (!Exists(R)) R = 1; EndIf
If (!Exists(h)) h = 0.1; EndIf
If (!Exists(hf)) hf = h; EndIf
If (!Exists(rc)) rc = 0.5 * R; EndIf
If (!Exists(zc)) zc = 0.4; EndIf

Sphere(1) = {0, 0, 0, R};
Box(2) = {0, 0, 0, R, R, R};
BooleanIntersection(3) = {Volume{1}; Delete;}{Volume{2}; Delete;};
Box(4) = {0, 0, 0, R, R, zc};
BooleanFragments{Volume{3}; Delete;}{Volume{4}; Delete;}
e = 1e-6 * R;
all[] = Volume{:};
ball[] = Volume In BoundingBox{-e, -e, -e, R + e, R + e, R + e};
out[] = all[];
out[] -= {ball[]};
Recursive Delete{Volume{out[]};}
symx[] = Surface In BoundingBox{-e, -e, -e, e, R + e, R + e};
symy[] = Surface In BoundingBox{-e, -e, -e, R + e, e, R + e};
symz[] = Surface In BoundingBox{-e, -e, -e, R + e, R + e, e};
cut[] = Surface In BoundingBox{-e, -e, zc - e, R + e, R + e, zc + e};
side[] = Surface In BoundingBox{-e, -e, -e, R + e, R + e, zc + e};
side[] -= {symx[], symy[], symz[], cut[]};
cap[] = Surface{:};
cap[] -= {symx[], symy[], symz[], cut[], side[]};
Physical Surface("symx") = {symx[]};
Physical Surface("symy") = {symy[]};
Physical Surface("symz") = {symz[]};
Physical Surface("cap") = {cap[]};
Physical Surface("side") = {side[]};
Physical Volume("body") = {ball[]};

Field[1] = MathEval;
Field[1].F = Sprintf("Sqrt(x * x + y * y + (z - %g) * (z - %g))", R, R);
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h;
Field[2].SizeMax = hf;
Field[2].DistMin = rc;
Field[2].DistMax = 2 * rc;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;
Mesh.MshFileVersion = 2.2;
