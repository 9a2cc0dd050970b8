// A bent artery: a tube of lumen radius Ri and wall outer radius Ro, straight along z for L1
// from its inlet at z = 0, then bent by 90 degrees about the axis (Rb, y, L1) (bend radius Rb:
// the centre line's radius of curvature), then straight along x for L2 up to its outlet at
// x = Rb + L2. The lumen (fluid) inside the wall, as ONE tetrahedral mesh, conforming at the
// fluid-wall interface, with the groups of tube.geo.
// Parameters (gmsh -setnumber NAME VALUE), cm: Ri, Ro, Rb, L1, L2; h the target element size;
// nwall the number of element layers through the wall.
// Defaults: the straight carotid scene's lumen and wall (Ri 0.3, Ro 0.37: scenes/carotid_tube.opts),
// a bend of curvature ratio Ri / Rb = 1/4, straight extensions of 1 cm.
// Construction (OpenCASCADE): a disc extruded along z, rotated about the bend's axis, extruded
// along x, and the three pieces fused; the same for the disc of radius Ro; the two bodies
// fragmented as in tube.geo. The lumen's volume is pi Ri^2 (L1 + L2 + Rb pi / 2) (Pappus).
SetFactory("OpenCASCADE");
DefineConstant[ Ri = 0.3, Ro = 0.37, Rb = 1.2, L1 = 1, L2 = 1, h = 0.1, nwall = 1 ];
If (Ri <= 0 || Ro <= Ri || Rb <= Ro || L1 <= 0 || L2 <= 0)
  Error("bend.geo: take 0 < Ri < Ro < Rb and L1, L2 > 0 (Ri %g, Ro %g, Rb %g, L1 %g, L2 %g)", Ri, Ro, Rb, L1, L2);
EndIf

For pass In {0 : 1} // 0: the lumen, 1: the outer surface
  r = (pass == 0) ? Ri : Ro;
  d = news; Disk(d) = {0, 0, 0, r};
  a() = Extrude {0, 0, L1} { Surface{d}; };
  b() = Extrude { {0, 1, 0}, {Rb, 0, L1}, Pi / 2 } { Surface{a(0)}; };
  c() = Extrude {L2, 0, 0} { Surface{b(0)}; };
  v() = BooleanUnion{ Volume{a(1)}; Delete; }{ Volume{b(1), c(1)}; Delete; };
  body(pass) = v(0);
EndFor
lumen = body(0); outer = body(1);
eps = 1e-6 * (L1 + L2 + Rb);
bb() = BoundingBox Volume{lumen};
BooleanFragments{ Volume{outer}; Delete; }{ Volume{lumen}; Delete; }
// After the fragments: the lumen and the wall around it; the lumen is the volume inside its box.
fluid() = Volume In BoundingBox{bb(0) - eps, bb(1) - eps, bb(2) - eps, bb(3) + eps, bb(4) + eps, bb(5) + eps};
wall() = Volume{:};
wall() -= fluid();

// the ends: the inlet's plane z = 0 and the outlet's x = Rb + L2, the disc of radius Ri and the
// annulus around it
xo = Rb + L2; zo = L1 + Rb;
inlet()  = Surface In BoundingBox{-Ri - eps, -Ri - eps, -eps, Ri + eps, Ri + eps, eps};
outlet() = Surface In BoundingBox{xo - eps, -Ri - eps, zo - Ri - eps, xo + eps, Ri + eps, zo + Ri + eps};
wallIn() = Surface In BoundingBox{-Ro - eps, -Ro - eps, -eps, Ro + eps, Ro + eps, eps};
wallOut() = Surface In BoundingBox{xo - eps, -Ro - eps, zo - Ro - eps, xo + eps, Ro + eps, zo + Ro + eps};
wallIn() -= inlet();
wallOut() -= outlet();
interface() = Abs(Boundary{ Volume{fluid()}; });
interface() -= inlet();
interface() -= outlet();
outer() = Abs(Boundary{ Volume{wall()}; });
outer() -= interface();
outer() -= wallIn();
outer() -= wallOut();
If (#fluid() != 1 || #wall() != 1 || #inlet() != 1 || #outlet() != 1 || #wallIn() != 1 || #wallOut() != 1)
  Error("bend.geo: the ends were not found (volumes %g + %g, discs %g %g, rings %g %g)", #fluid(), #wall(), #inlet(), #outlet(), #wallIn(), #wallOut());
EndIf

Physical Volume("fluid") = fluid();
Physical Volume("wall") = wall();
Physical Surface("inlet") = inlet();
Physical Surface("outlet") = outlet();
Physical Surface("interface") = interface();
Physical Surface("wall_inlet_ring") = wallIn();
Physical Surface("wall_outlet_ring") = wallOut();
Physical Surface("outer_wall") = outer();

// Element size: h everywhere, and at most (Ro - Ri) / nwall in the wall and on its faces
// (bifurcation.geo says why the faces too)
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeMax = h;
Mesh.MeshSizeMin = 0;
Field[1] = MathEval;
Field[1].F = Sprintf("%g", (Ro - Ri) / nwall);
Field[2] = Restrict;
Field[2].InField = 1;
Field[2].VolumesList = {wall()};
Field[2].SurfacesList = {Abs(Boundary{ Volume{wall()}; })};
Field[3] = Min;
Field[3].FieldsList = {2};
Background Field = 3;
Mesh.MeshSizeExtendFromBoundary = 1;
// HXT and the optimisation of every cell of quality below 0.5, as bifurcation.geo: no dihedral
// angle below 20 degrees at levels 0 and 1, where gmsh's Delaunay left slivers (6.4 degrees in
// the wall at level 0, 2.7 in the fluid at level 1).
// HXT orders its input points by their memory addresses: two runs give different meshes unless
// the address space is not randomised (scripts/make-meshes runs gmsh under setarch -R where it can).
Mesh.Algorithm3D = 10;
Mesh.OptimizeThreshold = 0.5;

// With -setstring centerline FILE: the lumen's centre line into FILE, one point "x y z" per line
// (the arc in 32 segments), for fsi_app's -structure_centerline (the fibres' frame).
DefineConstant[ centerline = "" ];
If (StrLen(centerline))
  Printf("# bend.geo's centre line: Ri %g, Rb %g, L1 %g, L2 %g", Ri, Rb, L1, L2) > centerline;
  Printf("0 0 0") >> centerline;
  For k In {0 : 32}
    Printf("%.12g 0 %.12g", Rb - Rb * Cos(k * Pi / 64), L1 + Rb * Sin(k * Pi / 64)) >> centerline;
  EndFor
  Printf("%.12g 0 %.12g", Rb + L2, L1 + Rb) >> centerline;
EndIf
