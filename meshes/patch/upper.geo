// Contact patch test, upper block: the rectangle [0, W] x [0, H], unstructured
// Tri6 of size hr * h. Edges: "contact" (bottom, y = 0), "symmetry" (left,
// x = 0), "push" (top), "free" (right).
// The interface edge has n = Round(W / (hr h)) elements whose lengths grow from
// x = 0 by the factor q. With q = 1 the middle x = W/2 would be a node of both
// meshes (the lower block's grid is uniform); q = 1.01 moves every node off the
// lower grid: at h = 0.1, W = 1 the nearest pair of interface nodes (mid-edge
// ones included) is 0.0054 apart, and only the two end nodes are shared.
// Parameters (gmsh -setnumber NAME VALUE): h, W, H, hr, q.
If (!Exists(h))  h = 0.1;  EndIf
If (!Exists(W))  W = 1.0;  EndIf
If (!Exists(H))  H = 1.0;  EndIf
If (!Exists(hr)) hr = 1.6; EndIf
If (!Exists(q))  q = 1.01; EndIf

ht = hr * h;
n = Floor(W / ht + 0.5);

Point(1) = {0, 0, 0, ht};
Point(2) = {W, 0, 0, ht};
Point(3) = {W, H, 0, ht};
Point(4) = {0, H, 0, ht};
Line(1) = {1, 2};   // bottom: the interface
Line(2) = {2, 3};   // right
Line(3) = {3, 4};   // top
Line(4) = {4, 1};   // left
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1} = n + 1 Using Progression q;

Physical Curve("contact") = {1};
Physical Curve("symmetry") = {4};
Physical Curve("push") = {3};
Physical Curve("free") = {2};
Physical Surface("body") = {1};

Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;
Mesh.MshFileVersion = 2.2;
