// Roller: a full disc of radius R centred at (0, yc), Tri6. Its two contact
// arcs face down and up, each within the angle tc (degrees) of the vertical:
// "bottom" around (0, yc - R), "top" around (0, yc + R); the rest of the
// circle is "free". The roller has no condition of its own: it is held by its
// two contacts alone. Size h within dp of each contact point, growing
// linearly to hfar over a further dc (never finer than h).
// Parameters (gmsh -setnumber NAME VALUE): h, R, yc, tc, hfar, dp, dc.
If (!Exists(h))    h = 0.02;  EndIf
If (!Exists(R))    R = 5.0;   EndIf
If (!Exists(yc))   yc = 0.0;  EndIf
If (!Exists(tc))   tc = 20;   EndIf
If (!Exists(hfar)) hfar = 0.5; EndIf
If (!Exists(dp))   dp = 0.5;  EndIf
If (!Exists(dc))   dc = 2.0;  EndIf
If (hfar < h) hfar = h; EndIf
t = tc * Pi / 180;

Point(1) = {0, yc, 0, hfar};                              // centre
Point(2) = {0, yc - R, 0, h};                             // lowest point
Point(3) = {R * Sin(t), yc - R * Cos(t), 0, hfar};        // bottom arc, right end
Point(4) = {R * Sin(t), yc + R * Cos(t), 0, hfar};        // top arc, right end
Point(5) = {0, yc + R, 0, h};                             // highest point
Point(6) = {-R * Sin(t), yc + R * Cos(t), 0, hfar};       // top arc, left end
Point(7) = {-R * Sin(t), yc - R * Cos(t), 0, hfar};       // bottom arc, left end
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Circle(3) = {4, 1, 5};
Circle(4) = {5, 1, 6};
Circle(5) = {6, 1, 7};
Circle(6) = {7, 1, 2};
Curve Loop(1) = {1, 2, 3, 4, 5, 6};
Plane Surface(1) = {1};

Field[1] = Distance;
Field[1].PointsList = {2, 5};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h;
Field[2].SizeMax = hfar;
Field[2].DistMin = dp;
Field[2].DistMax = dp + dc;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;

Physical Curve("bottom") = {6, 1};
Physical Curve("top") = {3, 4};
Physical Curve("free") = {2, 5};
Physical Surface("body") = {1};

Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;
Mesh.MshFileVersion = 2.2;
