// A 3D block, second order: Tet10 (hex = 0) or Hex27 (hex = 1, transfinite,
// n cells an edge). Its corners are those of the box [0, L]^3 moved by
// skew (0: the box), so that its faces are not plane and its cells are
// distorted. Groups: the faces xmin, xmax, ymin, ymax, zmin, zmax (of the
// undistorted box's naming), the volume "body".
// Parameters (gmsh -setnumber NAME VALUE): h, L, skew, hex, n, order (2;
// 1 for the first-order mesh a test refuses).
If (!Exists(h)) h = 0.25; EndIf
If (!Exists(L)) L = 1; EndIf
If (!Exists(skew)) skew = 0; EndIf
If (!Exists(hex)) hex = 0; EndIf
If (!Exists(n)) n = 3; EndIf
If (!Exists(order)) order = 2; EndIf

s = skew * L;
Point(1) = {0, 0, 0, h};
Point(2) = {L + 0.1 * s, 0.05 * s, 0, h};
Point(3) = {L + 0.2 * s, L - 0.1 * s, 0.1 * s, h};
Point(4) = {-0.05 * s, L, 0, h};
Point(5) = {0.1 * s, 0, L + 0.05 * s, h};
Point(6) = {L, -0.1 * s, L, h};
Point(7) = {L + 0.15 * s, L - 0.1 * s, L + 0.2 * s, h};
Point(8) = {0, L + 0.1 * s, L - 0.1 * s, h};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Line(9) = {1, 5}; Line(10) = {2, 6}; Line(11) = {3, 7}; Line(12) = {4, 8};
Curve Loop(1) = {1, 2, 3, 4};     Surface(1) = {1};   // zmin
Curve Loop(2) = {5, 6, 7, 8};     Surface(2) = {2};   // zmax
Curve Loop(3) = {1, 10, -5, -9};  Surface(3) = {3};   // ymin
Curve Loop(4) = {3, 12, -7, -11}; Surface(4) = {4};   // ymax
Curve Loop(5) = {4, 9, -8, -12};  Surface(5) = {5};   // xmin
Curve Loop(6) = {2, 11, -6, -10}; Surface(6) = {6};   // xmax
Surface Loop(1) = {1, 2, 3, 4, 5, 6};
Volume(1) = {1};
If (hex)
  Transfinite Curve{1:12} = n + 1;
  Transfinite Surface{1:6};
  Recombine Surface{1:6};
  Transfinite Volume{1};
  Recombine Volume{1};
EndIf
Physical Surface("zmin") = {1};
Physical Surface("zmax") = {2};
Physical Surface("ymin") = {3};
Physical Surface("ymax") = {4};
Physical Surface("xmin") = {5};
Physical Surface("xmax") = {6};
Physical Volume("body") = {1};
Mesh.ElementOrder = order;
Mesh.SecondOrderIncomplete = 0;
Mesh.MshFileVersion = 2.2;
