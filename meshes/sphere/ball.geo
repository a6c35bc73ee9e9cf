// A hemisphere of radius R in r-z (an axisymmetric scene: x = r, y = z), its
// lowest point at the origin on the axis, its centre (0, R): the quarter
// disc's section. Tri6, size h within a distance dp of the origin, growing
// linearly to hfar over a further dc (never finer than h). Boundary groups:
// "contact" (the arc below the angle tc from the axis, tc in degrees),
// "free" (the rest of the arc), "equator" (the flat cut y = R), "axis"
// (x = 0; the program holds u_r = 0 there by itself). With ra > 0 also of
// size hr within wr (2 hr) of the point (ra, 0), growing linearly to hfar at
// rr from it (dp + dc unless given): meshes/sphere3d/ball.geo's ring around
// the contact's edge in the meridian (tests/test_ring3d.py).
// Parameters (gmsh -setnumber NAME VALUE): h, R, tc, hfar, dp, dc, ra, hr, wr, rr.
If (!Exists(h))    h = 0.01;  EndIf
If (!Exists(R))    R = 1.0;   EndIf
If (!Exists(tc))   tc = 30;   EndIf
If (!Exists(hfar)) hfar = 0.1; EndIf
If (!Exists(dp))   dp = 0.2;  EndIf
If (!Exists(dc))   dc = 0.5;  EndIf
If (!Exists(ra))   ra = 0;    EndIf
If (!Exists(hr))   hr = h;    EndIf
If (!Exists(wr))   wr = 2 * hr; EndIf
If (!Exists(rr))   rr = dp + dc; EndIf
If (hfar < h) hfar = h; EndIf
t = tc * Pi / 180;

Point(1) = {0, R, 0, hfar};                          // centre
Point(2) = {0, 0, 0, h};                             // lowest point
Point(3) = {R * Sin(t), R - R * Cos(t), 0, hfar};    // end of the contact arc
Point(4) = {R, R, 0, hfar};                          // equator
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Line(3) = {4, 1};
Line(4) = {1, 2};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

Field[1] = Distance;
Field[1].PointsList = {2};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h;
Field[2].SizeMax = hfar;
Field[2].DistMin = dp;
Field[2].DistMax = dp + dc;
Background Field = 2;
If (ra > 0)
  Field[3] = MathEval;
  Field[3].F = Sprintf("Sqrt((x - %g) * (x - %g) + y * y)", ra, ra);
  Field[4] = Threshold;
  Field[4].InField = 3;
  Field[4].SizeMin = hr;
  Field[4].SizeMax = hfar;
  Field[4].DistMin = wr;
  Field[4].DistMax = rr;
  Field[5] = Min;
  Field[5].FieldsList = {2, 4};
  Background Field = 5;
EndIf
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;

Physical Curve("contact") = {1};
Physical Curve("free") = {2};
Physical Curve("equator") = {3};
Physical Curve("axis") = {4};
Physical Surface("body") = {1};

Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;
Mesh.MshFileVersion = 2.2;
