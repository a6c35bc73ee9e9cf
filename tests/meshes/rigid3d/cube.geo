// A cube [x0, x0 + s] x [y0, y0 + s] x [z0, z0 + s] (rigid body, 3D),
// Hex27 transfinite n cells a side (hex = 1) or Tet10 of size h.
// Groups: "bottom" (z = z0), "top" (z = z0 + s), "xmin", "xmax", "ymin",
// "ymax"; the volume "cube". Parameters: x0, y0, z0, s, n, hex, h.
SetFactory("OpenCASCADE");
If (!Exists(x0)) x0 = 0; EndIf
If (!Exists(y0)) y0 = 0; EndIf
If (!Exists(z0)) z0 = 0; EndIf
If (!Exists(s)) s = 1; EndIf
If (!Exists(n)) n = 2; EndIf
If (!Exists(hex)) hex = 1; EndIf
Box(1) = {x0, y0, z0, s, s, s};
e = 1e-6 * s;
Physical Surface("bottom") = Surface In BoundingBox{x0 - e, y0 - e, z0 - e, x0 + s + e, y0 + s + e, z0 + e};
Physical Surface("top") = Surface In BoundingBox{x0 - e, y0 - e, z0 + s - e, x0 + s + e, y0 + s + e, z0 + s + e};
Physical Surface("xmin") = Surface In BoundingBox{x0 - e, y0 - e, z0 - e, x0 + e, y0 + s + e, z0 + s + e};
Physical Surface("xmax") = Surface In BoundingBox{x0 + s - e, y0 - e, z0 - e, x0 + s + e, y0 + s + e, z0 + s + e};
Physical Surface("ymin") = Surface In BoundingBox{x0 - e, y0 - e, z0 - e, x0 + s + e, y0 + e, z0 + s + e};
Physical Surface("ymax") = Surface In BoundingBox{x0 - e, y0 + s - e, z0 - e, x0 + s + e, y0 + s + e, z0 + s + e};
Physical Volume("cube") = {1};
If (!Exists(h)) h = s / n; EndIf
If (hex)
  Transfinite Curve{:} = n + 1;
  Transfinite Surface{:};
  Recombine Surface{:};
  Transfinite Volume{1};
Else
  Mesh.MeshSizeMin = h;
  Mesh.MeshSizeMax = h;
EndIf
Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;
Mesh.MshFileVersion = 2.2;
