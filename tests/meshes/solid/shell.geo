// An octant of a thick hollow sphere (inner radius a, outer b) centred at
// the origin, Tet10. Groups: "inner" and "outer" (the spherical faces),
// "symx", "symy", "symz" (the faces in the planes x = 0, y = 0, z = 0), the
// volume "body". Parameters (gmsh -setnumber NAME VALUE): h, a, b.
SetFactory("OpenCASCADE");
If (!Exists(h)) h = 0.2; EndIf
If (!Exists(a)) a = 1; EndIf
If (!Exists(b)) b = 2; EndIf

Sphere(1) = {0, 0, 0, b};
Sphere(2) = {0, 0, 0, a};
BooleanDifference(3) = {Volume{1}; Delete;}{Volume{2}; Delete;};
Box(4) = {0, 0, 0, 2 * b, 2 * b, 2 * b};
BooleanIntersection(5) = {Volume{3}; Delete;}{Volume{4}; Delete;};
e = 1e-6 * b;
Physical Surface("symx") = Surface In BoundingBox{-e, -e, -e, e, b + e, b + e};
Physical Surface("symy") = Surface In BoundingBox{-e, -e, -e, b + e, e, b + e};
Physical Surface("symz") = Surface In BoundingBox{-e, -e, -e, b + e, b + e, e};
Physical Surface("inner") = Surface In BoundingBox{-e, -e, -e, a + e, a + e, a + e};
all() = Surface{:};
outer() = all();
outer() -= Surface In BoundingBox{-e, -e, -e, e, b + e, b + e};
outer() -= Surface In BoundingBox{-e, -e, -e, b + e, e, b + e};
outer() -= Surface In BoundingBox{-e, -e, -e, b + e, b + e, e};
outer() -= Surface In BoundingBox{-e, -e, -e, a + e, a + e, a + e};
Physical Surface("outer") = outer();
Physical Volume("body") = Volume{:};
Mesh.CharacteristicLengthMax = h;
Mesh.CharacteristicLengthMin = 0;
Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;
Mesh.MshFileVersion = 2.2;
