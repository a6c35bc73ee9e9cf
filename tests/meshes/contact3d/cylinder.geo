// The lower half of a cylinder of radius R, its axis along z at (0, R),
// touching the plane y = 0 along the z axis, of length Ly: its cross-section
// (x, y) meshed in quadrilaterals of size h within rc of the contact line,
// growing to hf at 3 rc, and extruded along z in nl layers: Hex27 (Quad9 on
// its curved faces). With dim2 = 1 the cross-section alone, Quad9 in the
// plane (x, y), for a plane-strain run of the same mesh. The surface is cut
// at y = zc so that its curved part is two: "cap" (y <= zc, the contact
// surface) and "side". Groups: top (y = R), cap, side, and in 3D front (z =
// 0) and back (z = Ly); the body "body". tests/test_line3d.py.
// Parameters (gmsh -setnumber NAME VALUE): R, h, hf, rc, zc, Ly, nl, dim2.
// (Mesh.Algorithm 8 with this size field crashes Gmsh 4.8.4: 6 and the
// blossom full-quad recombination here.)
If (!Exists(dim2)) dim2 = 0; EndIf
If (!Exists(R)) R = 1; EndIf
If (!Exists(h)) h = 0.02; EndIf
If (!Exists(hf)) hf = 0.2; EndIf
If (!Exists(rc)) rc = 0.2; EndIf
If (!Exists(zc)) zc = 0.1; EndIf
If (!Exists(Ly)) Ly = 0.05; EndIf
If (!Exists(nl)) nl = 1; EndIf
xc = Sqrt(R * R - (R - zc) * (R - zc));
Point(1) = {0, R, 0, hf};
Point(2) = {-R, R, 0, hf};
Point(3) = {-xc, zc, 0, hf};
Point(4) = {0, 0, 0, h};
Point(5) = {xc, zc, 0, hf};
Point(6) = {R, R, 0, hf};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Circle(3) = {4, 1, 5};
Circle(4) = {5, 1, 6};
Line(5) = {6, 1};
Line(6) = {1, 2};
Curve Loop(1) = {1, 2, 3, 4, 5, 6};
Plane Surface(1) = {1};
Field[1] = Distance; Field[1].PointsList = {4};
Field[2] = Threshold; Field[2].InField = 1; Field[2].SizeMin = h; Field[2].SizeMax = hf; Field[2].DistMin = rc; Field[2].DistMax = 3 * rc;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0; Mesh.MeshSizeFromPoints = 0;
Recombine Surface{1};
If (dim2)
  Physical Curve("cap") = {2, 3};
  Physical Curve("side") = {1, 4};
  Physical Curve("top") = {5, 6};
  Physical Surface("body") = {1};
Else
  ex[] = Extrude {0, 0, Ly} { Surface{1}; Layers{nl}; Recombine; };
  Physical Surface("front") = {1};
  Physical Surface("back") = {ex[0]};
  Physical Surface("cap") = {ex[3], ex[4]};
  Physical Surface("side") = {ex[2], ex[5]};
  Physical Surface("top") = {ex[6], ex[7]};
  Physical Volume("body") = {ex[1]};
EndIf
Mesh.ElementOrder = 2; Mesh.SecondOrderIncomplete = 0;
Mesh.Algorithm = 6; Mesh.RecombinationAlgorithm = 3;
