// Upper half (y >= 0) of the hertz block: the rectangle [x0, x0+W] x [0, H/2]
// on a structured Quad9 grid, the same cells as the upper half of
// meshes/hertz/block.geo at the same h. Edges: "contact" (left, x = x0),
// "push" (right), "top" (y = H/2), "symmetry" (the cut y = 0).
// A size field from the program (-accuracy, adapt = 1): an unstructured
// all-quad mesh, its sizes from the field.
// Parameters (gmsh -setnumber NAME VALUE): h, x0, W, H (H: the full height), adapt.
If (!Exists(h))  h = 0.1;  EndIf
If (!Exists(x0)) x0 = 0.0; EndIf
If (!Exists(W))  W = 1.0;  EndIf
If (!Exists(H))  H = 2.0;  EndIf

nx = Ceil(W / h - 1e-9);
ny = Ceil(0.5 * H / h - 1e-9);

Point(1) = {x0, 0, 0, h};
Point(2) = {x0 + W, 0, 0, h};
Point(3) = {x0 + W, H/2, 0, h};
Point(4) = {x0, H/2, 0, h};
Line(1) = {1, 2};   // symmetry cut
Line(2) = {2, 3};   // right
Line(3) = {3, 4};   // top
Line(4) = {4, 1};   // left
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
If (!Exists(adapt)) adapt = 0; EndIf
If (adapt)
  Mesh.Algorithm = 6;
  Mesh.RecombinationAlgorithm = 3;
Else
  Transfinite Curve{1, 3} = nx + 1;
  Transfinite Curve{2, 4} = ny + 1;
  Transfinite Surface{1};
EndIf
Recombine Surface{1};

Physical Curve("contact") = {4};
Physical Curve("push") = {2};
Physical Curve("top") = {3};
Physical Curve("symmetry") = {1};
Physical Surface("body") = {1};

Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;
Mesh.MshFileVersion = 2.2;
