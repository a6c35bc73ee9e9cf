// Square [0, L] x [0, L], Tri6 (quads = 0, unstructured) or Quad9 (quads = 1,
// structured). The whole boundary, counter-clockwise, is the group "boundary".
// Parameters (gmsh -setnumber NAME VALUE): h, L, quads.
If (!Exists(h))     h = 0.1;  EndIf
If (!Exists(L))     L = 1.0;  EndIf
If (!Exists(quads)) quads = 0; EndIf

Point(1) = {0, 0, 0, h};
Point(2) = {L, 0, 0, h};
Point(3) = {L, L, 0, h};
Point(4) = {0, L, 0, h};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
If (quads)
  n = Ceil(L / h - 1e-9);
  Transfinite Curve{1, 2, 3, 4} = n + 1;
  Transfinite Surface{1};
  Recombine Surface{1};
EndIf

Physical Curve("boundary") = {1, 2, 3, 4};
Physical Surface("body") = {1};

Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;
Mesh.MshFileVersion = 2.2;
