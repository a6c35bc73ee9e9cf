// A quarter of a thick-walled tube, inner radius a, outer radius b, centred at
// the origin: the annulus a <= r <= b in the first quadrant. Tri6 (quads = 0,
// unstructured) or Quad9 (quads = 1, structured). Groups: "inner" (the bore),
// "outer", "xaxis" (y = 0) and "yaxis" (x = 0), the cuts of the symmetry planes.
// Parameters (gmsh -setnumber NAME VALUE): h, a, b, quads.
If (!Exists(h))     h = 0.1;  EndIf
If (!Exists(a))     a = 1.0;  EndIf
If (!Exists(b))     b = 2.0;  EndIf
If (!Exists(quads)) quads = 1; EndIf

Point(1) = {0, 0, 0, h};
Point(2) = {a, 0, 0, h};
Point(3) = {b, 0, 0, h};
Point(4) = {0, b, 0, h};
Point(5) = {0, a, 0, h};
Line(1) = {2, 3};
Circle(2) = {3, 1, 4};
Line(3) = {4, 5};
Circle(4) = {5, 1, 2};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
If (quads)
  nr = Ceil((b - a) / h - 1e-9);
  nt = Ceil(Pi / 4 * (a + b) / h - 1e-9);
  Transfinite Curve{1, 3} = nr + 1;
  Transfinite Curve{2, 4} = nt + 1;
  Transfinite Surface{1};
  Recombine Surface{1};
EndIf

Physical Curve("xaxis") = {1};
Physical Curve("outer") = {2};
Physical Curve("yaxis") = {3};
Physical Curve("inner") = {4};
Physical Surface("body") = {1};

Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;
Mesh.MshFileVersion = 2.2;
