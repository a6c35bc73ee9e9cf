// A block [-W, W] x [-D, 0] in the plane (x, y), its top y = 0, of length Ly
// along z: its cross-section meshed in quadrilaterals of size h within rc of
// the origin (the top's part |x| <= c of size h), growing to hf at 4 rc, and
// extruded along z in nl layers: Hex27. With dim2 = 1 the cross-section
// alone (Quad9), for a plane-strain run of the same mesh. Groups: top (|x|
// <= c, the contact surface), rest (the top beyond c), sides (x = -W, W),
// bottom (y = -D), and in 3D front (z = 0) and back (z = Ly); the body
// "body". tests/test_line3d.py.
// Parameters (gmsh -setnumber NAME VALUE): W, D, h, hf, rc, c, Ly, nl, dim2.
If (!Exists(dim2)) dim2 = 0; EndIf
If (!Exists(W)) W = 2; EndIf
If (!Exists(D)) D = 2; EndIf
If (!Exists(h)) h = 0.02; EndIf
If (!Exists(hf)) hf = 0.3; EndIf
If (!Exists(rc)) rc = 0.2; EndIf
If (!Exists(Ly)) Ly = 0.05; EndIf
If (!Exists(nl)) nl = 2; EndIf
If (!Exists(c)) c = 0.3; EndIf
Point(1) = {-W, 0, 0, hf};
Point(2) = {-c, 0, 0, h};
Point(3) = {0, 0, 0, h};
Point(4) = {c, 0, 0, h};
Point(5) = {W, 0, 0, hf};
Point(6) = {W, -D, 0, hf};
Point(7) = {-W, -D, 0, hf};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 5};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 1};
Curve Loop(1) = {1, 2, 3, 4, 5, 6, 7};
Plane Surface(1) = {1};
Field[1] = Distance; Field[1].PointsList = {3};
Field[2] = Threshold; Field[2].InField = 1; Field[2].SizeMin = h; Field[2].SizeMax = hf; Field[2].DistMin = rc; Field[2].DistMax = 4 * rc;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0; Mesh.MeshSizeFromPoints = 0;
Recombine Surface{1};
If (dim2)
  Physical Curve("top") = {2, 3};
  Physical Curve("rest") = {1, 4};
  Physical Curve("sides") = {5, 7};
  Physical Curve("bottom") = {6};
  Physical Surface("body") = {1};
Else
  ex[] = Extrude {0, 0, Ly} { Surface{1}; Layers{nl}; Recombine; };
  Physical Surface("front") = {1};
  Physical Surface("back") = {ex[0]};
  Physical Surface("top") = {ex[3], ex[4]};
  Physical Surface("rest") = {ex[2], ex[5]};
  Physical Surface("sides") = {ex[6], ex[8]};
  Physical Surface("bottom") = {ex[7]};
  Physical Volume("body") = {ex[1]};
EndIf
Mesh.ElementOrder = 2; Mesh.SecondOrderIncomplete = 0;
Mesh.Algorithm = 6; Mesh.RecombinationAlgorithm = 3;
