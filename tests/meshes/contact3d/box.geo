// A box [x0, x0 + L] x [y0, y0 + L] x [z0, z0 + H], second order: Tet10
// (hex = 0, mesh size h) or Hex27 (hex = 1, transfinite, n cells across and
// m cells in height). Groups: the faces xmin, xmax, ymin, ymax, bottom
// (z = z0), top (z = z0 + H); the volume "body".
// Parameters (gmsh -setnumber NAME VALUE): x0, y0, z0, L, H, hex, n, m, h.
If (!Exists(x0)) x0 = 0; EndIf
If (!Exists(y0)) y0 = 0; EndIf
If (!Exists(z0)) z0 = 0; EndIf
If (!Exists(L)) L = 1; EndIf
If (!Exists(H)) H = 0.5; EndIf
If (!Exists(hex)) hex = 1; EndIf
If (!Exists(n)) n = 3; EndIf
If (!Exists(m)) m = 2; EndIf
If (!Exists(h)) h = 0.4; EndIf

Point(1) = {x0, y0, z0, h};
Point(2) = {x0 + L, y0, z0, h};
Point(3) = {x0 + L, y0 + L, z0, h};
Point(4) = {x0, y0 + L, z0, h};
Point(5) = {x0, y0, z0 + H, h};
Point(6) = {x0 + L, y0, z0 + H, h};
Point(7) = {x0 + L, y0 + L, z0 + H, h};
Point(8) = {x0, y0 + L, z0 + H, h};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Line(9) = {1, 5}; Line(10) = {2, 6}; Line(11) = {3, 7}; Line(12) = {4, 8};
Curve Loop(1) = {1, 2, 3, 4};     Surface(1) = {1};   // bottom
Curve Loop(2) = {5, 6, 7, 8};     Surface(2) = {2};   // top
Curve Loop(3) = {1, 10, -5, -9};  Surface(3) = {3};   // ymin
Curve Loop(4) = {3, 12, -7, -11}; Surface(4) = {4};   // ymax
Curve Loop(5) = {4, 9, -8, -12};  Surface(5) = {5};   // xmin
Curve Loop(6) = {2, 11, -6, -10}; Surface(6) = {6};   // xmax
Surface Loop(1) = {1, 2, 3, 4, 5, 6};
Volume(1) = {1};
If (hex)
  Transfinite Curve{1:8} = n + 1;
  Transfinite Curve{9:12} = m + 1;
  Transfinite Surface{1:6};
  Recombine Surface{1:6};
  Transfinite Volume{1};
  Recombine Volume{1};
EndIf
Physical Surface("bottom") = {1};
Physical Surface("top") = {2};
Physical Surface("ymin") = {3};
Physical Surface("ymax") = {4};
Physical Surface("xmin") = {5};
Physical Surface("xmax") = {6};
Physical Volume("body") = {1};
Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;
Mesh.MshFileVersion = 2.2;
