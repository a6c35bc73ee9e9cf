// Rectangle [x0, x0 + L] x [y0, y0 + H] with each side its own group, counter-clockwise:
// "bottom", "right", "top", "left". Tri6 (quads = 0, unstructured) or Quad9
// (quads = 1, structured). Parameters: h, x0, y0, L, H, quads.
If (!Exists(h))     h = 0.1;  EndIf
If (!Exists(x0))    x0 = 0.0; EndIf
If (!Exists(y0))    y0 = 0.0; EndIf
If (!Exists(L))     L = 1.0;  EndIf
If (!Exists(H))     H = 1.0;  EndIf
If (!Exists(quads)) quads = 0; EndIf

Point(1) = {x0, y0, 0, h};
Point(2) = {x0 + L, y0, 0, h};
Point(3) = {x0 + L, y0 + H, 0, h};
Point(4) = {x0, y0 + H, 0, h};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
If (quads)
  Transfinite Curve{1, 3} = Ceil(L / h - 1e-9) + 1;
  Transfinite Curve{2, 4} = Ceil(H / h - 1e-9) + 1;
  Transfinite Surface{1};
  Recombine Surface{1};
EndIf

Physical Curve("bottom") = {1};
Physical Curve("right") = {2};
Physical Curve("top") = {3};
Physical Curve("left") = {4};
Physical Surface("body") = {1};

Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;
Mesh.MshFileVersion = 2.2;
