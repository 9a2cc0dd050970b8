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


def subprocess_out(cmd):
    return subprocess.run([str(c) for c in cmd], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True).stdout


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
