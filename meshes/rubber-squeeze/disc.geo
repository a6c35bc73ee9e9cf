// A quarter of a disc of radius R centred at the origin (x >= 0, y >= 0),
// Tri6 (quads = 0) or Quad9 (quads = 1, the triangulation recombined), size h
// throughout, second-order nodes on the arc. Groups: "contact" (the arc),
// "symx" (the edge x = 0), "symy" (the edge y = 0).
// Parameters (gmsh -setnumber NAME VALUE): h, R, quads.
If (!Exists(h))     h = 0.1; EndIf
If (!Exists(R))     R = 1.0; EndIf
If (!Exists(quads)) quads = 0; EndIf

Point(1) = {0, 0, 0, h};
Point(2) = {R, 0, 0, h};
Point(3) = {0, R, 0, h};
Line(1) = {1, 2};
Circle(2) = {2, 1, 3};
Line(3) = {3, 1};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
If (quads)
  Recombine Surface{1};
EndIf

Physical Curve("contact") = {2};
Physical Curve("symx") = {3};
Physical Curve("symy") = {1};
Physical Surface("body") = {1};

Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;
Mesh.MshFileVersion = 2.2;
