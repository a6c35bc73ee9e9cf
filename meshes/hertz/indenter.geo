// Indenter: a full disc of radius R centred at (xc, yc), meshed with Tri6.
// Facing dir = +1 (+x) or -1 (-x), its boundary arcs are split at x = xclamp
// (the arc behind it, dir (x - xclamp) < 0, is "clamp") and at x = xcontact (the
// arc in front, dir (x - xcontact) > 0, is "contact"); the rest is "free".
// Optional grading: mesh size hc within a distance rc of the front point,
// growing to h over a further distance dc.
// Parameters (gmsh -setnumber NAME VALUE): h, R, xc, yc, xclamp, xcontact, dir, hc, rc, dc.
If (!Exists(h))        h = 0.1;   EndIf
If (!Exists(R))        R = 1.0;   EndIf
If (!Exists(xc))       xc = -1.0; EndIf
If (!Exists(yc))       yc = 0.0;  EndIf
If (!Exists(xclamp))   xclamp = -1.8; EndIf
If (!Exists(xcontact)) xcontact = -0.5; EndIf
If (!Exists(dir))      dir = 1;    EndIf
If (!Exists(hc))       hc = h;     EndIf
If (!Exists(dc))       dc = R;     EndIf
If (!Exists(rc))       rc = 0;     EndIf

tc = Acos(dir * (xcontact - xc) / R);   // half-angle of the contact arc
tk = Acos(dir * (xclamp - xc) / R);     // angle where the clamp arc starts

Point(1) = {xc, yc, 0, h};
Point(2) = {xc + dir*R*Cos(-tc), yc + R*Sin(-tc), 0, h};
Point(3) = {xc + dir*R*Cos(tc),  yc + R*Sin(tc),  0, h};
Point(4) = {xc + dir*R*Cos(tk),  yc + R*Sin(tk),  0, h};
Point(5) = {xc + dir*R*Cos(-tk), yc + R*Sin(-tk), 0, h};
Point(6) = {xc + dir*R, yc, 0, hc};
Point(7) = {xc - dir*R, yc, 0, h};

Circle(1) = {2, 1, 6};   // contact, lower half
Circle(2) = {6, 1, 3};   // contact, upper half
Circle(3) = {3, 1, 4};   // free, upper
Circle(4) = {4, 1, 7};   // clamp, upper half
Circle(5) = {7, 1, 5};   // clamp, lower half
Circle(6) = {5, 1, 2};   // free, lower
Curve Loop(1) = {1, 2, 3, 4, 5, 6};
Plane Surface(1) = {1};

If (hc < h)
  Field[1] = Distance;
  Field[1].PointsList = {6};
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

Physical Curve("contact") = {1, 2};
Physical Curve("clamp") = {4, 5};
Physical Curve("free") = {3, 6};
Physical Surface("body") = {1};

Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;
Mesh.MshFileVersion = 2.2;
