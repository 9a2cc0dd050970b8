// The unit cube (verification: manufactured solutions), faces labelled x0, x1, y0, y1, z0, z1.
SetFactory("OpenCASCADE");
DefineConstant[ h = 0.25 ];
Box(1) = {0, 0, 0, 1, 1, 1};
eps = 1e-6;
Physical Volume("solid") = {1};
Physical Surface("x0") = Surface In BoundingBox{-eps, -eps, -eps, eps, 1 + eps, 1 + eps};
Physical Surface("x1") = Surface In BoundingBox{1 - eps, -eps, -eps, 1 + eps, 1 + eps, 1 + eps};
Physical Surface("y0") = Surface In BoundingBox{-eps, -eps, -eps, 1 + eps, eps, 1 + eps};
Physical Surface("y1") = Surface In BoundingBox{-eps, 1 - eps, -eps, 1 + eps, 1 + eps, 1 + eps};
Physical Surface("z0") = Surface In BoundingBox{-eps, -eps, -eps, 1 + eps, 1 + eps, eps};
Physical Surface("z1") = Surface In BoundingBox{-eps, -eps, 1 - eps, 1 + eps, 1 + eps, 1 + eps};
Mesh.MeshSizeFromPoints = 0; // h alone sets the size (OCC points carry a default size)
Mesh.MeshSizeMax = h;
