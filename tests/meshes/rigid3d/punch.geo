// A quarter of a flat circular punch (rigid body, 3D: its Physical Volume
// makes it so): the cylinder r <= a, 0 <= z <= H, x >= 0, y >= 0, Tet10 of
// size h. Groups: "face" (z = 0, the punch's flat end), "top" (z = H),
// "side", "symx", "symy"; the volume "punch". Parameters: a, H, h.
SetFactory("OpenCASCADE");
If (!Exists(a)) a = 1; EndIf
If (!Exists(H)) H = 0.5; EndIf
If (!Exists(h)) h = 0.1; EndIf
Cylinder(1) = {0, 0, 0, 0, 0, H, a, Pi / 2};
e = 1e-6 * a;
Physical Surface("face") = Surface In BoundingBox{-e, -e, -e, a + e, a + e, e};
Physical Surface("top") = Surface In BoundingBox{-e, -e, H - e, a + e, a + e, H + e};
Physical Surface("symx") = Surface In BoundingBox{-e, -e, -e, e, a + e, H + e};
Physical Surface("symy") = Surface In BoundingBox{-e, -e, -e, a + e, e, H + e};
Physical Volume("punch") = {1};
Mesh.MeshSizeMin = h;
Mesh.MeshSizeMax = h;
Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;
Mesh.MshFileVersion = 2.2;
