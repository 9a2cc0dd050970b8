#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""ctest cases for scripts/stl-to-mesh, a user's vessel made from its lumen's surface (STL): the
committed bifurcation_L0's lumen written as an STL and meshed back, against that mesh, the
.geo's openings and Steiner's volume of the offset wall; and the inputs it must refuse."""
import math

from fsilib import *  # noqa: F401,F403 (the cases' shared runners, meshes and scenes)
from testlib import between, case, main, run

SCRIPT = os.path.join(TOP, "scripts", "stl-to-mesh")


def stl_to_mesh(*args, fail=False):
    p = subprocess.run([SCRIPT] + [str(a) for a in args], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=300, cwd=TOP)
    print("$", SCRIPT, " ".join(str(a) for a in args), "\n" + p.stdout[-2000:] + p.stderr[-2000:])
    assert (p.returncode != 0) == fail, f"exit status {p.returncode}"
    return p


def lumen_triangles(m):
    """The interface of a mesh as triples of points, each facing out of the fluid cell it bounds."""
    inside = {}
    for c in m.groups["fluid"]:
        for k in range(4):
            inside[frozenset(c[:k] + c[k + 1:4])] = c[k]
    out = []
    for t in m.groups["interface"]:
        a, b, c = m.points(t[:3])
        away = vec_sub(a, m.nodes[inside[frozenset(t[:3])]])
        out.append((a, b, c) if vec_dot(vec_cross(vec_sub(b, a), vec_sub(c, a)), away) > 0 else (a, c, b))
    return out


def write_stl(path, triangles):
    with open(path, "w") as f:
        f.write("solid lumen\n")
        for t in triangles:
            f.write(" facet normal 0 0 0\n  outer loop\n" + "".join("   vertex %.17g %.17g %.17g\n" % q for q in t) + "  endloop\n endfacet\n")
        f.write("endsolid lumen\n")


def offset_volume(triangles, t):
    """The volume swept by an open surface's outward normals from 0 to t (Steiner): the map
    x + s n has Jacobian 1 + 2 H s + K s^2, so the layer holds A t + t^2 int H + t^3/3 int K (H the
    mean curvature, positive where the surface bends away from its normal, K the Gaussian one).
    On triangles int H = 1/2 sum over interior edges of length x the angle between the normals,
    signed, and int K = sum over interior vertices of 2 pi - their angles. A cylinder of radius r
    and length L gives pi ((r + t)^2 - r^2) L exactly, the thick tube's volume; the bifurcation's
    junction adds what the normals' spreading and converging make of it."""
    index, tris = {}, []
    for tri in triangles:
        tris.append(tuple(index.setdefault(q, len(index)) for q in tri))
    P = list(index)
    unit = lambda v: tuple(x / math.sqrt(vec_dot(v, v)) for x in v)
    normal = [unit(vec_cross(vec_sub(P[b], P[a]), vec_sub(P[c], P[a]))) for a, b, c in tris]
    area = sum(surface_area([P[a], P[b], P[c]]) for a, b, c in tris)
    by_edge, angles = {}, [0.0] * len(P)
    for k, (a, b, c) in enumerate(tris):
        for u, v, w in ((a, b, c), (b, c, a), (c, a, b)):
            by_edge.setdefault(frozenset((u, v)), []).append((k, w))
            e, f = unit(vec_sub(P[v], P[u])), unit(vec_sub(P[w], P[u]))
            angles[u] += math.acos(max(-1.0, min(1.0, vec_dot(e, f))))
    mean, rim = 0.0, set()
    for edge, sides in by_edge.items():
        if len(sides) == 1:
            rim |= edge
            continue
        (k, _), (j, w) = sides
        theta = math.acos(max(-1.0, min(1.0, vec_dot(normal[k], normal[j]))))
        u, v = edge
        bends_away = vec_dot(vec_sub(P[w], P[u]), normal[k]) < 0
        mean += 0.5 * math.dist(P[u], P[v]) * theta * (1 if bends_away else -1)
    gauss = sum(2 * math.pi - angles[v] for v in range(len(P)) if v not in rim)
    print(f"offset volume: area {area:.6f} int H {mean:.6f} int K {gauss:.6f} (the openings' circles are geodesics: -2 pi + theirs)")
    return area * t + t * t * mean + t ** 3 / 3 * gauss


def faces_of(cells):
    """How many of the cells have each face (by its vertices)."""
    count = {}
    for c in cells:
        for k in range(4):
            key = frozenset(c[:k] + c[k + 1:4])
            count[key] = count.get(key, 0) + 1
    return count


@case
def stl_round_trip():
    """The committed bifurcation_L0's interface (its lumen without the caps, 5455 triangles)
    written as an STL and meshed back by scripts/stl-to-mesh with the .geo's wall (0.07) and size
    (0.1), the openings named by their centres. Orders 1 and 2: the ten groups of the
    bifurcation with their dimensions and element orders, every node in a cell, conforming
    (each interface face a face of one fluid cell and one wall cell, each cap face of a fluid
    cell, each ring and outer face of a wall cell), each cap and ring in its opening's plane (the
    .geo's: to 1e-9 cm). Order 2, the numbers within 1 % of independent references: the fluid
    volume and the inlet's, outlets' and interface's areas of the original mesh (measured
    -0.02 %, 0, 0, 0 and -0.24 %; the curved interface follows the STL's facets, the rims are
    the STL's); the wall against Steiner's volume of the layer the STL's normals sweep
    (`offset_volume`; measured -0.44 %), not against the original wall, which the .geo makes
    thicker at the junction (its outer fillets are fillet + wall: 1.5 % more than the offset).
    fsi_app reads it: the wall clamped at its rings under a pressure, one linear solve on 2
    ranks, with 3 x (wall nodes - ring nodes) unknowns as the file has them. Nothing is written
    into meshes/."""
    tmp = tempfile.mkdtemp()
    before = sorted(os.listdir(MESHES))
    orig = GmshMesh(os.path.join(MESHES, "bifurcation_L0.msh"))
    p, ends, wall = bifurcation()
    lumen = lumen_triangles(orig)
    stl = os.path.join(tmp, "lumen.stl")
    write_stl(stl, lumen)
    at = lambda name: ",".join(repr(x) for x in ends[name][0])
    names = ["--inlet", at("inlet"), "--outlet", "ica=" + at("outlet_ica"), "--outlet", "eca=" + at("outlet_eca")]
    rings = {ring: (centre, axis) for centre, axis, _, ring in ends.values()}
    planes = {**{disc: (centre, axis) for disc, (centre, axis, _, _) in ends.items()}, **rings}
    for order in (1, 2):
        out = os.path.join(tmp, f"vessel_o{order}.msh")
        stl_to_mesh(stl, "--wall", wall, "--size", p["h"], "--order", order, *names, "--out", out)
        m = GmshMesh(out)
        assert sorted(m.groups) == sorted(BIFURCATION_GROUPS.split(",")), sorted(m.groups)
        for name, elements in m.groups.items():
            dim = 3 if name in ("fluid", "wall") else 2
            assert m.dims[name] == dim and {len(e) for e in elements} == {(4 if dim == 3 else 3) if order == 1 else (10 if dim == 3 else 6)}, name
        assert {q for g in ("fluid", "wall") for c in m.groups[g] for q in c} == set(m.nodes), "a node in no cell"
        fluid, solid = faces_of(m.groups["fluid"]), faces_of(m.groups["wall"])
        for name in m.groups:
            if m.dims[name] == 2:
                for t in m.groups[name]:
                    key = frozenset(t[:3])
                    want = (1, 1) if name == "interface" else (1, 0) if name in ends else (0, 1)  # the caps: fluid; rings, outer wall: wall
                    assert (fluid.get(key, 0), solid.get(key, 0)) == want, (name, t)
                    if name in planes:
                        centre, axis = planes[name]
                        assert all(abs(vec_dot(vec_sub(q, centre), axis)) < 1e-9 for q in m.points(t)), (name, t)
    volume = lambda mesh, name: sum(tet_volume(mesh.points(c)) for c in mesh.groups[name])
    area = lambda mesh, name: sum(surface_area(mesh.points(t)) for t in mesh.groups[name])
    for name in ("fluid", "inlet", "outlet_ica", "outlet_eca", "interface"):
        new, ref = (volume(x, name) if name == "fluid" else area(x, name) for x in (m, orig))
        print(f"{name}: {new:.6f} against the original's {ref:.6f}")
        between(abs(new / ref - 1), 0, 0.01, f"|{name} / the original's - 1|")
    steiner = offset_volume(lumen, wall)
    print(f"wall: {volume(m, 'wall'):.6f}, the original's {volume(orig, 'wall'):.6f} (thicker at the junction), the offset's {steiner:.6f}")
    between(abs(volume(m, "wall") / steiner - 1), 0, 0.01, "|wall / Steiner's offset volume - 1|")
    out = run([APP, "-mesh", out, "-structure_region", "wall", "-structure_clamp", ",".join(rings), "-structure_pressure", 1330, "-structure_E", 5e6,
               "-structure_nu", 0.45, "-snes_type", "ksponly", "-ksp_type", "cg", "-pc_type", "gamg", "-ksp_rtol", 1e-6], 2)
    assert re.search(r"load step 1/1 .* CONVERGED", out), out[-2000:]
    free = {q for c in m.groups["wall"] for q in c} - {q for ring in rings for t in m.groups[ring] for q in t}
    assert f"unknowns: structure {3 * len(free)}\n" in out, (3 * len(free), out[-2000:])
    assert sorted(os.listdir(MESHES)) == before
    shutil.rmtree(tmp)


@case
def stl_bad_input():
    """What scripts/stl-to-mesh refuses, each with one sentence on stderr, a nonzero exit status
    and nothing written (the output's folder as it was): a missing STL, a closed surface (no
    openings: cube_L0's six faces), a hole that is not planar (bifurcation_L0's lumen less the
    triangles around a point of the common carotid's cylinder: its rim bends with the
    cylinder, 7.5 % of its radius out of its plane), an edge of three triangles (one triangle
    twice), a second piece (a triangle apart), a folder of --out that does not exist."""
    tmp = tempfile.mkdtemp()
    orig = GmshMesh(os.path.join(MESHES, "bifurcation_L0.msh"))
    lumen = lumen_triangles(orig)
    centre = min({q for t in lumen for q in t}, key=lambda q: math.dist(q, (0.3, 0, -1)))
    cube = GmshMesh(os.path.join(MESHES, "cube_L0.msh"))
    inputs = {"closed": [tuple(cube.points(t)) for g in ("x0", "x1", "y0", "y1", "z0", "z1") for t in cube.groups[g]],
              "hole": [t for t in lumen if centre not in t],
              "three_at_an_edge": lumen + lumen[:1],
              "two_pieces": lumen + [((5, 5, 5), (5.1, 5, 5), (5, 5.1, 5))]}
    cases = [(os.path.join(tmp, "nothere.stl"), "nothere.stl: no such file", tmp),
             (os.path.join(tmp, "closed.stl"), "the surface is closed, so it has no openings", tmp),
             (os.path.join(tmp, "hole.stl"), "is not planar: its rim leaves its plane by", tmp),
             (os.path.join(tmp, "three_at_an_edge.stl"), "3 triangles meet at one edge (the surface is not a manifold)", tmp),
             (os.path.join(tmp, "two_pieces.stl"), "the surface is in 2 separate pieces", tmp),
             (os.path.join(tmp, "hole.stl"), "the folder " + os.path.join(tmp, "nowhere") + " does not exist", os.path.join(tmp, "nowhere"))]
    for name, triangles in inputs.items():
        write_stl(os.path.join(tmp, name + ".stl"), triangles)
    for stl, msg, folder in cases:
        listing = sorted(os.listdir(tmp))
        p = stl_to_mesh(stl, "--wall", 0.07, "--size", 0.1, "--out", os.path.join(folder, "vessel.msh"), fail=True)
        lines = p.stderr.strip().split("\n")
        assert len(lines) == 1 and lines[0].startswith("stl-to-mesh: ") and msg in lines[0], (msg, p.stderr)
        assert sorted(os.listdir(tmp)) == listing, "a file was written"
    shutil.rmtree(tmp)


if __name__ == "__main__":
    main("fsi_stl")
