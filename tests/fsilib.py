# SPDX-License-Identifier: BSD-2-Clause
"""What the fsi_app case files share: the programs, meshes and scenes, one runner that returns a
run's report (the JSON of -report, with the printed output beside it), the check that a run
refuses a mistake, and the closed forms and rates the cases compare with."""
import cmath
import json
import math
import os
import re
import shutil
import signal
import subprocess
import tempfile

from testlib import BUILD, ENV, TOP, between, run

MESHES = os.path.join(TOP, "meshes")
SCENES = os.path.join(TOP, "scenes")
MESH_INFO = os.path.join(BUILD, "fsi_app", "fsi_mesh_info")
APP = os.path.join(BUILD, "fsi_app", "fsi_app")
WALL = ["-structure_region", "wall", "-structure_clamp", "wall_inlet_ring,wall_outlet_ring", "-snes_type", "ksponly",
        "-ksp_type", "cg", "-ksp_rtol", "1e-8"]
TUBE_GROUPS = "fluid,wall,inlet,outlet,interface,wall_inlet_ring,wall_outlet_ring,outer_wall"
BIFURCATION_GROUPS = "fluid,wall,inlet,outlet_ica,outlet_eca,interface,wall_inlet_ring,wall_ica_ring,wall_eca_ring,outer_wall"
FSI = os.path.join(SCENES, "fsi_tube1_linear.opts")


def report(path):
    with open(path) as f:
        return json.load(f)


def scene(*opts, np=1, converged=True):
    """fsi_app with opts on np ranks: its run report, with the totals of its steps ("newton",
    "krylov", the last step's "reason"), the results at the top level ("max_displacement",
    "l2_relative", ...) and the printed output ("out"). converged: every step must converge."""
    tmp = tempfile.mkdtemp()
    out = run([APP] + [str(o) for o in opts] + ["-report", os.path.join(tmp, "r.json")], np)
    r = report(os.path.join(tmp, "r.json"))
    shutil.rmtree(tmp)
    r["newton"] = sum(s["newton"] for s in r["steps"])
    r["krylov"] = sum(s["krylov"] for s in r["steps"])
    r["reason"] = r["steps"][-1]["reason"] if r["steps"] else None
    r["out"] = out
    assert not converged or all(s["reason"].startswith("CONVERGED") for s in r["steps"]), (r["steps"], out[-2000:])
    return r


def solve(*opts, np=1):
    """A structure scene: its report with the wall's largest displacement as "dmax" and its
    errors (None where the scene has no exact solution)."""
    r = scene(*opts, np=np)
    res = r["results"]
    r.update(dmax=res["max_displacement"], l2=res.get("l2_error"), l2_relative=res.get("l2_relative"), h1=res.get("h1_error"), h1_relative=res.get("h1_relative"))
    return r


def flow(*opts, np=1):
    """A fluid scene: its report with the Poiseuille flux and its error where the scene has one,
    and the Newton residual norms of -snes_monitor ("norms")."""
    r = scene(*opts, np=np)
    res = r["results"]
    if "flux" in res:
        r.update(flux=res["flux"], flux_error=res["flux_relative_error"], l2_relative=res["l2_relative"])
    r["norms"] = [float(x) for x in re.findall(r"\d+ SNES Function norm (\S+)", r["out"])]
    return r


def ale(*opts, np=1):
    """fsi_app on the manufactured flow of scenes/fluid_ale_mms_cube.opts: its run report."""
    r = scene(*ALE_CUBE, *opts, np=np)
    r["newton_per_step"] = [s["newton"] for s in r["steps"]]
    return r


def fsi(*opts, np=2, scene_file=FSI):
    """fsi_app on the coupled tube: its run report (with the Newton residuals of -snes_monitor)
    and output."""
    return scene("-options_file", scene_file, *opts, np=np)


def refused(cmd, msg, np=1, cwd=TOP):
    """Run cmd, which must fail with msg, printed once (by rank 0 for all ranks), without a
    signal, and before any step."""
    full = ["mpiexec", "-n", str(np)] + [str(c) for c in cmd]
    p = subprocess.run(full, env=ENV, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=500, cwd=cwd)
    out = p.stdout
    print("$", " ".join(full), "\n" + out[-3000:])
    assert p.returncode != 0, "exit status 0"
    assert out.count(msg) == 1, (msg, out[-3000:])
    assert not re.search(r"^\[[1-9]\d*\]PETSC ERROR", out, re.M) and "Caught signal" not in out, out[-3000:]
    assert not re.search(r"^(load )?step 1/", out, re.M), "a step was solved before the refusal"
    return out


def paraview_reads(xdmf, png, warp=1):
    """What ParaView (pvbatch, scripts/render_xdmf.py) reads of a series and renders to png:
    frames, points, cells and the largest displacement of the last frame."""
    for attempt in range(3):  # xvfb-run -a can lose the race for a display number to another X client
        out = subprocess_out(["xvfb-run", "-a", "-s", "-screen 0 1600x1200x24", "-e", "/dev/stdout", "pvbatch", os.path.join(TOP, "scripts", "render_xdmf.py"), xdmf, png, warp])
        print(out[-2000:])
        if "frames" in out and os.path.exists(png):
            break
    m = re.search(r"frames (\d+) last time (\S+) points (\d+) cells (\d+) displacement magnitude (\S+) (\S+)", out)
    assert m, out[-2000:]
    return {"frames": int(m.group(1)), "points": int(m.group(3)), "cells": int(m.group(4)), "displacement_max": float(m.group(6))}


def subprocess_out(cmd, timeout=600):
    """cmd's output (both streams), written to a file rather than a pipe, cmd in a process group
    of its own that is killed whole when cmd ends: a helper left running (xvfb-run's X server,
    which inherits the output) can then neither hold the test nor outlive it."""
    with tempfile.TemporaryFile("w+") as out:
        p = subprocess.Popen([str(c) for c in cmd], stdout=out, stderr=subprocess.STDOUT, text=True, start_new_session=True)
        try:
            p.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            print(f"{cmd[0]} still running after {timeout} s: stopped")
        try:
            os.killpg(p.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        p.wait()
        out.seek(0)
        return out.read()


def groups(mesh, np=1, require=""):
    out = run([MESH_INFO, "-mesh", os.path.join(MESHES, mesh)] + (["-require", require] if require else []), np)
    g = {m.group(1): tuple(int(x) for x in m.groups()[1:]) for m in re.finditer(r"group (\S+) cells (\d+) faces (\d+) vertices (\d+) edges (\d+)", out)}
    ranks = [int(x) for x in re.findall(r"rank cells (\d+)", out)]
    return g, ranks


def rates(e):
    import math
    return [math.log2(e[k] / e[k + 1]) for k in range(len(e) - 1)]


def mesh_cells(path):
    """The tetrahedra of a gmsh 4 ASCII file (4- and 10-node)."""
    with open(path) as f:
        lines = f.read().split("\n")
    i = lines.index("$Elements")
    blocks, j, cells = int(lines[i + 1].split()[0]), i + 2, 0
    for _ in range(blocks):
        _, _, kind, n = map(int, lines[j].split())
        cells += n if kind in (4, 11) else 0
        j += n + 1
    return cells


class GmshMesh:
    """A gmsh 4.1 ASCII file read directly (not through PETSc): nodes[tag] = (x, y, z) and, per
    physical group, its dimension and its elements as lists of node tags in the file's order
    (4 or 10 per tetrahedron, 3 or 6 per triangle)."""

    def __init__(self, path):
        with open(path) as f:
            text = f.read().split("\n")
        names = {}
        k = text.index("$PhysicalNames")
        for line in text[k + 2:text.index("$EndPhysicalNames")]:
            dim, tag, name = line.split(maxsplit=2)
            names[int(dim), int(tag)] = name.strip('"')
        k = text.index("$Entities")
        counts = [int(n) for n in text[k + 1].split()]
        entity_groups, k = {}, k + 2 + counts[0]  # points have no bounding box: skipped
        for dim in (1, 2, 3):
            for line in text[k:k + counts[dim]]:
                w = line.split()  # tag, bounding box, number of physical tags, the tags, ...
                entity_groups[dim, int(w[0])] = [names[dim, int(t)] for t in w[8:8 + int(w[7])] if (dim, int(t)) in names]
            k += counts[dim]
        self.nodes, k = {}, text.index("$Nodes")
        blocks, k = int(text[k + 1].split()[0]), k + 2
        for _ in range(blocks):
            n = int(text[k].split()[3])
            for tag, coords in zip(text[k + 1:k + 1 + n], text[k + 1 + n:k + 1 + 2 * n]):
                self.nodes[int(tag)] = tuple(float(c) for c in coords.split()[:3])
            k += 1 + 2 * n
        self.groups, k = {}, text.index("$Elements")
        self.dims = {name: dim for (dim, _), name in names.items()}
        blocks, k = int(text[k + 1].split()[0]), k + 2
        for _ in range(blocks):
            dim, entity, _, n = map(int, text[k].split())
            elements = [[int(t) for t in line.split()[1:]] for line in text[k + 1:k + 1 + n]]
            for name in entity_groups.get((dim, entity), []):
                self.groups.setdefault(name, []).extend(elements)
            k += 1 + n

    def points(self, element):
        return [self.nodes[t] for t in element]


def vec_sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def vec_cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def vec_dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


# gmsh's 10-node tetrahedron: vertices 0-3, then the nodes of the edges in this order
TET10_EDGES = [(0, 1), (1, 2), (0, 2), (0, 3), (2, 3), (1, 3)]
# a rule exact for cubics on the tetrahedron (barycentric points, weights summing to 1): the
# Jacobian determinant of a 10-node tetrahedron is a cubic
TET_RULE3 = [((0.25, 0.25, 0.25, 0.25), -0.8)] + [(tuple(0.5 if j == i else 1 / 6 for j in range(4)), 0.45) for i in range(4)]


def tet_jacobian(P, lam):
    """det dX/d(l1, l2, l3) of a 4- or 10-node tetrahedron P at barycentric lam (l0 = 1 - l1 - l2 - l3):
    6 times the volume of a straight cell."""
    if len(P) == 4:
        return vec_dot(vec_sub(P[1], P[0]), vec_cross(vec_sub(P[2], P[0]), vec_sub(P[3], P[0])))
    rows = []
    for k in (1, 2, 3):
        g = [0.0, 0.0, 0.0]
        for i in range(4):  # vertex functions l_i (2 l_i - 1)
            d = (4 * lam[i] - 1) * ((i == k) - (i == 0))
            for c in range(3):
                g[c] += d * P[i][c]
        for e, (a, b) in enumerate(TET10_EDGES):  # edge functions 4 l_a l_b
            d = 4 * (lam[b] * ((a == k) - (a == 0)) + lam[a] * ((b == k) - (b == 0)))
            for c in range(3):
                g[c] += d * P[4 + e][c]
        rows.append(g)
    return vec_dot(rows[0], vec_cross(rows[1], rows[2]))


def tet_volume(P):
    """The volume of a straight (4 nodes) or curved (10 nodes, exact: a cubic rule) tetrahedron."""
    if len(P) == 4:
        return tet_jacobian(P, None) / 6
    return sum(w * tet_jacobian(P, lam) for lam, w in TET_RULE3) / 6


def tet_folded(P):
    """A curved tetrahedron is folded where its Jacobian is not positive: at its 10 nodes or its
    centroid (fsi_app's test, discretization/cells.cxx); the smallest J there over J(centroid)."""
    at = [tuple(1.0 if j == i else 0.0 for j in range(4)) for i in range(4)]
    at += [tuple(0.5 if j in e else 0.0 for j in range(4)) for e in TET10_EDGES] + [(0.25,) * 4]
    j = [tet_jacobian(P, lam) for lam in at]
    return min(j) / j[-1] if j[-1] > 0 else -1.0


def planar_area(P, normal):
    """The area of a 3- or 6-node triangle lying in the plane of unit normal `normal`: its in-plane
    Jacobian is linear (6 nodes), so a 3-point rule is exact."""
    def jac(l1, l2):
        if len(P) == 3:
            a, b = vec_sub(P[1], P[0]), vec_sub(P[2], P[0])
        else:  # gmsh's 6-node triangle: vertices, then the edges (0,1), (1,2), (2,0)
            l0 = 1 - l1 - l2
            dN1 = [-(4 * l0 - 1), 4 * l1 - 1, 0, 4 * (l0 - l1), 4 * l2, -4 * l2]
            dN2 = [-(4 * l0 - 1), 0, 4 * l2 - 1, -4 * l1, 4 * l1, 4 * (l0 - l2)]
            a = tuple(sum(dN1[i] * P[i][c] for i in range(6)) for c in range(3))
            b = tuple(sum(dN2[i] * P[i][c] for i in range(6)) for c in range(3))
        return vec_dot(vec_cross(a, b), normal)
    return abs(sum(jac(*q) for q in ((1 / 6, 1 / 6), (2 / 3, 1 / 6), (1 / 6, 2 / 3))) / 6)


# Dunavant's 7-point rule on the triangle (barycentric points, weights summing to 1), exact for
# polynomials of degree 5
TRI_RULE5 = [((1 / 3, 1 / 3, 1 / 3), 0.225)] + \
    [(p, 0.132394152788506) for p in ((0.059715871789770, 0.470142064105115, 0.470142064105115), (0.470142064105115, 0.059715871789770, 0.470142064105115),
                                      (0.470142064105115, 0.470142064105115, 0.059715871789770))] + \
    [(p, 0.125939180544827) for p in ((0.797426985353087, 0.101286507323456, 0.101286507323456), (0.101286507323456, 0.797426985353087, 0.101286507323456),
                                      (0.101286507323456, 0.101286507323456, 0.797426985353087))]


def surface_area(P):
    """The area of a 3- or 6-node triangle in space: |x_u x x_v| by Dunavant's rule (exact for a
    straight triangle; for a curved one the integrand is smooth, not polynomial: 5e-9 relative
    against a fine midpoint sum on a cylinder's triangle of legs a third of its radius)."""
    if len(P) == 3:
        n = vec_cross(vec_sub(P[1], P[0]), vec_sub(P[2], P[0]))
        return 0.5 * math.sqrt(vec_dot(n, n))
    area = 0.0
    for (l0, l1, l2), w in TRI_RULE5:  # gmsh's 6-node triangle: vertices, then the edges (0,1), (1,2), (2,0)
        dN1 = [-(4 * l0 - 1), 4 * l1 - 1, 0, 4 * (l0 - l1), 4 * l2, -4 * l2]
        dN2 = [-(4 * l0 - 1), 0, 4 * l2 - 1, -4 * l1, 4 * l1, 4 * (l0 - l2)]
        a = tuple(sum(dN1[i] * P[i][c] for i in range(6)) for c in range(3))
        b = tuple(sum(dN2[i] * P[i][c] for i in range(6)) for c in range(3))
        n = vec_cross(a, b)
        area += w * 0.5 * math.sqrt(vec_dot(n, n))
    return area


def boundary_loops(triangles):
    """The vertex pairs on the boundary of a set of triangles (edges of one triangle only)."""
    count = {}
    for t in triangles:
        for a, b in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0])):
            key = (min(a, b), max(a, b))
            count[key] = count.get(key, 0) + 1
    return [e for e, n in count.items() if n == 1]


def geo_defaults(geo):
    """The parameters of a meshes/*.geo file and their defaults (its DefineConstant[...])."""
    with open(os.path.join(MESHES, geo)) as f:
        text = f.read()
    body = re.search(r"DefineConstant\[(.*?)\];", text, re.S).group(1)
    return {k: float(v) for k, v in re.findall(r"(\w+)\s*=\s*([-+0-9.eE]+)", body)}


def bifurcation():
    """meshes/bifurcation.geo's defaults and its openings: group -> (centre, unit axis, radius) for the
    lumen's discs and (..., inner and outer radius) for the wall's rings."""
    p = geo_defaults("bifurcation.geo")
    tI, tE, w = math.radians(p["aI"]), math.radians(p["aE"]), p["wall"]
    ends = {"inlet": ((0, 0, -p["Lc"]), (0, 0, 1), p["R"], "wall_inlet_ring"),
            "outlet_ica": ((p["Li"] * math.sin(tI), 0, p["Li"] * math.cos(tI)), (math.sin(tI), 0, math.cos(tI)), p["rI"], "wall_ica_ring"),
            "outlet_eca": ((-p["Le"] * math.sin(tE), 0, p["Le"] * math.cos(tE)), (-math.sin(tE), 0, math.cos(tE)), p["rE"], "wall_eca_ring")}
    return p, ends, w


def rates_h(e, meshes):
    """Observed orders against each mesh's own size h ~ cells^(-1/3) (the same domain): gmsh's
    levels of a given h are not nested, and their cell counts need not grow 8-fold."""
    import math
    h = [mesh_cells(m) ** (-1 / 3) for m in meshes]
    return [math.log(e[k] / e[k + 1]) / math.log(h[k] / h[k + 1]) for k in range(len(e) - 1)]


CUBE_LOAD = ["-structure_clamp", "x0", "-structure_pressure_group", "x1", "-snes_type", "newtonls", "-ksp_type", "preonly", "-pc_type", "lu"]


def small_strain_limit(law, shear, bulk, p):
    """A hyperelastic wall of tube #1 against the linear wall with its small-strain moduli (E and
    nu from the shear and bulk moduli), under the pressures p and p/2 (Newton to 1e-12, LU):
    the ratios r(p), r(p/2) of their largest displacements. A smooth law agrees with its
    linearisation to first order in the load: r - 1 is proportional to p, and the extrapolation
    2 r(p/2) - r(p) to p = 0 is 1 up to O(p^2)."""
    E, nu = 9 * bulk * shear / (3 * bulk + shear), (3 * bulk - 2 * shear) / (2 * (3 * bulk + shear))
    tmp = tempfile.mkdtemp()
    wall = ["-mesh", os.path.join(MESHES, "tube1_L0.msh"), "-structure_region", "wall", "-structure_clamp", "wall_inlet_ring,wall_outlet_ring",
            "-snes_type", "newtonls", "-snes_rtol", 1e-12, "-snes_atol", 1e-20, "-ksp_type", "preonly", "-pc_type", "lu", "-report", os.path.join(tmp, "r.json")]

    def dmax(*opts):
        run([APP] + [str(o) for o in wall + list(opts)])
        return report(os.path.join(tmp, "r.json"))["results"]["max_displacement"]

    linear = dmax("-structure_material", "linear", "-structure_E", E, "-structure_nu", nu, "-structure_pressure", p)  # linear in p: at p/2 half of it
    r = [dmax(*law, "-structure_pressure", load) / (linear * load / p) for load in (p, p / 2)]
    shutil.rmtree(tmp)
    print(law, "small-strain E", E, "nu", nu, "ratios to the linear wall at p and p/2", r)
    between((r[0] - 1) / (r[1] - 1), 1.9, 2.1, f"{law[1]}: (r(p) - 1) / (r(p/2) - 1), first order in p")
    between(abs(2 * r[1] - r[0] - 1), 0, 3e-4, f"{law[1]}: |2 r(p/2) - r(p) - 1|, the ratio extrapolated to p = 0")
    return r


def lame_radial(r, E, nu, p, Ri, Ro):
    """Lame's plane-strain radial displacement u_r = A r + B / r of a cylinder under internal
    pressure p."""
    A = (1 + nu) * (1 - 2 * nu) * p * Ri**2 / (E * (Ro**2 - Ri**2))
    B = (1 + nu) * p * Ri**2 * Ro**2 / (E * (Ro**2 - Ri**2))
    return A * r + B / r


def radial_frequency(E, nu, rho, Ri, Ro, n=400):
    """The lowest angular frequency of the free radial (breathing) vibration of a thick-walled
    cylinder in plane strain: u'' + u'/r - u/r^2 + k^2 u = 0 (Bessel J1, Y1 of k r) with
    (lambda + 2 mu) u' + lambda u / r = 0 at Ri and Ro; k by shooting (RK4) and bisection,
    omega = k sqrt((lambda + 2 mu) / rho)."""
    lam, mu = E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))
    M, h = lam + 2 * mu, (Ro - Ri) / n

    def outer_stress(k):
        r, y = Ri, (1.0, -lam / (M * Ri))
        f = lambda r, y: (y[1], -y[1] / r + y[0] / r**2 - k * k * y[0])
        for _ in range(n):
            k1 = f(r, y)
            k2 = f(r + h / 2, (y[0] + h / 2 * k1[0], y[1] + h / 2 * k1[1]))
            k3 = f(r + h / 2, (y[0] + h / 2 * k2[0], y[1] + h / 2 * k2[1]))
            k4 = f(r + h, (y[0] + h * k3[0], y[1] + h * k3[1]))
            y = tuple(y[i] + h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]) for i in range(2))
            r += h
        return M * y[1] + lam * y[0] / Ro

    a, dk = 1e-6, 0.01 / (Ro - Ri)
    while outer_stress(a) * outer_stress(a + dk) > 0:
        a += dk
    b = a + dk
    for _ in range(60):
        m = (a + b) / 2
        a, b = (a, m) if outer_stress(a) * outer_stress(m) <= 0 else (m, b)
    return (a + b) / 2 * math.sqrt(M / rho)


def oscillation(u):
    """The pole z and centre c of u_n = c + Re(w z^n) fitted by least squares to the recurrence
    u_(n+1) = a u_n + b u_(n-1) + e (z, conj(z) the roots of z^2 = a z + b; c = e / (1 - a - b))."""
    rows = [(u[n], u[n - 1], 1.0) for n in range(1, len(u) - 1)]
    N = [[sum(x[i] * x[j] for x in rows) for j in range(3)] for i in range(3)]
    v = [sum(x[i] * y for x, y in zip(rows, u[2:])) for i in range(3)]
    det = lambda m: (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
                     + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]))
    a, b, e = (det([[v[i] if j == c else N[i][j] for j in range(3)] for i in range(3)]) / det(N) for c in range(3))
    return a / 2 + cmath.sqrt(a * a / 4 + b), e / (1 - a - b)


CUBE_DYNAMIC = ["-mesh", os.path.join(MESHES, "cube_L0.msh"), "-structure_clamp", "x0", "-structure_pressure_group", "x1",
                "-structure_density", 1, "-snes_type", "newtonls", "-snes_rtol", 1e-10, "-snes_atol", 1e-12,
                "-ksp_type", "gmres", "-ksp_rtol", 1e-12, "-pc_type", "gdsw", "-structure_subdomains", 4]


def check_seconds(r, what, split):
    """The run report's phases: present and positive, none longer than the time loop (total);
    assembly never overlaps the preconditioner's set-up or the Krylov iterations, and those two
    do not overlap when the set-up is all in the outer PCSetUp (split preconditioners set up
    their inner solvers at first use, inside KSPSolve: then only each pair with assembly is
    bounded). One rank: on several the phases are each rank's largest, not one rank's sum; 1 ms
    for the report's 4 decimals."""
    s, bound = r["seconds"], r["seconds"]["total"] + 1e-3
    print(what, s, "peak memory", r["peak_memory_mib"], "MiB")
    for phase in ("assembly", "preconditioner_setup", "krylov", "total"):
        between(s[phase], 1e-6, s["total"], f"{what}: seconds in {phase}")
    between(s["assembly"] + s["preconditioner_setup"], 0, bound, f"{what}: assembly + preconditioner set-up (s)")
    between(s["assembly"] + s["krylov"], 0, bound, f"{what}: assembly + Krylov (s)")
    if not split:
        between(s["assembly"] + s["preconditioner_setup"] + s["krylov"], 0, bound, f"{what}: sum of the phases (s)")


def check_step_seconds(r, what):
    """Each step's phases in the run report: summed over the steps they stay within the run's
    (the run's events count from the log's start, before the loop), the steps' wall clocks add
    up to the loop's but for what runs between steps (probes; no output here), and the peak
    memory after each step never falls and ends at the run's."""
    steps, bound = r["steps"], 1e-3 * len(r["steps"])
    for phase in ("assembly", "preconditioner_setup", "krylov"):
        between(sum(s["seconds"][phase] for s in steps), 1e-6, r["seconds"][phase] + bound, f"{what}: seconds in {phase} summed over the steps")
    between(sum(s["seconds"]["total"] for s in steps) / r["seconds"]["total"], 0.9, 1 + bound / r["seconds"]["total"], f"{what}: steps' wall clocks / the loop's")
    peaks = [s["peak_memory_mib"] for s in steps]
    assert peaks == sorted(peaks) and abs(peaks[-1] - r["peak_memory_mib"]) < 0.11, (peaks, r["peak_memory_mib"])


POISEUILLE = ["-options_file", os.path.join(MESHES, "..", "scenes", "fluid_poiseuille.opts")]


def pipe_flux_step(dp, t, R=0.15, L=2.5, rho=1.0, mu=0.03):
    """The flux at time t through a rigid pipe whose fluid, at rest until t = 0, is driven by the
    pressure drop dp from then on (Szymanski's exact flow); its short-time expansion
    Q = pi R^2 (dp / L) t / rho (1 - 8 sqrt(tau) / (3 sqrt(pi)) + tau / 2), tau = nu t / R^2, is
    exact to 3e-5 relative for tau < 0.01 (checked against the Bessel series)."""
    tau = mu / rho * t / R**2
    return math.pi * R**2 * dp / L * t / rho * (1 - 8 * math.sqrt(tau) / (3 * math.sqrt(math.pi)) + tau / 2)


ALE_CUBE = ["-options_file", os.path.join(MESHES, "..", "scenes", "fluid_ale_mms_cube.opts")]


def corrupt(lines, header, edit):
    """lines with the first line after `header` (a section name) that matches the regex edit[0]
    rewritten by edit[1]; the new lines and the 1-based number of the edited line."""
    at = next(k for k in range(lines.index(header), len(lines)) if re.match(edit[0], lines[k]))
    return lines[:at] + [edit[1](lines[at])] + lines[at + 1:], at + 1


def tube_unknowns(mesh, u):
    """Asserts a coupled tube's unknowns against the counts of its mesh's topology; returns the
    mesh's groups and the P2 node count of a group."""
    g, _ = groups(mesh, 1, TUBE_GROUPS)
    nodes = lambda group: g[group][2] + g[group][3]  # P2: vertices + edges
    _, faces, v, e = g["interface"]
    print(mesh, "interface", g["interface"], "unknowns", u)
    assert v - e + faces == 0, g["interface"]
    assert u["multiplier"] == 3 * nodes("interface"), u
    assert u["fluid"] == 3 * nodes("fluid") and u["pressure"] == g["fluid"][2], (u, g["fluid"])
    assert u["geometry"] == u["fluid"] - nodes("inlet") - nodes("outlet"), u
    assert u["structure"] == 3 * (nodes("wall") - nodes("wall_inlet_ring") - nodes("wall_outlet_ring")), (u, g)
    return g, nodes


FACSI = os.path.join(MESHES, "..", "scenes", "fsi_facsi.opts")


EXACT_INNER = ["-fieldsplit_structure_pc_type", "lu", "-fieldsplit_geometry_pc_type", "lu", "-fieldsplit_fluid_dirichlet_pc_type", "lu"]


def krylov_residuals(out):
    """The first linear solve's -ksp_monitor residual norms."""
    res = []
    for line in out.splitlines():
        m = re.match(r"\s*(\d+) KSP Residual norm (\S+)", line)
        if m:
            if m.group(1) == "0" and res:
                break
            res.append(float(m.group(2)))
    return res


def gdsw_view(out):
    """Subdomains, dofs per node, null-space vectors, interface components and coarse dimension
    from the first gdsw in -ksp_view."""
    m = re.search(r"(\d+) subdomains \(.*?\), overlap .*?, (\d+) dofs per node, (\d+) null-space vectors\s*\n"
                  r"\s*interface components: (\d+) faces, (\d+) edges, (\d+) vertices.*\n\s*coarse dimension (\d+)", out)
    assert m, out[-3000:]
    return [int(g) for g in m.groups()]


INEXACT = os.path.join(MESHES, "..", "scenes", "fsi_inexact_newton.opts")


ARTERIAL = os.path.join(MESHES, "..", "scenes", "fsi_tube1_arterial.opts")
