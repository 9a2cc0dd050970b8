#!/usr/bin/env python3
"""ctest cases for fsi_app: each runs programs and asserts numbers or messages from their output."""
import os
import re

from testlib import BUILD, between, case, main, run

MESHES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "meshes")
MESH_INFO = os.path.join(BUILD, "fsi_app", "fsi_mesh_info")
TUBE_GROUPS = "fluid,wall,inlet,outlet,interface,wall_inlet_ring,wall_outlet_ring,outer_wall"


def groups(mesh, np=1, require=""):
    out = run([MESH_INFO, "-mesh", os.path.join(MESHES, mesh)] + (["-require", require] if require else []), np)
    g = {m.group(1): tuple(int(x) for x in m.groups()[1:]) for m in re.finditer(r"group (\S+) cells (\d+) faces (\d+) vertices (\d+)", out)}
    ranks = [int(x) for x in re.findall(r"rank cells (\d+)", out)]
    return g, ranks


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
def mesh_errors():
    """A missing file, a file that is not a mesh, a mesh without a group the scene needs."""
    for args, msg in (([os.path.join(MESHES, "nothere.msh")], "mesh file '{}' does not exist or cannot be read (option -mesh)"),
                      ([os.path.join(MESHES, "tube.geo")], "mesh file '{}' is not a gmsh .msh file"),
                      ([os.path.join(MESHES, "cube_L0.msh"), "-require", "solid,interface"],
                       "mesh file '{}' has no physical group 'interface', which this scene needs (the file has: solid, x0, x1")):
        for np in (1, 2):
            out = run([MESH_INFO, "-mesh"] + args, np, fail=True)
            assert msg.format(args[0]) in out, msg


if __name__ == "__main__":
    main("fsi")
