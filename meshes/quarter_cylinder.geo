// A quarter of Lame's thick-walled cylinder (x, y >= 0), inner radius Ri, outer Ro, length L:
// with symmetry conditions on "sym_x" (x = 0) and "sym_y" (y = 0) and the axial displacement
// fixed on "bottom" and "top" (plane strain) the problem has no rigid motion left.
SetFactory("OpenCASCADE");
DefineConstant[ Ri = 1.0, Ro = 2.0, L = 0.5, h = 0.25 ];
Cylinder(1) = {0, 0, 0, 0, 0, L, Ro, Pi / 2};
Cylinder(2) = {0, 0, 0, 0, 0, L, Ri, Pi / 2};
BooleanDifference{ Volume{1}; Delete; }{ Volume{2}; Delete; }
eps = 1e-6;
bottom() = Surface In BoundingBox{-eps, -eps, -eps, Ro + eps, Ro + eps, eps};
top()    = Surface In BoundingBox{-eps, -eps, L - eps, Ro + eps, Ro + eps, L + eps};
symx()   = Surface In BoundingBox{-eps, -eps, -eps, eps, Ro + eps, L + eps};
symy()   = Surface In BoundingBox{-eps, -eps, -eps, Ro + eps, eps, L + eps};
inner()  = Surface In BoundingBox{-eps, -eps, -eps, Ri + eps, Ri + eps, L + eps};
inner() -= bottom();
inner() -= top();
inner() -= symx();
inner() -= symy();
outer()  = Boundary{ Volume{1}; };
outer() -= bottom();
outer() -= top();
outer() -= symx();
outer() -= symy();
outer() -= inner();
Physical Volume("solid") = {1};
Physical Surface("inner") = inner();
Physical Surface("outer") = outer();
Physical Surface("bottom") = bottom();
Physical Surface("top") = top();
Physical Surface("sym_x") = symx();
Physical Surface("sym_y") = symy();
Mesh.MeshSizeFromPoints = 0; // h alone sets the size (OCC points carry a default size)
Mesh.MeshSizeMax = h;
