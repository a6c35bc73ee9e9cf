// Disc of radius R centred at (xc, yc), Tri6 (quads = 0) or Quad9 (quads = 1,
// unstructured: the triangulation recombined, Gmsh's default algorithm; its
// Frontal-Delaunay for quads, 8, crashes Gmsh 4.8.4 here), with second-order
// nodes on the circle. The whole boundary is the group "boundary".
// Parameters (gmsh -setnumber NAME VALUE): h, R, xc, yc, quads.
If (!Exists(h))  h = 0.1;  EndIf
If (!Exists(R))  R = 1.0;  EndIf
If (!Exists(xc)) xc = 0.0; EndIf
If (!Exists(yc)) yc = 0.0; EndIf
If (!Exists(quads)) quads = 0; EndIf

Point(1) = {xc, yc, 0, h};
Point(2) = {xc + R, yc, 0, h};
Point(3) = {xc, yc + R, 0, h};
Point(4) = {xc - R, yc, 0, h};
Point(5) = {xc, yc - R, 0, h};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Circle(3) = {4, 1, 5};
Circle(4) = {5, 1, 2};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
If (quads)
  Recombine Surface{1};
EndIf

Physical Curve("boundary") = {1, 2, 3, 4};
Physical Surface("body") = {1};

Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;
Mesh.MshFileVersion = 2.2;
