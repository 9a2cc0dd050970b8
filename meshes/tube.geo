// A straight artery: fluid cylinder (radius Ri) inside a wall annulus (outer radius Ro), length L,
// as ONE tetrahedral mesh, conforming at the fluid-wall interface (seed Fig. 1).
// Parameters (gmsh -setnumber NAME VALUE): Ri, Ro, L in cm; h the target element size;
// nwall the number of element layers through the wall thickness.
// The seed's geometries: #1 0.15/0.21/2.5, #2 0.08/0.10/5, #3 0.08/0.11/10 (see make-meshes).
SetFactory("OpenCASCADE");
// outlets = 2 splits the fluid at y = 0 into two halves, so the outlet is two groups, outlet_a
// (y > 0) and outlet_b (y < 0): a mesh with two outlets for the outlets' tests.
DefineConstant[ Ri = 0.15, Ro = 0.21, L = 2.5, h = 0.05, nwall = 2, outlets = 1 ];

If (outlets == 2)
  Cylinder(1) = {0, 0, 0, 0, 0, L, Ri, Pi};
  Cylinder(3) = {0, 0, 0, 0, 0, L, Ri, Pi};
  Rotate {{0, 0, 1}, {0, 0, 0}, Pi} { Volume{3}; }
  Cylinder(2) = {0, 0, 0, 0, 0, L, Ro};
  BooleanFragments{ Volume{2}; Delete; }{ Volume{1, 3}; Delete; }
Else
  Cylinder(1) = {0, 0, 0, 0, 0, L, Ri};
  Cylinder(2) = {0, 0, 0, 0, 0, L, Ro};
  BooleanFragments{ Volume{2}; Delete; }{ Volume{1}; Delete; }
EndIf

// After the fragments: the inner cylinder and the annulus; find their faces by position.
eps = 1e-6 * L;
fluid() = Volume In BoundingBox{-Ri - eps, -Ri - eps, -eps, Ri + eps, Ri + eps, L + eps};
all() = Volume{:};
wall() = all();
wall() -= fluid();

inlet()      = Surface In BoundingBox{-Ri - eps, -Ri - eps, -eps, Ri + eps, Ri + eps, eps};
outlet()     = Surface In BoundingBox{-Ri - eps, -Ri - eps, L - eps, Ri + eps, Ri + eps, L + eps};
ends0()      = Surface In BoundingBox{-Ro - eps, -Ro - eps, -eps, Ro + eps, Ro + eps, eps};
ends1()      = Surface In BoundingBox{-Ro - eps, -Ro - eps, L - eps, Ro + eps, Ro + eps, L + eps};
inner()      = Surface In BoundingBox{-Ri - eps, -Ri - eps, -eps, Ri + eps, Ri + eps, L + eps};
wallIn()     = ends0();
wallIn()    -= inlet();
wallOut()    = ends1();
wallOut()   -= outlet();
interface()  = inner();
interface() -= inlet();
interface() -= outlet();
If (outlets == 2)
  interface() -= Surface In BoundingBox{-Ri - eps, -eps, -eps, Ri + eps, eps, L + eps}; // between the halves
  outletA() = Surface In BoundingBox{-Ri - eps, -eps, L - eps, Ri + eps, Ri + eps, L + eps};
  outletB() = outlet();
  outletB() -= outletA();
EndIf
fluidFaces() = Boundary{ Volume{fluid()}; };
wallFaces()  = Boundary{ Volume{wall()}; };
outer()      = wallFaces();
outer()     -= interface();
outer()     -= wallIn();
outer()     -= wallOut();

Physical Volume("fluid") = fluid();
Physical Volume("wall") = wall();
Physical Surface("inlet") = inlet();
If (outlets == 2)
  Physical Surface("outlet_a") = outletA();
  Physical Surface("outlet_b") = outletB();
Else
  Physical Surface("outlet") = outlet();
EndIf
Physical Surface("interface") = interface();
Physical Surface("wall_inlet_ring") = wallIn();
Physical Surface("wall_outlet_ring") = wallOut();
Physical Surface("outer_wall") = outer();

// element size: h everywhere, and at most (Ro - Ri)/nwall across the wall
Mesh.MeshSizeFromPoints = 0; // h alone sets the size (OCC points carry a default size)
Mesh.MeshSizeMax = h;
Mesh.MeshSizeMin = 0;
Field[1] = MathEval;
Field[1].F = Sprintf("%g", (Ro - Ri) / nwall);
Field[2] = Restrict;
Field[2].InField = 1;
Field[2].VolumesList = {wall()};
Field[3] = Min;
Field[3].FieldsList = {2};
Background Field = 3;
Mesh.MeshSizeExtendFromBoundary = 1;
Mesh.Algorithm3D = 1;
