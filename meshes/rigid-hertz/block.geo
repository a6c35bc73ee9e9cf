// Block: the rectangle [x0, x0+W] x [-H/2, H/2] on a structured Quad9 grid,
// symmetric about y = 0. Edges: "contact" (left), "push" (right), "top", "bottom".
// Optional grading (hc < h): an unstructured all-quad mesh of size hc within a
// distance rc of the point (x0, 0), growing to h over a further distance dc.
// A size field from the program (-accuracy, adapt = 1): the same unstructured
// all-quad mesh, its sizes from the field.
// Parameters (gmsh -setnumber NAME VALUE): h, x0, W, H, hc, rc, dc, adapt.
If (!Exists(h))  h = 0.1;  EndIf
If (!Exists(x0)) x0 = 0.0; EndIf
If (!Exists(W))  W = 1.0;  EndIf
If (!Exists(H))  H = 2.0;  EndIf
If (!Exists(hc)) hc = h;   EndIf
If (!Exists(dc)) dc = W;   EndIf
If (!Exists(rc)) rc = 0;   EndIf
If (!Exists(adapt)) adapt = 0; EndIf

nx = Ceil(W / h - 1e-9);
ny = 2 * Ceil(0.5 * H / h - 1e-9);

Point(1) = {x0, -H/2, 0, h};
Point(2) = {x0 + W, -H/2, 0, h};
Point(3) = {x0 + W, H/2, 0, h};
Point(4) = {x0, H/2, 0, h};
Line(1) = {1, 2};   // bottom
Line(2) = {2, 3};   // right
Line(3) = {3, 4};   // top
Line(4) = {4, 1};   // left
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
If (hc < h || adapt)
  If (hc < h)
    Point(5) = {x0, 0, 0, hc};
    Field[1] = Distance;
    Field[1].PointsList = {5};
    Field[2] = Threshold;
    Field[2].InField = 1;
    Field[2].SizeMin = hc;
    Field[2].SizeMax = h;
    Field[2].DistMin = rc;
    Field[2].DistMax = rc + dc;
    Background Field = 2;
    Mesh.MeshSizeExtendFromBoundary = 0;
    Mesh.MeshSizeFromPoints = 0;
  EndIf
  Mesh.Algorithm = 6;
  Mesh.RecombinationAlgorithm = 3;
  Recombine Surface{1};
Else
  Transfinite Curve{1, 3} = nx + 1;
  Transfinite Curve{2, 4} = ny + 1;
  Transfinite Surface{1};
  Recombine Surface{1};
EndIf

Physical Curve("contact") = {4};
Physical Curve("push") = {2};
Physical Curve("top") = {3};
Physical Curve("bottom") = {1};
Physical Surface("body") = {1};

Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;
Mesh.MshFileVersion = 2.2;
