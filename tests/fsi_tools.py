#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""ctest cases for fsi_app: the meshes, the layout of the sources, the benchmark scripts' command
lines and the error study's analysis. Each case runs fsi_app and asserts numbers of its run
report (tests/fsilib.py) against references independent of the code."""
import csv
import importlib.util
import sys

from fsilib import *  # noqa: F401,F403 (the cases' shared runners, meshes and scenes)
from testlib import between, case, main, run

# The floors of fsi_app's sources, lowest first: a file includes only its own folder and the
# floors below it, and no block includes another block (docs/code_map.md).
FLOORS = [["base"], ["mesh"], ["discretization"], ["io"], ["core"], ["verification"],
          ["structure", "fluid", "geometry", "coupling", "outlets", "facsi"], ["run"], ["tools", "main.cxx"]]


@case
def mesh_tubes():
    """The three seed tubes: every physical group present, conforming fluid/wall, counts that do
    not depend on the number of ranks, and a METIS split with balanced cells."""
    expect = {"tube1_L0.msh": (909, 2089, 580), "tube2_L0.msh": (4253, 8199, 2438), "tube3_L0.msh": (8287, 16874, 4796)}
    for mesh, (fluid, wall, interface) in expect.items():
        for np in (1, 2):
            g, ranks = groups(mesh, np, TUBE_GROUPS)
            assert g["fluid"][0] == fluid and g["wall"][0] == wall and g["interface"][1] == interface, g
            for face in ("inlet", "outlet", "wall_inlet_ring", "wall_outlet_ring", "outer_wall"):
                assert g[face][1] > 0, (face, g)
            assert sum(ranks) == fluid + wall and max(ranks) <= (0.55 if np == 2 else 1) * (fluid + wall), ranks


@case
def mesh_verification():
    """The cube and the thick-walled cylinder: their groups, and a ladder of sizes."""
    sizes = [groups(f"cylinder_L{k}.msh", 1, "solid,inner,outer,top,bottom")[0]["solid"][0] for k in range(3)]
    print("cylinder cells per level", sizes)
    assert sizes[0] < sizes[1] < sizes[2] and sizes[2] >= 4 * sizes[1]
    g, _ = groups("cube_L1.msh", 2, "solid,x0,x1,y0,y1,z0,z1")
    assert all(g[f][1] > 0 for f in ("x0", "x1", "y0", "y1", "z0", "z1"))


@case
def layout_floors():
    """Every #include of fsi_app's sources goes down the floors or stays in its folder; a
    header that climbs (io including core, a block including another block) fails, naming both."""
    top = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "fsi_app")
    floor = {room: k for k, rooms in enumerate(FLOORS) for room in rooms}
    climbs, files = [], 0
    for root, _, names in os.walk(top):
        for name in names:
            if not name.endswith((".h", ".cxx")):
                continue
            path = os.path.relpath(os.path.join(root, name), top)
            room = path.split(os.sep)[0]
            assert room in floor, f"{path}: folder {room} is on no floor of FLOORS"
            files += 1
            for inc in re.findall(r'#include "([^"]+)"', open(os.path.join(root, name)).read()):
                target = inc.split("/")[0] if "/" in inc else room
                assert target in floor, f"{path} includes {inc}: {target} is on no floor"
                if target != room and floor[target] >= floor[room]:
                    climbs.append(f"{path} -> {inc}")
    print(files, "files;", "climbing includes:", climbs)
    assert files > 60 and not climbs, climbs


@case
def make_meshes_tube():
    """scripts/make-meshes makes a tube of any size into a file of the user's (nothing is written
    into the source tree): its fluid region holds pi Ri^2 L and its wall pi (Ro^2 - Ri^2) L to
    within 1 % (the circle's polygonal approximation at h = Ri / 6), every group of the tube
    scenes is there (fsi_mesh_info), and a wrong size stops the script, exit 2, before gmsh runs."""
    tmp = tempfile.mkdtemp()
    mesh = os.path.join(tmp, "carotid.msh")
    script = os.path.join(TOP, "scripts", "make-meshes")
    before = sorted(os.listdir(MESHES))
    Ri, Ro, L = 0.3, 0.37, 1.0
    subprocess.run([str(a) for a in (script, "tube", "--Ri", Ri, "--Ro", Ro, "--L", L, "--h", 0.05, "--layers", 1, "--out", mesh)], check=True)
    assert sorted(os.listdir(MESHES)) == before
    volume = gmsh_region_volumes(mesh)
    print("region volumes", volume)
    between(volume["fluid"] / (math.pi * Ri**2 * L), 0.99, 1.0, "fluid volume / pi Ri^2 L")
    between(volume["wall"] / (math.pi * (Ro**2 - Ri**2) * L), 0.99, 1.01, "wall volume / pi (Ro^2 - Ri^2) L")
    g, _ = groups(mesh, 1, TUBE_GROUPS)
    assert all(g[name][0] + g[name][1] > 0 for name in TUBE_GROUPS.split(",")), g
    for bad, msg in ((["--Ri", 0.4, "--Ro", 0.3, "--L", 1, "--h", 0.1, "--layers", 1, "--out", mesh], "--Ri 0.4 must be less than --Ro 0.3"),
                     (["--Ri", 0.3, "--Ro", 0.4, "--L", -1, "--h", 0.1, "--layers", 1, "--out", mesh], "--L -1: give a positive number"),
                     (["--Rx", 1], "unknown option or missing value: --Rx")):
        p = subprocess.run([script, "tube"] + [str(b) for b in bad], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        assert p.returncode == 2 and msg in p.stdout, (bad, p.returncode, p.stdout)
    shutil.rmtree(tmp)


def gmsh_region_volumes(path):
    """The volume of each physical group of 3-D cells of a gmsh 4.1 ASCII file, from its
    tetrahedra's vertices."""
    text = open(path).read().split("\n")
    names = {}
    k = text.index("$PhysicalNames")
    for line in text[k + 2:text.index("$EndPhysicalNames")]:
        dim, tag, name = line.split(maxsplit=2)
        if dim == "3":
            names[int(tag)] = name.strip('"')
    k = text.index("$Entities")
    npts, ncur, nsur, nvol = map(int, text[k + 1].split())
    physical = {}
    for line in text[k + 2 + npts + ncur + nsur:k + 2 + npts + ncur + nsur + nvol]:
        w = line.split()
        tags = [int(t) for t in w[8:8 + int(w[7])]]
        physical[int(w[0])] = [names[t] for t in tags if t in names]
    xyz, k = {}, text.index("$Nodes")
    blocks, k = int(text[k + 1].split()[0]), k + 2
    for _ in range(blocks):
        n = int(text[k].split()[3])
        for tag, coords in zip(text[k + 1:k + 1 + n], text[k + 1 + n:k + 1 + 2 * n]):
            xyz[int(tag)] = [float(c) for c in coords.split()[:3]]
        k += 1 + 2 * n
    volume, k = {}, text.index("$Elements")
    blocks, k = int(text[k + 1].split()[0]), k + 2
    for _ in range(blocks):
        dim, entity, kind, n = map(int, text[k].split())
        for line in text[k + 1:k + 1 + n] if kind in (4, 11) else []:
            a, b, c, d = (xyz[int(t)] for t in line.split()[1:5])
            u, v, w = ([q[i] - a[i] for i in range(3)] for q in (b, c, d))
            det = u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0])
            for name in physical.get(entity, []):
                volume[name] = volume.get(name, 0) + abs(det) / 6
        k += 1 + n
    return volume


@case
def bench_command_line():
    """Every benchmark script prints its usage on --help, and stops before any run on an option or
    a mode it does not take, or an option without its value, naming what it takes (a sweep that
    started instead would run for hours and fail the test by its timeout)."""
    scripts = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scripts")
    def py(*args):
        p = subprocess.run(["python3", *args], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=60)
        print("$ python3", " ".join(args), "\n" + p.stdout[-500:])
        return p.returncode, p.stdout
    names = sorted(f for f in os.listdir(scripts) if f.startswith("bench_") and f.endswith(".py"))
    assert len(names) >= 12, names
    for name in names:
        path = os.path.join(scripts, name)
        rc, out = py(path, "--help")
        assert rc == 0 and "usage" in out.lower(), (name, out)
        rc, out = py(path, "--no-such-option")
        assert rc != 0 and ("unknown option --no-such-option" in out or "unrecognized arguments: --no-such-option" in out), (name, out)
    for args, msg in ((["bench_fsi_scalability.py", "--tube", "2"], "unknown option --tube; the script takes --tubes VALUE"),
                      (["bench_fsi_scalability.py", "--tubes"], "--tubes needs a value"),
                      (["bench_wall.py", "sede"], "unexpected argument 'sede'; the script takes one of proxy|seed|ab|tubes"),
                      (["bench_fsi_solvers.py", "setup", "3"], "unexpected argument 'setup 3'")):
        rc, out = py(os.path.join(scripts, args[0]), *args[1:])
        assert rc != 0 and msg in out, (args, out)


@case
def work_precision_reference():
    """The coupled study's reference (scripts/bench_fsi_work_precision.py) on rows made from
    q(h, dt) = q* + a h^2 + b dt^3 (h halving per level): Richardson's extrapolation recovers q*
    and the orders 2 and 3, from the full grid and from a finest level run only at the two larger
    steps (the time error then comes from the level below)."""
    scripts = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scripts")
    sys.path.insert(0, scripts)
    argv, sys.argv = sys.argv, [sys.argv[0]]
    spec = importlib.util.spec_from_file_location("work_precision", os.path.join(scripts, "bench_fsi_work_precision.py"))
    wp = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(wp)
    sys.argv = argv
    exact, a, b = 1.5e-4, 3.0e-3, -2.0e6
    unknowns = {0: 1000, 1: 8000, 2: 64000}  # h ~ unknowns^(-1/3): 1/10, 1/20, 1/40
    def row(level, dt):
        h = unknowns[level] ** (-1 / 3)
        r = {q: "" for q in wp.QUANTITIES}
        r.update(config="facsi", scheme="bdf2", geometry="curved", level=str(level), dt=f"{dt:g}",
                 fluid_unknowns=str(unknowns[level]), seconds="1", interface_l2=repr(exact + a * h ** 2 + b * dt ** 3))
        return r
    full = [row(lv, dt) for lv in unknowns for dt in wp.DTS]
    partial = [r for r in full if not (r["level"] == "2" and math.isclose(float(r["dt"]), wp.DTS[-1]))]
    with tempfile.TemporaryDirectory() as d:
        wp.OUT = os.path.join(d, "wp")
        for rows, time_level in ((full, "2"), (partial, "1")):
            errors = wp.errors(rows)
            with open(wp.OUT + "_orders.csv") as f:
                (ref,) = [r for r in csv.DictReader(f) if r["quantity"] == "interface_l2"]
            print(ref)
            assert abs(float(ref["reference"]) - exact) < 1e-12 * exact, ref
            assert abs(float(ref["reference_from_2dt"]) - exact) < 1e-12 * exact, ref
            assert abs(float(ref["order_h"]) - 2) < 1e-9 and abs(float(ref["order_dt"]) - 3) < 1e-9, ref
            assert ref["order_dt_level"] == time_level, ref
            finest = max(rows, key=lambda r: (int(r["level"]), -float(r["dt"])))
            expected = abs(float(finest["interface_l2"]) - exact) / exact
            between(errors[id(finest)]["interface_l2"], expected * (1 - 1e-9), expected * (1 + 1e-9), "relative error of the finest run")


if __name__ == "__main__":
    main("fsi_tools")
