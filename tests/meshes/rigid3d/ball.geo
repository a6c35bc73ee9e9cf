// A quarter ball of radius R centred at the origin, x >= 0, y >= 0 (a
// rigid body, 3D: its Physical Volume makes it so), Tet10 of size h, in
// two halves so that its surface is two: "lower" (z <= 0) and "upper"
// (z >= 0). Groups: lower, upper, symx (x = 0), symy (y = 0); the volume
// "ball". Parameters: R, h.
SetFactory("OpenCASCADE");
If (!Exists(R)) R = 1; EndIf
If (!Exists(h)) h = 0.1; EndIf
Sphere(1) = {0, 0, 0, R, -Pi / 2, 0, Pi / 2};
Sphere(2) = {0, 0, 0, R, 0, Pi / 2, Pi / 2};
v[] = BooleanFragments{Volume{1}; Delete;}{Volume{2}; Delete;};
e = 1e-6 * R;
sx[] = Surface In BoundingBox{-e, -e, -R - e, e, R + e, R + e};
sy[] = Surface In BoundingBox{-e, -e, -R - e, R + e, e, R + e};
mid[] = Surface In BoundingBox{-e, -e, -e, R + e, R + e, e};
lower[] = Surface In BoundingBox{-e, -e, -R - e, R + e, R + e, e};
upper[] = Surface In BoundingBox{-e, -e, -e, R + e, R + e, R + e};
lower[] -= {sx[], sy[], mid[]};
upper[] -= {sx[], sy[], mid[]};
Physical Surface("lower") = {lower[]};
Physical Surface("upper") = {upper[]};
Physical Surface("symx") = {sx[]};
Physical Surface("symy") = {sy[]};
Physical Volume("ball") = {v[]};
Mesh.MeshSizeMin = h;
Mesh.MeshSizeMax = h;
Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;
Mesh.MshFileVersion = 2.2;
