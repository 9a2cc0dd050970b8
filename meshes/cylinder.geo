// Lame's thick-walled cylinder (verification): inner radius Ri, outer radius Ro, length L.
// Pressure on "inner", free "outer", axial displacement fixed on "bottom" and "top" (plane strain).
SetFactory("OpenCASCADE");
DefineConstant[ Ri = 1.0, Ro = 2.0, L = 0.5, h = 0.25 ];
Cylinder(1) = {0, 0, 0, 0, 0, L, Ro};
Cylinder(2) = {0, 0, 0, 0, 0, L, Ri};
BooleanDifference{ Volume{1}; Delete; }{ Volume{2}; Delete; }
eps = 1e-6;
bottom() = Surface In BoundingBox{-Ro - eps, -Ro - eps, -eps, Ro + eps, Ro + eps, eps};
top()    = Surface In BoundingBox{-Ro - eps, -Ro - eps, L - eps, Ro + eps, Ro + eps, L + eps};
inner()  = Surface In BoundingBox{-Ri - eps, -Ri - eps, -eps, Ri + eps, Ri + eps, L + eps};
inner() -= bottom();
inner() -= top();
outer()  = Boundary{ Volume{1}; };
outer() -= bottom();
outer() -= top();
outer() -= inner();
Physical Volume("solid") = {1};
Physical Surface("inner") = inner();
Physical Surface("outer") = outer();
Physical Surface("bottom") = bottom();
Physical Surface("top") = top();
Mesh.MeshSizeFromPoints = 0; // h alone sets the size (OCC points carry a default size)
Mesh.MeshSizeMax = h;
