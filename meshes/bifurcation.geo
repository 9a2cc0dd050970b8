// A carotid bifurcation: the common carotid (CCA, along z up to the bifurcation point at the
// origin) divides into the internal (ICA, towards +x) and the external carotid (ECA, towards -x),
// the branches in the plane y = 0. The lumen (fluid) inside a wall of thickness `wall`, as ONE
// tetrahedral mesh, conforming at the fluid-wall interface (as tube.geo).
// Parameters (gmsh -setnumber NAME VALUE), cm and degrees:
//   R, rI, rE   the lumen radii of the CCA, ICA and ECA;
//   aI, aE      the angles of the ICA's and the ECA's axis from the CCA's axis;
//   Lc, Li, Le  the lengths of the CCA (from its opening to the bifurcation point) and of the
//               ICA and ECA (from the bifurcation point along their axes to their openings);
//   wall        the wall's thickness; fillet the radius that rounds the lumen's junction;
//   h           the target element size; nwall the number of element layers through the wall.
// Defaults: the proportions of the carotid bifurcation model of Bharadvaj, Mabon and Giddens
// (J. Biomech. 15, 349-362, 1982; used by Ku et al. 1985 and Perktold et al. 1991): ICA 0.7 and
// ECA 0.6 of the CCA's diameter, both branches 25 degrees from the CCA's axis (its sinus bulb
// is left out); an adult common carotid's lumen radius 0.3 cm (ultrasound: diameter 6.1 mm in
// women, 6.5 in men, Krejza et al., Stroke 37, 1103-1105, 2006) and a wall of 0.07 cm (about the
// intima-media thickness), as the straight carotid scene (scenes/carotid_tube.opts). Ours: the
// lengths (CCA 2, ICA 3, ECA 2 cm: short, for small meshes; a developed inflow wants a longer
// CCA) and the fillet's radius 0.1 cm.
//
// Construction (OpenCASCADE), for the lumen and then for the outer surface, whose radii are
// larger by `wall`: (1) the two branch cylinders start at the bifurcation point; their union
// less a ball about the point (radius between the branches' and the CCA's: it removes their
// starting discs and the region where their surfaces cross) has its crotch (the ICA-ECA curve)
// rounded by a fillet; (2) that, the CCA's cylinder and a sphere of radius R at the point (the
// CCA's end, tangent to it) are fused, and the sphere-branch curves (one loop over both branches
// and the crotch's fillet) rounded by a second fillet. In two steps no corner has three fillets
// meeting: OCC's patches at such corners (one fillet of all the junction's curves) had edges of a
// few microns, and slivers in the mesh, for several values of the parameters. The outer surface's
// fillets have radius fillet + wall: the wall is thicker at the junction (2.3 wall at the flow
// divider's apex, whose outer crotch is 0.16 cm from the lumen). Every opening is the end face of
// a cylinder, a plane perpendicular to its axis. Tried at level 0: branch angles from 15 to 50
// degrees, equal or unequal branches (rI, rE 0.12-0.21 with R 0.3; R 0.4 with wall 0.1), fillet
// 0.05-0.2: the smallest dihedral angle 8.6-19 degrees; at 10 and 10 degrees OCC's second fillet
// fails ("Could not compute fillet").
SetFactory("OpenCASCADE");
DefineConstant[ R = 0.3, rI = 0.21, rE = 0.18, aI = 25, aE = 25, Lc = 2, Li = 3, Le = 2,
                wall = 0.07, fillet = 0.1, h = 0.1, nwall = 1 ];

tI = aI * Pi / 180; tE = aE * Pi / 180;
eps = 1e-4;
big = 10 * (R + Lc + Li + Le);
// The junction's curves lie below zmax, the branches' straight parts (their seams, their
// openings) reach above it: zc is the outer surface's crotch (where the branches' inner
// generators meet in the plane y = 0), zend the lowest point of the openings' rims.
zc = ((rE + wall) * Cos(tI) + (rI + wall) * Cos(tE)) / Sin(tI + tE);
zend = Li * Cos(tI) - (rI + wall) * Sin(tI);
If (Le * Cos(tE) - (rE + wall) * Sin(tE) < zend)
  zend = Le * Cos(tE) - (rE + wall) * Sin(tE);
EndIf
zmax = (zc + zend) / 2;
If (rI >= R || rE >= R || aI <= 0 || aE <= 0 || aI + aE >= 150 || wall <= 0 || fillet <= 0 || Lc <= R || zend - zc < 2 * (fillet + wall))
  Error("bifurcation.geo: take rI, rE < R, 0 < aI, aE with aI + aE < 150, wall and fillet > 0, Lc > R, and branches long enough (their openings beyond z = %g)", zc + 2 * (fillet + wall));
EndIf

For pass In {0 : 1} // 0: the lumen, 1: the outer surface
  o = pass * wall;
  // (1) the branches less the ball of radius rc, their crotch rounded
  rc = ((rI > rE ? rI : rE) + R) / 2 + o;
  i = newv; Cylinder(i) = {0, 0, 0, Li * Sin(tI), 0, Li * Cos(tI), rI + o};
  e = newv; Cylinder(e) = {0, 0, 0, -Le * Sin(tE), 0, Le * Cos(tE), rE + o};
  y() = BooleanUnion{ Volume{i}; Delete; }{ Volume{e}; Delete; };
  b = newv; Sphere(b) = {0, 0, 0, rc};
  y() = BooleanDifference{ Volume{y()}; Delete; }{ Volume{b}; Delete; };
  curves() = Unique(Abs(Boundary{ Surface{Abs(Boundary{ Volume{y(0)}; })}; }));
  far() = curves();
  far() -= Curve In BoundingBox{-big, -big, -big, big, big, zmax};
  crotch() = curves();
  crotch() -= far();
  crotch() -= Curve In BoundingBox{-rc - eps, -rc - eps, -rc - eps, rc + eps, rc + eps, rc + eps}; // on the ball
  y() = Fillet{ y(0) }{ crotch() }{ fillet + o };
  // (2) the CCA, the sphere at its end and the branches fused, the sphere-branch loop rounded
  c = newv; Cylinder(c) = {0, 0, -Lc, 0, 0, Lc, R + o};
  s = newv; Sphere(s) = {0, 0, 0, R + o}; // its seam in the plane y = 0, x > 0, as the CCA's and ICA's
  v() = BooleanUnion{ Volume{c}; Delete; }{ Volume{s, y(0)}; Delete; };
  curves() = Unique(Abs(Boundary{ Surface{Abs(Boundary{ Volume{v(0)}; })}; }));
  far() = curves();
  far() -= Curve In BoundingBox{-big, -big, -Lc / 2, big, big, zmax};
  junction() = curves();
  junction() -= far();
  junction() -= Curve In BoundingBox{-R - o - eps, -R - o - eps, -eps, R + o + eps, R + o + eps, eps}; // CCA-sphere: tangent
  junction() -= Curve In BoundingBox{-eps, -eps, -eps, R + o + eps, eps, R + o + eps}; // the sphere's seam
  f() = Fillet{ v(0) }{ junction() }{ fillet + o };
  body(pass) = f(0);
EndFor
lumen = body(0); outer = body(1);
bb() = BoundingBox Volume{lumen};
BooleanFragments{ Volume{outer}; Delete; }{ Volume{lumen}; Delete; }
// After the fragments: the lumen and the wall around it; the lumen is the volume inside its box.
fluid() = Volume In BoundingBox{bb(0) - eps, bb(1) - eps, bb(2) - eps, bb(3) + eps, bb(4) + eps, bb(5) + eps};
solid() = Volume{:};
solid() -= fluid(); // (not wall(): that would overwrite the parameter wall)

// The openings: a disc (lumen) and an annulus (wall) in the plane perpendicular to each branch's
// axis at its end, found in the box around the disc of radius r (the annulus: r + wall);
// k = 0 the CCA, 1 the ICA, 2 the ECA: centre (cx, 0, cz), unit axis (nx, 0, nz), radius ra.
cx() = {0, Li * Sin(tI), -Le * Sin(tE)};
cz() = {-Lc, Li * Cos(tI), Le * Cos(tE)};
nx() = {0, Sin(tI), -Sin(tE)};
nz() = {1, Cos(tI), Cos(tE)};
ra() = {R, rI, rE};
For k In {0 : 2}
  For pass In {0 : 1}
    rr = ra(k) + pass * wall;
    dx = rr * Fabs(nz(k)) + eps; dy = rr + eps; dz = rr * Fabs(nx(k)) + eps;
    sel() = Surface In BoundingBox{cx(k) - dx, -dy, cz(k) - dz, cx(k) + dx, dy, cz(k) + dz};
    If (pass == 0)
      disc~{k}() = sel();
    Else
      ring~{k}() = sel();
      ring~{k}() -= disc~{k}();
    EndIf
  EndFor
EndFor
interface() = Abs(Boundary{ Volume{fluid()}; });
interface() -= disc~{0}(); interface() -= disc~{1}(); interface() -= disc~{2}();
outer() = Abs(Boundary{ Volume{solid()}; });
outer() -= interface(); outer() -= ring~{0}(); outer() -= ring~{1}(); outer() -= ring~{2}();
If (#fluid() != 1 || #solid() != 1 || #disc~{0}() != 1 || #disc~{1}() != 1 || #disc~{2}() != 1 ||
    #ring~{0}() != 1 || #ring~{1}() != 1 || #ring~{2}() != 1)
  Error("bifurcation.geo: the openings were not found (volumes %g + %g, discs %g %g %g, rings %g %g %g)",
        #fluid(), #solid(), #disc~{0}(), #disc~{1}(), #disc~{2}(), #ring~{0}(), #ring~{1}(), #ring~{2}());
EndIf

Physical Volume("fluid") = fluid();
Physical Volume("wall") = solid();
Physical Surface("inlet") = disc~{0}();
Physical Surface("outlet_ica") = disc~{1}();
Physical Surface("outlet_eca") = disc~{2}();
Physical Surface("interface") = interface();
Physical Surface("wall_inlet_ring") = ring~{0}();
Physical Surface("wall_ica_ring") = ring~{1}();
Physical Surface("wall_eca_ring") = ring~{2}();
Physical Surface("outer_wall") = outer();

// Element size: h everywhere; at most wall / nwall in the wall and on its faces (tube.geo
// restricts it to the wall's cells alone: the interface and the outer surface then get h, and at
// level 1 tube #1's wall has no vertex inside, one layer of cells for nwall = 2); at most
// fillet / 2 within a fillet's radius of the junction's curves, growing to h at three radii (the
// second fillet crosses the first in short curves, 0.024 cm at the defaults, whose cells were
// flat at the size h).
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeMax = h;
Mesh.MeshSizeMin = 0;
Field[1] = MathEval;
Field[1].F = Sprintf("%g", wall / nwall);
Field[2] = Restrict;
Field[2].InField = 1;
Field[2].VolumesList = {solid()};
Field[2].SurfacesList = {Abs(Boundary{ Volume{solid()}; })};
junction() = Curve In BoundingBox{-big, -big, -Lc / 2, big, big, zmax};
Field[4] = Distance;
Field[4].CurvesList = {junction()};
Field[5] = Threshold;
Field[5].InField = 4;
Field[5].SizeMin = fillet / 2;
Field[5].SizeMax = h;
Field[5].DistMin = fillet;
Field[5].DistMax = 3 * fillet;
Field[3] = Min;
Field[3].FieldsList = {2, 5};
Background Field = 3;
Mesh.MeshSizeExtendFromBoundary = 1;
// HXT and the optimisation of every cell of quality below 0.5: the smallest dihedral angle at
// levels 0 and 1 is 8-13 degrees in the fluid (a cell or two at the short curves above; it
// varies from run to run) and 16 in the wall; gmsh's Delaunay (tube.geo's) gave 8.6 and 10.5
// (the wall 9.3 and 10.9). HXT orders its input points by their memory addresses: two
// runs give different meshes unless the address space is not randomised (scripts/make-meshes
// runs gmsh under setarch -R where it can; its second-order file then has the first-order one's
// cells).
Mesh.Algorithm3D = 10;
Mesh.OptimizeThreshold = 0.5;

// With -setstring centerline FILE: the lumen's centre lines into FILE, for fsi_app's
// -structure_centerline (the fibres' frame): the CCA, the ICA and the ECA, each a branch from or
// to the bifurcation point.
DefineConstant[ centerline = "" ];
If (StrLen(centerline))
  Printf("# bifurcation.geo's centre lines: CCA, ICA, ECA") > centerline;
  Printf("0 0 %.12g", -Lc) >> centerline;
  Printf("0 0 0") >> centerline;
  Printf("") >> centerline;
  Printf("0 0 0") >> centerline;
  Printf("%.12g 0 %.12g", Li * Sin(tI), Li * Cos(tI)) >> centerline;
  Printf("") >> centerline;
  Printf("0 0 0") >> centerline;
  Printf("%.12g 0 %.12g", -Le * Sin(tE), Le * Cos(tE)) >> centerline;
EndIf
