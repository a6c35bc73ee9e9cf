// Contact patch test, lower block: the rectangle [0, W] x [-H, 0] on a structured
// Quad9 grid of size h. Edges: "contact" (top, y = 0), "symmetry" (left, x = 0),
// "base" (bottom), "free" (right).
// Parameters (gmsh -setnumber NAME VALUE): h, W, H.
If (!Exists(h)) h = 0.1; EndIf
If (!Exists(W)) W = 1.0; EndIf
If (!Exists(H)) H = 1.0; EndIf

nx = Ceil(W / h - 1e-9);
ny = Ceil(H / h - 1e-9);

Point(1) = {0, -H, 0, h};
Point(2) = {W, -H, 0, h};
Point(3) = {W, 0, 0, h};
Point(4) = {0, 0, 0, h};
Line(1) = {1, 2};   // bottom
Line(2) = {2, 3};   // right
Line(3) = {3, 4};   // top: the interface
Line(4) = {4, 1};   // left
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = nx + 1;
Transfinite Curve{2, 4} = ny + 1;
Transfinite Surface{1};
Recombine Surface{1};

Physical Curve("contact") = {3};
Physical Curve("symmetry") = {4};
Physical Curve("base") = {1};
Physical Curve("free") = {2};
Physical Surface("body") = {1};

Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;
Mesh.MshFileVersion = 2.2;
