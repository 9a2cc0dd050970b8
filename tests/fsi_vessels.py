#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""ctest cases for the vessels that are not straight tubes, meshes/bifurcation.geo (a carotid
bifurcation) and meshes/bend.geo (a tube bent by 90 degrees): the committed level-0 meshes'
groups as fsi_app reads them (fsi_mesh_info), their openings and volumes read from the files
directly (tests/fsilib.py's GmshMesh) against closed forms of the .geo files' parameters, and
the second-order meshes made by scripts/make-meshes."""
import math

from fsilib import *  # noqa: F401,F403 (the cases' shared runners, meshes and scenes)
from testlib import between, case, main, run

# the committed meshes: groups, (fluid cells, wall cells, interface faces) as docs/meshes.md says
VESSELS = {"bifurcation_L0.msh": (BIFURCATION_GROUPS, (19565, 19134, 5455)),
           "bend_L0.msh": (TUBE_GROUPS, (12321, 11233, 3358))}


def bend():
    p = geo_defaults("bend.geo")
    ends = {"inlet": ((0, 0, 0), (0, 0, 1), p["Ri"], "wall_inlet_ring"),
            "outlet": ((p["Rb"] + p["L2"], 0, p["L1"] + p["Rb"]), (1, 0, 0), p["Ri"], "wall_outlet_ring")}
    return p, ends, p["Ro"] - p["Ri"]


def union_volume(p, o, n=800):
    """The bifurcation's body without its fillets, every radius + o: the CCA's cylinder
    (z in [-Lc, 0]) and the union of the sphere of radius R and the two branch cylinders (from the
    bifurcation point to their openings). At fixed (x, z) each of these is an interval of y
    symmetric about 0, so the union's volume above z = 0 is the integral over (x, z) of twice the
    largest half-width (midpoint rule on n columns: converged to 1e-6 at n = 800)."""
    R, rI, rE = p["R"] + o, p["rI"] + o, p["rE"] + o
    tI, tE = math.radians(p["aI"]), math.radians(p["aE"])
    branches = (((math.sin(tI), math.cos(tI)), rI, p["Li"]), ((-math.sin(tE), math.cos(tE)), rE, p["Le"]))

    def half(x, z):
        w2 = R * R - x * x - z * z
        for (dx, dz), r, L in branches:
            s = x * dx + z * dz
            if 0 <= s <= L:
                w2 = max(w2, r * r - (x * x + z * z - s * s))
        return math.sqrt(w2) if w2 > 0 else 0.0
    x0, x1 = -p["Le"] * math.sin(tE) - rE, p["Li"] * math.sin(tI) + rI
    z1 = max(p["Li"] * math.cos(tI) + rI, p["Le"] * math.cos(tE) + rE)
    nz = int(n * z1 / (x1 - x0)) + 1
    hx, hz = (x1 - x0) / n, z1 / nz
    above = sum(2 * half(x0 + (i + 0.5) * hx, (k + 0.5) * hz) for i in range(n) for k in range(nz)) * hx * hz
    return math.pi * R * R * p["Lc"] + above


def facet_bound(m, faces, curvature):
    """How far the P1 surface of these faces may enclose a volume other than the exact one: each
    triangle, its vertices on a surface of normal curvature at most kappa, stays within
    kappa R_t^2 / 2 of it (R_t its circumradius; the sagitta), so the volumes differ by at most
    the sum of area x 0.55 kappa R_t^2 (10 % for the sagitta's higher terms)."""
    total = 0.0
    for t in faces:
        a, b, c = m.points(t[:3])
        la, lb, lc = math.dist(b, c), math.dist(a, c), math.dist(a, b)
        n = vec_cross(vec_sub(b, a), vec_sub(c, a))
        area = 0.5 * math.sqrt(vec_dot(n, n))
        rt = la * lb * lc / (4 * area)
        total += area * 0.55 * curvature(a, b, c) * rt * rt
    return total


def region_volume(m, name):
    return sum(tet_volume(m.points(c)) for c in m.groups[name])


def opening(m, disc, ring, centre, axis, r, w):
    """A disc and its ring on the file's nodes: planar (every node within 1e-9 cm of the plane
    through the centre normal to the axis), the disc's rim and the ring's inner rim the same nodes
    at radius r, the ring's outer rim at r + w (to 1e-9 cm); the triangles' areas are those of the
    polygons their rims inscribe (to 1e-12); those fall short of pi r^2 by at most
    theta_max^2 / 6 of it, theta_max the rim's largest central angle (the shortfall is the sum of
    (theta - sin theta) / (2 pi) over the segments). Returns the areas."""
    out = {}
    rims = {}
    for name in (disc, ring):
        tris = m.groups[name]
        for t in tris:
            for q in m.points(t):
                assert abs(vec_dot(vec_sub(q, centre), axis)) < 1e-9, (name, q)
        loop = boundary_loops(tris)
        radius = {v: math.dist(m.nodes[v], centre) for e in loop for v in e}
        rims[name] = loop, radius
        area = sum(planar_area(m.points(t[:3]), axis) for t in tris)
        out[name] = area
    loop, radius = rims[disc]
    assert all(abs(x - r) < 1e-9 for x in radius.values()), (disc, min(radius.values()), max(radius.values()))
    inner = {e for e in rims[ring][0] if rims[ring][1][e[0]] < r + w / 2}
    outer = [e for e in rims[ring][0] if e not in inner]
    assert inner == set(loop), f"{ring}'s inner rim is not {disc}'s rim: the wall does not conform"
    assert all(abs(rims[ring][1][v] - (r + w)) < 1e-9 for e in outer for v in e), ring

    def polygon(edges, radius):
        theta = [2 * math.asin(min(1.0, math.dist(m.nodes[a], m.nodes[b]) / (2 * radius))) for a, b in edges]
        return sum(radius * radius * math.sin(t) / 2 for t in theta), max(theta)
    pd, td = polygon(loop, r)
    po, to = polygon(outer, r + w)
    between(abs(out[disc] / pd - 1), 0, 1e-12, f"{disc}: area / its rim's polygon - 1")
    between(abs(out[ring] / (po - pd) - 1), 0, 1e-12, f"{ring}: area / (outer polygon - inner polygon) - 1")
    between(1 - out[disc] / (math.pi * r * r), 0, td * td / 6, f"{disc}: 1 - area / pi r^2 ({len(loop)} segments)")
    between(1 - po / (math.pi * (r + w) ** 2), 0, to * to / 6, f"{ring}: 1 - outer polygon / pi (r + w)^2 ({len(outer)} segments)")
    return out


@case
def vessel_groups():
    """The committed bifurcation_L0 and bend_L0 as fsi_app reads them (fsi_mesh_info, 1 and 2
    ranks): every group the scenes name, a region holding only cells and a face group only
    faces, as many as the file's own elements (read directly); the counts of docs/meshes.md; METIS
    balanced (<= 55 % of the cells on one of 2 ranks); the surfaces' Euler characteristic
    V - E + F: 1 for each opening (a disc), 0 for each ring (an annulus), 2 - openings for the
    interface and the outer wall (a sphere with 3 holes for the bifurcation: -1; a tube: 0)."""
    for mesh, (names, (fluid, wall, interface)) in VESSELS.items():
        m = GmshMesh(os.path.join(MESHES, mesh))
        openings = sum(1 for n in names.split(",") if n == "inlet" or n.startswith("outlet"))
        for np in (1, 2):
            g, ranks = groups(mesh, np, names)
            for name in names.split(","):
                cells, faces, v, e = g[name]
                dim, count = m.dims[name], len(m.groups[name])
                assert (cells, faces) == ((count, 0) if dim == 3 else (0, count)) and count > 0, (mesh, name, g[name], dim, count)
                if dim == 2:
                    chi = v - e + faces
                    want = 1 if name == "inlet" or name.startswith("outlet") else 0 if "ring" in name else 2 - openings
                    assert chi == want, (mesh, name, "Euler characteristic", chi, want)
            assert (g["fluid"][0], g["wall"][0], g["interface"][1]) == (fluid, wall, interface), (mesh, g)
            assert sum(ranks) == fluid + wall and max(ranks) <= (0.55 if np == 2 else 1) * (fluid + wall), ranks


@case
def vessel_openings():
    """The openings of the committed meshes against their parameters (the .geo files' defaults):
    each a planar disc of the branch's radius perpendicular to its axis at its end, and the
    wall's ring around it conforming to it (`opening`: areas to 1e-12 of the inscribed polygons,
    and pi r^2 within the polygons' shortfall)."""
    for mesh, spec in (("bifurcation_L0.msh", bifurcation), ("bend_L0.msh", bend)):
        m = GmshMesh(os.path.join(MESHES, mesh))
        _, ends, w = spec()
        for disc, (centre, axis, r, ring) in ends.items():
            opening(m, disc, ring, centre, axis, r, w)


@case
def vessel_volumes():
    """The committed meshes' volumes against the geometry's (P1 cells: within the facets' bound,
    `facet_bound`, of the exact values). The bend (Pappus): the lumen pi Ri^2 (L1 + L2 + Rb pi/2),
    the wall pi (Ro^2 - Ri^2) (L1 + L2 + Rb pi/2); surface curvature at most 1/Ri and 1/Ro (the
    torus's other curvature is at most 1/(Rb - Ro)). The bifurcation: the lumen, and the lumen
    with its wall, against the union of cylinders and sphere without fillets (`union_volume`);
    the fillets add material, less than 1 % of it (measured on the curved mesh: 0.22 % and
    0.50 %, test vessel_curved); curvature 1/r on the cylinders' faces (a triangle whose
    vertices are all at the radius from the axis), 1/fillet (1/(fillet + wall) outside) elsewhere."""
    p, _, w = bend()
    m = GmshMesh(os.path.join(MESHES, "bend_L0.msh"))
    length = p["L1"] + p["L2"] + p["Rb"] * math.pi / 2
    inner = facet_bound(m, m.groups["interface"], lambda *t: 1 / p["Ri"])
    outer = facet_bound(m, m.groups["outer_wall"], lambda *t: 1 / p["Ro"])
    for name, exact, bound in (("fluid", math.pi * p["Ri"] ** 2 * length, inner),
                               ("wall", math.pi * (p["Ro"] ** 2 - p["Ri"] ** 2) * length, inner + outer)):
        v = region_volume(m, name)
        print(f"bend {name}: volume {v:.6f} exact {exact:.6f} facets' bound {bound:.6f}")
        between(abs(v - exact) / bound, 0, 1, f"bend {name}: |volume - exact| / facets' bound")

    p, ends, w = bifurcation()
    m = GmshMesh(os.path.join(MESHES, "bifurcation_L0.msh"))
    tI, tE = math.radians(p["aI"]), math.radians(p["aE"])
    axes = (((0, 0, -p["Lc"]), (0, 0, 1), p["R"], p["Lc"]), ((0, 0, 0), (math.sin(tI), 0, math.cos(tI)), p["rI"], p["Li"]),
            ((0, 0, 0), (-math.sin(tE), 0, math.cos(tE)), p["rE"], p["Le"]))

    def curvature(o):
        def kappa(*tri):
            for base, axis, r, _ in axes:
                radial = [math.sqrt(max(0.0, vec_dot(vec_sub(q, base), vec_sub(q, base)) - vec_dot(vec_sub(q, base), axis) ** 2)) for q in tri]
                if all(abs(x - (r + o)) < 1e-9 for x in radial):
                    return 1 / (r + o)
            return 1 / (p["fillet"] + o)
        return kappa
    lumen = region_volume(m, "fluid")
    body = lumen + region_volume(m, "wall")
    for what, v, o, faces in (("lumen", lumen, 0, "interface"), ("lumen and wall", body, w, "outer_wall")):
        ref = union_volume(p, o)
        bound = facet_bound(m, m.groups[faces], curvature(o))
        print(f"bifurcation {what}: volume {v:.6f} union {ref:.6f} facets' bound {bound:.6f}")
        between(v, ref - bound, 1.01 * ref + bound, f"bifurcation {what}: volume within [union - facets, 1.01 union + facets]")


@case
def vessel_curved():
    """scripts/make-meshes bifurcation 0 2 and bend 0 2 (second-order, into a folder of the
    test's: nothing is written into meshes/): no cell folded by its nodes (J > 0 at the 10 nodes
    and the centroid, as fsi_app checks), and fsi_app reads both (the wall alone, clamped at its
    rings, under a pressure: one linear solve on 2 ranks); the curved cells hold the exact
    volumes closely: the bend's lumen and wall their Pappus volumes to 1e-4 (measured 5e-6 and
    3e-6), the bifurcation's lumen, and lumen with wall, 0-1 % above the union without fillets
    (the fillets' material: measured 0.22 % and 0.50 %); each opening's curved triangles fall
    short of pi r^2 by at most theta_max^4 / 400 of it (a quadratic arc of angle theta through the
    circle's points at its ends and middle cuts off (theta/2)^5 / 30 r^2: theta^4 / 480 for the
    whole circle; measured 2.5e-5 to 1.6e-4 for 19 to 12 segments)."""
    tmp = tempfile.mkdtemp()
    before = sorted(os.listdir(MESHES))
    script = os.path.join(TOP, "scripts", "make-meshes")
    for name, spec, rings in (("bend", bend, "wall_inlet_ring,wall_outlet_ring"), ("bifurcation", bifurcation, "wall_inlet_ring,wall_ica_ring,wall_eca_ring")):
        subprocess.run([script, name, "0", "2", "--out", tmp], check=True)
        path = os.path.join(tmp, f"{name}_L0_o2.msh")
        m = GmshMesh(path)
        p, ends, w = spec()
        for region in ("fluid", "wall"):
            assert all(len(c) == 10 for c in m.groups[region]), f"{name}: not second-order"
            worst = min(tet_folded(m.points(c)) for c in m.groups[region])
            between(worst, 1e-6, 1, f"{name} {region}: smallest J / J(centroid) of a cell")
        for disc, (centre, axis, r, ring) in ends.items():
            area = sum(planar_area(m.points(t), axis) for t in m.groups[disc])
            theta = max(2 * math.asin(min(1.0, math.dist(m.nodes[a], m.nodes[b]) / (2 * r))) for a, b in boundary_loops(m.groups[disc]))
            between(1 - area / (math.pi * r * r), 0, theta ** 4 / 400, f"{name} {disc}: 1 - area / pi r^2 (curved triangles; bound theta_max^4 / 400)")
        lumen = region_volume(m, "fluid")
        body = lumen + region_volume(m, "wall")
        if name == "bend":
            length = p["L1"] + p["L2"] + p["Rb"] * math.pi / 2
            between(abs(lumen / (math.pi * p["Ri"] ** 2 * length) - 1), 0, 1e-4, "bend: |lumen / pi Ri^2 (L1 + L2 + Rb pi/2) - 1|")
            between(abs((body - lumen) / (math.pi * (p["Ro"] ** 2 - p["Ri"] ** 2) * length) - 1), 0, 1e-4, "bend: |wall / its Pappus volume - 1|")
        else:
            between(lumen / union_volume(p, 0) - 1, 0, 0.01, "bifurcation: lumen / union without fillets - 1")
            between(body / union_volume(p, w) - 1, 0, 0.01, "bifurcation: lumen and wall / union without fillets - 1")
        out = run([APP, "-mesh", path, "-structure_region", "wall", "-structure_clamp", rings, "-structure_pressure", 1330,
                   "-structure_E", 5e6, "-structure_nu", 0.45, "-snes_type", "ksponly", "-ksp_type", "cg", "-pc_type", "gamg", "-ksp_rtol", 1e-6], 2)
        assert re.search(r"load step 1/1 .* CONVERGED", out), out[-2000:]
    assert sorted(os.listdir(MESHES)) == before
    shutil.rmtree(tmp)


def h5_vectors(h5, dataset):
    """The rows of a (n, 3) dataset of an HDF5 file, through h5dump."""
    dump = subprocess_out(["h5dump", "-y", "-w", "0", "-m", "%.17g", "-d", dataset, h5]).split("DATA {")[1]
    v = [float(x) for x in re.findall(r"-?\d+(?:\.\d+)?(?:e[-+]\d+)?", dump)]
    return [v[3 * k:3 * k + 3] for k in range(len(v) // 3)]


@case
def vessel_fibres():
    """The arterial fibres of the bend in the frame of its centre line (bend.geo writes it:
    meshes/bend_centerline.dat, the arc in 32 segments), as the output's fibre_1 and fibre_2 at
    the wall's nodes: their axial direction (fibre_1 - fibre_2) / (2 sin beta) is the exact
    tangent of the bend's circles within 1e-4 (measured 2.6e-6: the cross-section through a
    node found on the polyline, whose tangents turn linearly; the nearest point of a chord gave
    7e-3), e_z along the first straight part and e_x along the second to round-off, and each
    fibre a unit vector at beta from the circumferential direction (their sum's length
    2 cos beta)."""
    tmp = tempfile.mkdtemp()
    Rb, L1, beta = 1.2, 1.0, math.radians(43.39)
    run([APP, "-mesh", os.path.join(MESHES, "bend_L0.msh"), "-structure_region", "wall", "-structure_clamp", "wall_inlet_ring,wall_outlet_ring",
         "-structure_material", "arterial", "-structure_centerline", os.path.join(MESHES, "bend_centerline.dat"),
         "-ksp_type", "preonly", "-pc_type", "lu", "-output", os.path.join(tmp, "b.xdmf")], 2)
    h5 = os.path.join(tmp, "b.h5")
    X, a1, a2 = (h5_vectors(h5, d) for d in ("/mesh/coordinates", "/fields/fibre_1_0", "/fields/fibre_2_0"))
    worst = {"bend": 0, "first": 0, "second": 0}
    for x, f1, f2 in zip(X, a1, a2):
        ea = [(f1[d] - f2[d]) / (2 * math.sin(beta)) for d in range(3)]
        s = [f1[d] + f2[d] for d in range(3)]
        assert abs(math.sqrt(sum(v * v for v in f1)) - 1) < 1e-12 and abs(math.sqrt(sum(v * v for v in s)) - 2 * math.cos(beta)) < 1e-12, (x, f1, f2)
        if x[2] < L1 - 0.4:
            part, t = "first", (0, 0, 1)
        elif x[0] > Rb + 0.4:
            part, t = "second", (1, 0, 0)
        else:
            theta = math.atan2(x[2] - L1, Rb - x[0])
            if not 0.2 < theta < math.pi / 2 - 0.2:
                continue
            part, t = "bend", (math.sin(theta), 0, math.cos(theta))
        worst[part] = max(worst[part], max(abs(ea[d] - t[d]) for d in range(3)))
    print("largest |e_a - exact tangent|:", worst)
    between(worst["bend"], 0, 1e-4, "axial direction in the bend / the circles' tangent")
    between(worst["first"] + worst["second"], 0, 1e-12, "axial direction in the straight parts")
    shutil.rmtree(tmp)


if __name__ == "__main__":
    main("fsi_vessels")
