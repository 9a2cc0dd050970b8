#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""ctest cases for fsi_app's handling of mistakes: options, options files, file names, meshes
and checkpoints that a run must refuse with one sentence (naming the option, file or cause),
a nonzero exit status and nothing lost; and what a new user meets on the way (-help, a scene
run from another folder, a one-step run)."""
import socket

from fsilib import *  # noqa: F401,F403 (the cases' shared runners, meshes and scenes)
from testlib import BUILD, ENV, TOP, between, case, main, run

WALL_SCENE = ["-options_file", os.path.join(SCENES, "wall_tube1_static.opts")]
FSI_SCENE = ["-options_file", FSI]
CUBE = ["-mesh", os.path.join(MESHES, "cube_L0.msh"), "-structure_clamp", "x0", "-structure_pressure_group", "x1", "-structure_pressure", 0.01,
        "-structure_density", 1, "-ksp_type", "preonly", "-pc_type", "lu"]


@case
def mesh_errors():
    """A missing file, a file that is not a mesh, a mesh without a group the scene needs."""
    for args, msg in (([os.path.join(MESHES, "nothere.msh")], "mesh file '{}' does not exist or cannot be read (option -mesh)"),
                      ([os.path.join(MESHES, "tube.geo")], "mesh file '{}' is not a gmsh .msh file"),
                      ([os.path.join(MESHES, "cube_L0.msh"), "-require", "solid,interface"],
                       "-require interface: mesh file '{}' has no physical group 'interface', which this scene needs (the file has: x0, x1, y0, y1, z0, z1, solid)")):
        for np in (1, 2):
            out = run([MESH_INFO, "-mesh"] + args, np, fail=True)
            assert msg.format(args[0]) in out, msg


@case
def mesh_group_faults():
    """A group an option names that the mesh file does not have, one of the wrong dimension (the
    fluid's inlet naming the fluid's cells) and one that is named but empty (in $PhysicalNames,
    no element carrying it: PETSc makes no label of it, and the run said the file had no such
    group): one sentence naming the option, the group and the file, on 1 and 2 ranks, exit
    status nonzero, and nothing written (no series, report, checkpoint, nor their locks)."""
    tmp = tempfile.mkdtemp()
    empty = os.path.join(tmp, "empty_group.msh")
    text = open(os.path.join(MESHES, "tube1_L0.msh")).read()
    open(empty, "w").write(text.replace("$PhysicalNames\n8\n", '$PhysicalNames\n9\n2 99 "outlet_b"\n'))
    out = os.path.join(tmp, "out")
    os.mkdir(out)
    files = ["-output", os.path.join(out, "s.xdmf"), "-report", os.path.join(out, "r.json"), "-checkpoint", os.path.join(out, "c.chk")]
    for opts, msg in ((["-fluid_inlet", "inflow"], f"-fluid_inlet inflow: mesh file '{empty}' has no physical group 'inflow', which this scene needs (the file has: "),
                      (["-fluid_inlet", "fluid"], f"-fluid_inlet fluid: the group holds cells, and the option takes a group of faces (mesh file '{empty}'; its groups of faces: inlet, outlet, interface, "),
                      (["-fluid_inlet", "outlet_b"], f"-fluid_inlet outlet_b: the physical group 'outlet_b' of mesh file '{empty}' is empty (named, but no element belongs to it), and the option takes a group of faces"),
                      (["-structure_clamp", "wall_inlet_ring,outlet_b"], f"-structure_clamp outlet_b: the physical group 'outlet_b' of mesh file '{empty}' is empty")):
        for np in (1, 2):
            refused([APP] + FSI_SCENE + ["-mesh", empty] + opts + files, msg, np)
            assert os.listdir(out) == [], os.listdir(out)
    shutil.rmtree(tmp)


@case
def curved_mesh_faults():
    """Curved cells asked of a first-order file, refinement of curved cells (which would put the
    new nodes on the straight edges), and a curved cell folded by its nodes stop with a sentence
    naming the file or the cell and the way out, printed once on 2 ranks; -mesh_order 1 reads
    the same files straight."""
    lame = ["-structure_clamp", "sym_x:x,sym_y:y,top:z,bottom:z", "-structure_pressure", 1, "-structure_pressure_group", "inner"]
    refused([APP, "-mesh", os.path.join(MESHES, "quarter_cylinder_L0.msh"), "-mesh_order", 2] + lame,
            "-mesh_order 2: mesh file '" + os.path.join(MESHES, "quarter_cylinder_L0.msh") + "' has first-order cells only", np=2)
    refused([APP, "-mesh", os.path.join(MESHES, "quarter_cylinder_L0_o2.msh"), "-refine", 1] + lame,
            "-refine 1 on the curved cells of", np=2)
    out = run([APP, "-mesh", os.path.join(MESHES, "quarter_cylinder_L0_o2.msh"), "-refine", 1, "-mesh_order", 1] + lame + ["-snes_type", "ksponly", "-pc_type", "lu"], 2)
    assert "unknowns:" in out, out
    # gmsh's second-order hollow cylinder at level 1 holds a cell its nodes fold (gmsh: "jac. < 0")
    cylinder = ["-mesh", os.path.join(MESHES, "cylinder_L1_o2.msh"), "-structure_clamp", "bottom", "-structure_pressure", 1, "-structure_pressure_group", "inner"]
    refused([APP] + cylinder, "is folded by its second-order nodes", np=2)
    out = run([APP] + cylinder + ["-mesh_order", 1, "-snes_type", "ksponly", "-pc_type", "lu"], 2)
    assert "unknowns:" in out, out


@case
def structure_bad_options():
    """Options out of their range, incomplete arrays, unknown names: a sentence naming the option
    and what it may take."""
    mesh = os.path.join(MESHES, "tube1_L0.msh")
    for opts, msg in ((["-structure_nu", 0.5], "-structure_nu: value must be in (-1, 0.5) (got 0.5)"),
                      (["-structure_E", -1], "-structure_E: value must be positive (got -1)"),
                      (["-structure_arterial", "1,2"], "-structure_arterial: give all five of c1,eps1,eps2,alpha1,alpha2 (got 2)"),
                      (["-structure_arterial", "1,1,0.5,1,5"], "need c1 > 0, eps1 > 0, eps2 > 1, alpha1 >= 0, alpha2 >= 2"),
                      (["-max_step_cuts", -1], "-max_step_cuts: value must be in [0, 20] (got -1)"),
                      (["-time_scheme", "bdf3"], "-time_scheme bdf3 is not one of: backward_euler, bdf2"),
                      (["-dt", 1e-3, "-time_predictor_order", 2], "-time_predictor_order 2: backward_euler keeps 2 past states, so the order is at most 1"),
                      (["-output", "out.vtk"], "-output out.vtk: name the file <name>.xdmf"),
                      (["-restart", "nothere.chk"], "-restart nothere.chk: no such checkpoint"),
                      (["-structure_nh_mu", -1, "-structure_material", "neohooke"], "-structure_nh_mu: value must be positive (got -1)"),
                      (["-structure_region", "lumen"], "has no physical group 'lumen', which this scene needs"),
                      (["-structure_subdomains", 0], "-structure_subdomains: value must be >= 1 (got 0)"),
                      (["-dt", -1], "-dt: value must be >= 0 (got -1)"),
                      (["-structure_load_steps", 0], "-structure_load_steps: value must be in [1, 10000] (got 0)"),
                      (["-structure_clamp", "wall_inlet_ring:w"], "-structure_clamp wall_inlet_ring:w: components are x, y, z"),
                      (["-blocks", "structure,fluid,geometry,coupling", "-fluid_density", 0], "-fluid_density: value must be positive (got 0)"),
                      (["-lame", "2,1"], "-lame 2,1: the inner radius must be smaller than the outer one (give Ri,Ro)"),
                      (["-lame", "1"], "-lame: give the inner and the outer radius, Ri,Ro (got 1 values)"),
                      (["-lame", "-1,2"], "-lame: value 1 must be positive (got -1)"),
                      (["-structure_support", -1], "-structure_support: value must be >= 0 (got -1)"),
                      (["-structure_support", "1,2,3"], "-structure_support 1,2,3: give at most 2 values (got 3)"),
                      (["-structure_body_force", "1,2,3,4"], "-structure_body_force 1,2,3,4: give at most 3 values (got 4)"),
                      (["-structure_support", 1, "-structure_support_group", "wall"], "-structure_support_group wall: the group holds cells, and the option takes a group of faces"),
                      (["-structure_support", 1, "-structure_support_group", "adventitia"], "has no physical group 'adventitia', which this scene needs")):
        refused([APP, "-mesh", mesh] + WALL[2:] + [str(o) for o in opts], msg)


@case
def options_not_finite():
    """Every real option of -help (the scene's and every block's, scalars and arrays), given nan
    in a scene with every block, stops with its name before the mesh is read (the wall's pulse
    end also in a fluid-only scene, whose inlet pulse takes it as its default) (it used to reach Newton as four halvings and "apply the load in more
    increments"); inf too, on 2 ranks."""
    sections = run([APP, "-help"], 1, fail=None).split("-----")
    scene = "".join(t for t in sections if t.lstrip("-\n").startswith("fsi_app: "))  # the scene's and every block's options
    reals = re.findall(r"^\s+(-[a-z_0-9A-Z]+) <[^>]*>: .*\((?:a number|numbers separated by commas)[,;)]", scene, re.M)
    print(len(reals), "real options:", " ".join(reals))
    assert len(reals) >= 25 and {"-structure_pressure", "-structure_body_force", "-fluid_inlet_pressure", "-mms_amplitude", "-geometry_amplitude", "-dt"} <= set(reals)
    for name in reals:
        out = refused([APP, "-blocks", "structure,fluid,geometry,coupling", name, "nan"], f"{name}: value must be a finite number (got nan)")  # every block reads its options
        assert "unknowns:" not in out
    # the fluid's pulse takes the wall's end by default: checked there too when no wall reads it
    refused([APP, "-blocks", "fluid", "-mesh", os.path.join(MESHES, "tube1_L0.msh"), "-structure_pressure_until", "nan"], "-structure_pressure_until: value must be a finite number (got nan)")
    for name, value in (("-structure_pressure", "inf"), ("-structure_body_force", "0,0,-inf"), ("-fluid_inlet_pressure", "1e400")):
        refused([APP, "-options_file", FSI, name, value], f"{name}: value{' 3' if ',' in value else ''} must be a finite number (got {'-' if '-inf' in value else ''}inf)", np=2)


@case
def time_steps_bad():
    """dt and t_final: finite, at least one step, a whole number of steps that the step counter
    holds (a step count past 2^31 used to wrap to none: exit 0 after no step); 0.1 to 0.3 is 3
    steps although 0.3 / 0.1 is 2.9999999999999996 in floating point."""
    cube = ["-mesh", os.path.join(MESHES, "cube_L0.msh"), "-structure_clamp", "x0", "-structure_pressure_group", "x1", "-structure_pressure", 0.01,
            "-ksp_type", "preonly", "-pc_type", "lu"]
    for opts, msg in ((["-dt", 1e-10, "-t_final", 1], "-dt 1e-10 -t_final 1: 1e+10 steps, more than a run can count (2147483647)"),
                      (["-dt", "inf", "-t_final", "inf"], "-dt: value must be a finite number (got inf)"),
                      (["-dt", 0.1, "-t_final", "nan"], "-t_final: value must be a finite number (got nan)"),
                      (["-dt", 0.3, "-t_final", 1], "-dt 0.3 -t_final 1: the end time must be a whole number of steps (it is 3.33333 steps): take -t_final 0.9 or 1.2"),
                      (["-dt", 2, "-t_final", 1], "-dt 2 -t_final 1: the end time must be at least one step")):
        refused([APP] + cube + [str(o) for o in opts], msg, np=2 if "inf" in opts else 1)
    out = run([APP] + cube + ["-dt", 0.1, "-t_final", 0.3], 1)
    assert "step 3/3 t 3.0000e-01" in out and "step 4" not in out, out


@case
def mesh_bad_files():
    """Damaged copies of cube_L0.msh: an element naming a node that does not exist (a segfault
    in PETSc's reader on 1 rank, a wrong mesh on 2), a block naming an entity that does not
    exist (a segfault), a NaN coordinate (accepted), a file cut short inside $Nodes or $Elements
    (PETSc's "Insufficient data" without the file's name), the format 2.2, a coordinate of 1e300
    (NaN in the assembly), two nodes at one point (a silent crack), a tetrahedron without volume
    (named by a rank-local cell number): a sentence naming the file and the line or the nodes
    and element by their tags, on 1 and 2 ranks."""
    tmp = tempfile.mkdtemp()
    text = open(os.path.join(MESHES, "cube_L0.msh")).read()
    lines = text.split("\n")
    cases = []

    def damaged(name, new_lines):
        path = os.path.join(tmp, name + ".msh")
        open(path, "w").write("\n".join(new_lines))
        return path

    tet_block = corrupt(lines, "$Elements", (r"^3 \d+ 4 \d+$", lambda l: l))[1]  # the first tetrahedron follows its block's header
    tet = lines[tet_block].split()
    bad, at = corrupt(lines, "$Elements", (r"^" + tet[0] + " ", lambda l: " ".join(tet[:-1] + ["1000"])))
    cases.append((damaged("node", bad), f"line {at}: element {tet[0]} names node 1000, which $Nodes does not define"))
    bad, at = corrupt(lines, "$Nodes", (r"^3 \d+ 0 \d+$", lambda l: "3 99 0 " + l.split()[3]))
    cases.append((damaged("entity", bad), f"line {at}: the block names the entity 99 of dimension 3, which $Entities does not define"))
    block = corrupt(lines, "$Nodes", (r"^3 \d+ 0 \d+$", lambda l: l))[1]
    n = int(lines[block - 1].split()[3])  # its n tags, then its n coordinate lines
    bad = lines[:block + n] + ["nan " + lines[block + n].split(" ", 1)[1]] + lines[block + n + 1:]
    cases.append((damaged("nan", bad), f"line {block + n + 1}: node {lines[block]} has the coordinate 'nan': coordinates must be finite numbers"))
    # 1e300 is finite, but a volume of such coordinates is not (NaN in the assembly, before)
    bad = lines[:block + n] + ["1e300 " + lines[block + n].split(" ", 1)[1]] + lines[block + n + 1:]
    cases.append((damaged("huge", bad), f"line {block + n + 1}: node {lines[block]} has the coordinate '1e300': coordinates must be at most 1e100 in size"))
    # a block's second node moved onto its first: two nodes at one point (a silent crack, before)
    b2 = next(k + 1 for k in range(lines.index("$Nodes") + 1, lines.index("$EndNodes")) if re.match(r"^\d \d+ 0 \d+$", lines[k]) and int(lines[k].split()[3]) >= 2)
    n2 = int(lines[b2 - 1].split()[3])
    bad = lines[:b2 + n2 + 1] + [lines[b2 + n2]] + lines[b2 + n2 + 2:]
    first, second = sorted((int(lines[b2]), int(lines[b2 + 1])))
    x, y, z = (float(c) for c in lines[b2 + n2].split())
    cases.append((damaged("twin", bad), f": nodes {first} and {second} are both at ({x:.17g}, {y:.17g}, {z:.17g}): the cells on either side would not be connected there"))
    # a tetrahedron naming one node twice has no volume (named by a rank-local cell number, before)
    bad, at = corrupt(lines, "$Elements", (r"^" + tet[0] + " ", lambda l: " ".join(tet[:-1] + [tet[-2]])))
    cases.append((damaged("flat", bad), f"line {at}: tetrahedron {tet[0]} (nodes {' '.join(tet[1:-1] + [tet[-2]])}) has no volume: its nodes lie in a plane"))
    for section in ("$Nodes", "$Elements"):
        cut = text[:text.index(section) + (text.index("$End" + section[1:]) - text.index(section)) // 2]
        cases.append((damaged("cut" + section[1:], cut.split("\n")), f"ends inside {section} (line {cut.count(chr(10)) + 1}): the file is truncated"))
    cases.append((damaged("v22", ["$MeshFormat", "2.2 0 8"] + lines[2:]), "is gmsh format 2.2: fsi_app reads format 4.1 ASCII"))
    for path, msg in cases:
        for np in (1, 2):
            refused([APP, "-mesh", path], f"mesh file '{path}'{'' if msg.startswith(':') else ' '}{msg}", np)
    shutil.rmtree(tmp)


@case
def option_faults():
    """Option values a new user mistypes stop the run before the first step with one sentence,
    printed once on 2 ranks: a choice that is not one of the list (PETSc's own parsers print it
    on every rank), a switch that is neither true nor false (PETSc's names no option), a structure set-up interval where the wall is not set up every time step, a cosine pulse without its length, more probes than the 20 a run records (the rest were dropped silently), a
    number of load increments no static solve needs, a refinement whose mesh 32-bit indices
    cannot number (it ran out of memory in DMRefine); and a probe that the pulse's front has not
    reached by the end of the run is said to be so (it printed "arrives at t -1")."""
    probes21 = ",".join(f"0.09,0,{0.1 * i:g}" for i in range(21))
    cases = ((["-time_scheme", "bogus"], "-time_scheme bogus is not one of: backward_euler, bdf2"),
             (["-structure_pc_setup", "sometimes"], "-structure_pc_setup sometimes is not one of: every_newton, every_step, once"),
             (["-fluid_pc_setup", "once"], "-fluid_pc_setup once is not one of: every_newton, every_step"),
             (["-structure_pc_setup_interval", 2], "-structure_pc_setup_interval 2: only with a set-up every time step (-structure_pc_setup every_step); this run's is once"),
             (["-fluid_pc_setup_interval", 2], "-fluid_pc_setup_interval 2: only with a set-up every time step (-fluid_pc_setup every_step); this run's is every_newton"),
             (["-structure_pc_setup_interval", 0], "-structure_pc_setup_interval: value must be >= 1 (got 0)"),
             (["-jacobian_direct_add", "maybe"], "-jacobian_direct_add maybe is not true or false"),
             (["-structure_material", "rubber"], "-structure_material rubber is not one of:"),
             (["-fluid_inlet_pressure_shape", "square"], "-fluid_inlet_pressure_shape square is not one of: step, cosine"),
             (["-fluid_inlet_pressure_shape", "cosine", "-fluid_inlet_pressure_until", 0], "-fluid_inlet_pressure_shape cosine needs the hump's length: -fluid_inlet_pressure_until T with T > 0"),
             (["-structure_probes", probes21], "-structure_probes: at most 20 points (got more than 20)"),
             (["-fluid_probes", probes21], "-fluid_probes: at most 20 points (got more than 20)"),
             (["-structure_load_steps", 100000000], "-structure_load_steps: value must be in [1, 10000] (got 1e+08)"),
             # tube1_L0 has 2998 cells: 8^10 times as many is 3.2e12
             (["-refine", 10], "-refine 10: the mesh's 2998 cells would become 3.22e+12 (each refinement multiplies them by 8)"))
    for opts, msg in cases:
        out = run([APP, "-options_file", FSI] + [str(o) for o in opts], 2, fail=True)
        assert out.count(msg) == 1, (msg, out[-2000:])
        assert "PETSC ERROR: #" not in out.split(msg)[0], out[-2000:]  # the sentence comes first, no other error before it
    # one step of 0.5 ms: the front (217 cm/s) has not reached z = 0.625 or 2.5
    out = run([APP, "-options_file", FSI, "-t_final", 5e-4, "-fluid_probes", "0,0,0.625,0,0,2.5"], 2)
    assert "arrives at t -1" not in out, out[-2000:]
    for z in ("0.625", "2.5"):
        assert f"probe (0., 0., {z}): the front (p = 665.) has not arrived by t 5.000000e-04, the end of the run" in out, out[-2000:]


@case
def group_faults():
    """Every option that names a mesh group is checked against what the group holds, and options
    whose roles exclude each other against naming the same group: a cell group as clamped faces
    or slip faces, a face group as the wall's region (each ran and exited 0 with nothing
    clamped, or nothing solved), the fluid's region as the wall's, the inlet as the outlet or a
    no-slip group as the outlet (each solved another problem and exited 0). One sentence naming
    both the option and the group, on 2 ranks."""
    wall = os.path.join(MESHES, "..", "scenes", "wall_tube1_static.opts")
    cases = ((wall, ["-structure_clamp", "wall"], "-structure_clamp wall: the group holds cells, and the option takes a group of faces"),
             (wall, ["-structure_region", "outer_wall"], "-structure_region outer_wall: the group holds faces, and the option takes a group of cells"),
             (FSI, ["-structure_region", "fluid"], "-structure_region fluid and -fluid_region fluid name the same group: the regions of the wall and the fluid must be different groups"),
             (FSI, ["-geometry_slip", "fluid:z"], "-geometry_slip fluid: the group holds cells, and the option takes a group of faces"),
             (FSI, ["-fluid_outlet", "inlet"], "-fluid_inlet inlet and -fluid_outlet inlet name the same group: the fluid's inlet, outlet and no-slip faces must be different groups"),
             (FSI, ["-fluid_noslip", "outlet"], "-fluid_noslip outlet and -fluid_outlet outlet name the same group"))
    for scene, opts, msg in cases:
        out = run([APP, "-options_file", scene] + [str(o) for o in opts], 2, fail=True)
        assert out.count(msg) == 1, (msg, out[-2000:])


@case
def coupled_bad_input():
    """A mesh without an interface group, an interface group that is not between the fluid
    and the wall, a no-slip interface, a static coupled run, an incomplete or unknown block
    list, a probe outside the fluid, FaCSI's fluid PC told a multiplier field the split does not
    have, a direct solver out of workspace (alone and inside a field split), a fluid mesh that
    inverts under a soft wall, a scene with no solver (PETSc's default ILU stopped at the
    multiplier's missing diagonal entry with its own trace), a direct solver out of memory inside
    FaCSI's fluid step: a sentence naming the cause."""
    cases = ((["-mesh", os.path.join(MESHES, "cube_L0.msh")], "has no physical group"),
             (["-geometry_interface", "outer_wall"], "-geometry_interface outer_wall: the group's faces must lie between cells of -fluid_region fluid and of -structure_region wall"),
             (["-fluid_noslip", "interface"], "-fluid_noslip interface: on the interface interface the fluid moves with the wall"),
             (["-dt", 0], "-dt 0: the coupled problem is dynamic"),
             (["-blocks", "structure,coupling"], "-blocks: the coupling ties structure, fluid and geometry: name all four"),
             (["-blocks", "structure,wall"], "-blocks: unknown block 'wall' (structure, fluid, geometry, coupling, outlets)"),
             (["-fluid_probes", "5,0,1"], "-fluid_probes: the point (5., 0., 1.) is not in the field's region"),
             (["-options_file", FACSI, "-fieldsplit_fluid_pc_facsi_fluid_multiplier_field", "lambda"],
              "PCFACSIFLUID: the split has no field called lambda (-pc_facsi_fluid_multiplier_field)"),
             # MUMPS given no room beyond its analysis' estimate: the split and option to raise
             # (with no raise of its room allowed: fsi_workspace_raised has the raises)
             (["-mat_mumps_icntl_14", 0, "-t_final", 5e-4, "-max_step_cuts", 0, "-max_workspace_raises", 0],
              "the linear solver failed in step 1: the factorization of -pc_type ran out of workspace (MUMPS: raise -mat_mumps_icntl_14"),
             (["-options_file", os.path.join(SCENES, "fsi_fieldsplit.opts"), "-fieldsplit_fluid_mat_mumps_icntl_14", 0, "-t_final", 5e-4, "-max_step_cuts", 0, "-max_workspace_raises", 0],
              "the factorization of -fieldsplit_fluid_pc_type ran out of workspace (MUMPS: raise -fieldsplit_fluid_mat_mumps_icntl_14"),
             # MUMPS allowed 1 MB of working memory inside FaCSI's fluid step: the inner factorization named
             (["-options_file", os.path.join(SCENES, "fsi_facsi_lu_fluid.opts"), "-fieldsplit_fluid_dirichlet_mat_mumps_icntl_23", 1, "-t_final", 5e-4, "-max_step_cuts", 0],
              "the linear solver failed in step 1: the factorization of -fieldsplit_fluid_dirichlet_pc_type failed in mumps"),
             # a wall 1000 times softer under 750 times the pulse, full Newton steps: the fluid mesh
             # inverts on one rank, and both ranks stop with its cause (they used to part ways in the line search)
             (["-structure_E", 400, "-fluid_inlet_pressure", 1e6, "-t_final", 5e-4, "-max_step_cuts", 0, "-snes_linesearch_type", "basic"],
              "Newton stopped in step 1: a cell of the moved fluid mesh inverted (J <= 0): the wall moved too far in one step"))
    for opts, msg in cases:
        out = run([APP, "-options_file", FSI] + [str(o) for o in opts], 2, fail=True)
        assert msg in out, (msg, out[-2000:])
        assert not re.search(r"\bnan\b", out, re.I)
    refused([APP, "-options_file", os.path.join(SCENES, "fsi_tube1.opts"), "-t_final", 5e-4],
            "-pc_type: not given, and PETSc's default (ILU) cannot factor the rows of the coupling block (they have no diagonal entry): choose a solver", np=2)


@case
def renamed_options():
    """The wall's material options carry the block's prefix (-structure_E, -structure_nu,
    -structure_material, ...); the old names still work and say the new one once on 2 ranks. A
    linear cube under pressure (clamped at x0, loaded at x1, LU): with -E 2 -nu 0.25 the largest
    displacement equals that of -structure_E 2 -structure_nu 0.25 to round-off and is half that
    of E = 1 (linear elasticity: d scales as 1/E), so the old name reaches the material; the run
    with the new names prints no deprecation."""
    base = [APP, "-mesh", os.path.join(MESHES, "cube_L0.msh"), "-structure_material", "linear", "-structure_pressure", 1] + CUBE_LOAD
    old = run(base + ["-E", 2, "-nu", 0.25], 2)
    new = run(base + ["-structure_E", 2, "-structure_nu", 0.25], 2)
    unit = run(base + ["-structure_E", 1, "-structure_nu", 0.25], 2)
    dmax = lambda out: float(re.search(r"max displacement (\S+)", out).group(1))
    for opt in ("-structure_E", "-structure_nu"):
        assert old.count(f"Please use the option {opt} instead") == 1, old
    assert "DEPRECATION" not in new, new
    between(abs(dmax(old) / dmax(new) - 1), 0, 1e-12, "old names against new, relative difference of the largest displacement")
    between(dmax(unit) / dmax(new), 2 - 1e-6, 2 + 1e-6, "largest displacement at E = 1 over E = 2 (Newton to its tolerance)")


@case
def app_help():
    """-help lists every application option the options table of docs/fsi.md documents, each
    with its default (PETSc prints <default>). Only stdout: the run stops after the help on the
    default mesh, and its error on stderr must not split a line of the help."""
    out = run([APP, "-help", "-blocks", "fluid"], 1, fail=None, stderr=False)
    readme = open(os.path.join(MESHES, "..", "docs", "fsi.md")).read()
    table = readme[readme.index("### Options (defaults in brackets; `-help` prints them all)"):readme.index("### How it is built")]
    first = [line.split("|")[1] for line in table.splitlines() if line.startswith("| `")]  # the option column
    options = sorted({o for cell in first for o in re.findall(r"`(-[a-z_0-9<>]+)", cell)})
    missing = [o for o in options if not re.search(r"^\s+" + re.escape(o) + r"[ :]+<", out, re.M)]
    print(len(options), "options documented; missing from -help:", missing)
    assert len(options) >= 35 and not missing, missing


@case
def empty_group_names():
    """An option that names a group of faces given an empty value, or no value at all, is
    refused with its name (it segfaulted)."""
    for extra, option in ((["-structure_pressure_group", ""], "-structure_pressure_group"), (["-structure_clamp", "wall_inlet_ring", "-structure_pressure_group"], "-structure_pressure_group")):
        refused([APP] + WALL_SCENE + extra, f"{option}: the value is empty; name a physical group of faces of")
    for extra, option in ((["-fluid_inlet", ""], "-fluid_inlet"), (["-geometry_interface", ""], "-geometry_interface"), (["-geometry_interface"], "-geometry_interface")):
        refused([APP] + FSI_SCENE + extra, f"{option}: the value is empty; name a physical group of faces of", np=2)
    refused([APP] + FSI_SCENE + ["-fluid_region", ""], "-fluid_region: name the fluid's group (the wall's cells are not the fluid's)", np=2)


@case
def options_file_cycles():
    """An options file that includes itself, or two that include each other, stop with the
    chain of files once on 2 ranks (PETSc's reader recursed until the stack overflowed); an
    included file that is not there is named with the file that names it."""
    tmp = tempfile.mkdtemp()
    f = lambda name: os.path.join(tmp, name)
    open(f("self.opts"), "w").write("-dt 0.1 # a comment\n-options_file self.opts\n")
    open(f("a.opts"), "w").write("-options_file b.opts\n")
    open(f("b.opts"), "w").write("-options_file a.opts\n")
    open(f("c.opts"), "w").write("-options_file nothere.opts\n")
    for np in (1, 2):
        refused([APP, "-options_file", f("self.opts")], f"-options_file: {f('self.opts')} includes {f('self.opts')} again: options files cannot include themselves", np)
        refused([APP, "-options_file", f("a.opts")], f"-options_file: {f('a.opts')} includes {f('b.opts')} includes {f('a.opts')} again", np)
    refused([APP, "-options_file", f("c.opts")], f"-options_file nothere.opts (named in {f('c.opts')}): no such file")
    shutil.rmtree(tmp)


@case
def scenes_from_any_folder():
    """A scene names its included files and meshes relative to itself: it runs from another
    working directory, and installed (cmake --install: share/fsi_app/scenes and meshes) from
    there, with the same answer as from the repository's top."""
    tmp = tempfile.mkdtemp()
    subprocess.run(["cmake", "--install", BUILD, "--prefix", os.path.join(tmp, "prefix")], check=True, stdout=subprocess.DEVNULL)
    installed = os.path.join(tmp, "prefix", "share", "fsi_app")
    assert os.path.isfile(os.path.join(installed, "meshes", "tube1_L0.msh")), os.listdir(installed)
    answers = []
    for scene, cwd in ((os.path.join(SCENES, "wall_tube1_static.opts"), TOP), (os.path.join(SCENES, "wall_tube1_static.opts"), tmp),
                       (os.path.join(installed, "scenes", "wall_tube1_static.opts"), tmp), ("scenes/wall_tube1_static.opts", installed)):
        r = os.path.join(tmp, "r.json")
        p = subprocess.run(["mpiexec", "-n", "1", APP, "-options_file", scene, "-report", r], env=ENV, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=300)
        print(scene, "from", cwd, "\n", p.stdout[-1500:])
        assert p.returncode == 0, p.stdout[-2000:]
        answers.append(report(r)["results"]["max_displacement"])
    assert max(answers) == min(answers) > 0, answers
    shutil.rmtree(tmp)


@case
def outputs_not_inputs():
    """A file the run writes that is the mesh it reads, or two outputs that are one file, stop
    the run before it writes anything; the mesh is unchanged (it was overwritten, exit 0)."""
    tmp = tempfile.mkdtemp()
    f = lambda name: os.path.join(tmp, name)
    mesh = f("m.msh")
    shutil.copy(os.path.join(MESHES, "tube1_L0.msh"), mesh)
    before = open(mesh, "rb").read()
    wall = WALL_SCENE + ["-mesh", mesh]
    for opt in ("-checkpoint", "-report"):
        refused([APP] + wall + [opt, mesh], f"{opt} {mesh} is the file of -mesh: the run would write over what it reads", 2)
    refused([APP] + wall + ["-report", f("a"), "-checkpoint", f("a")], f"-checkpoint {f('a')} and -report {f('a')} are one file: one would be lost")
    refused([APP] + wall + ["-output", f("o.xdmf"), "-checkpoint", f("o.h5")], f"-output (its data file) {f('o.h5')} and -checkpoint {f('o.h5')} are one file")
    os.symlink(mesh, f("link.msh"))
    refused([APP] + wall + ["-report", f("link.msh")], f"-report {f('link.msh')} is the file of -mesh")
    assert open(mesh, "rb").read() == before
    assert sorted(os.listdir(tmp)) == ["link.msh", "m.msh"], os.listdir(tmp)
    shutil.rmtree(tmp)


@case
def checkpoint_locked():
    """A checkpoint another live run is writing can neither be written nor restarted from (the
    second run took the first's later steps); a finished run leaves no lock; a restart from a
    checkpoint that no run holds goes on."""
    tmp = tempfile.mkdtemp()
    chk = os.path.join(tmp, "c.chk")
    dyn = [APP] + CUBE + ["-dt", 0.1]
    run(dyn + ["-t_final", 0.2, "-checkpoint", chk])
    assert not os.path.exists(chk + ".lock")
    open(chk + ".lock", "w").write(f"{socket.gethostname()} {os.getpid()}\n")  # this test's process: alive
    refused(dyn + ["-t_final", 0.4, "-restart", chk, "-checkpoint", chk], f"-checkpoint {chk}: another run (process {os.getpid()}) is writing it", 2)
    refused(dyn + ["-t_final", 0.4, "-restart", chk], f"-restart {chk}: another run (process {os.getpid()}) is writing it; give another name, or wait until that run ends (or remove {chk}.lock if no run is); reading it now would take that run's later steps")
    os.remove(chk + ".lock")
    out = run(dyn + ["-t_final", 0.4, "-restart", chk, "-checkpoint", chk])
    assert "restart from" in out and "step 4/4" in out
    shutil.rmtree(tmp)


@case
def checkpoint_keep():
    """-checkpoint_keep 2 keeps the two newest checkpoints as c.chk.<step> beside c.chk (the
    newest); a restart from the older one ends in the uninterrupted run's state."""
    tmp = tempfile.mkdtemp()
    f = lambda name: os.path.join(tmp, name)
    dyn = [APP] + CUBE + ["-dt", 0.1, "-time_scheme", "bdf2"]
    run(dyn + ["-t_final", 0.5, "-report", f("full.json")])
    run(dyn + ["-t_final", 0.4, "-checkpoint", f("c.chk"), "-checkpoint_every", 1, "-checkpoint_keep", 2])
    assert sorted(os.listdir(tmp)) == ["c.chk", "c.chk.3", "c.chk.4", "full.json"], os.listdir(tmp)
    assert open(f("c.chk"), "rb").read() == open(f("c.chk.4"), "rb").read()
    out = run(dyn + ["-t_final", 0.5, "-restart", f("c.chk.3"), "-report", f("resumed.json")])
    assert "restart from" in out and "step 3 t" in out, out
    full, resumed = report(f("full.json")), report(f("resumed.json"))
    assert [s["step"] for s in resumed["steps"]] == [4, 5], resumed["steps"]
    for key in ("max_displacement", "displacement_norm"):
        assert abs(full["results"][key] - resumed["results"][key]) <= 1e-12 * abs(full["results"][key]), key
    shutil.rmtree(tmp)


@case
def checkpoint_header_tampered():
    """A checkpoint whose stored time, or a stored option's value, was changed (the size kept)
    is refused as damaged (it was accepted: the header was outside the checksum)."""
    tmp = tempfile.mkdtemp()
    chk = os.path.join(tmp, "c.chk")
    dyn = [APP] + CUBE + ["-dt", 0.1]
    run(dyn + ["-t_final", 0.2, "-checkpoint", chk])
    data = open(chk, "rb").read()
    time = bytearray(data)
    time[8 * 4 + 3] ^= 0x01  # the stored time t: the first real after the eight integers of the header
    open(os.path.join(tmp, "time.chk"), "wb").write(time)
    k = data.index(b"-structure_density 1\n")
    option = data[:k] + b"-structure_density 2\n" + data[k + len(b"-structure_density 1\n"):]
    open(os.path.join(tmp, "option.chk"), "wb").write(option)
    for name, extra in (("time.chk", []), ("option.chk", ["-structure_density", 2])):
        path = os.path.join(tmp, name)
        refused(dyn + ["-t_final", 0.4, "-restart", path] + extra, f"-restart {path}: its header (step, time, step size or options) does not match its checksum")
    shutil.rmtree(tmp)


@case
def misspelled_options():
    """An option that is no option of fsi_app but starts with a block's prefix, or is a letter
    or two from one, stops the run naming the closest (the run used to solve nothing, exit 0);
    so does one in an options file."""
    tmp = tempfile.mkdtemp()
    for extra, msg in ((["-structure_presure", 1], "-structure_presure: no such option; did you mean -structure_pressure?"),
                       (["-t_finl", 1], "-t_finl: no such option; did you mean -t_final?"),
                       (["-fluid_inlet_presure", 1], "-fluid_inlet_presure: no such option; did you mean -fluid_inlet_pressure?")):
        refused([APP] + FSI_SCENE + extra, msg, np=2)
    typo = os.path.join(tmp, "typo.opts")
    open(typo, "w").write("-options_file " + os.path.join(SCENES, "wall_tube1_static.opts") + "\n-structure_nuu 0.4\n")
    refused([APP, "-options_file", typo], "-structure_nuu: no such option; did you mean -structure_nu?")
    shutil.rmtree(tmp)


@case
def numbers_without_values():
    """A number given without its value, or an integer past what a PetscInt holds, is refused
    (-dt alone kept dt = 0 and solved statics; 4294967297 load steps wrapped to 1)."""
    refused([APP] + WALL_SCENE + ["-dt"], "-dt: give a value (a number, >= 0)")
    refused([APP] + WALL_SCENE + ["-structure_subdomains"], "-structure_subdomains: give a value (an integer, >= 1)")
    refused([APP] + WALL_SCENE + ["-structure_load_steps", 4294967297], "-structure_load_steps: value must be at most 2147483647 in size (got 4294967297)")
    refused([APP] + WALL_SCENE + ["-structure_load_steps", "2.5"], "-structure_load_steps: value must be an integer (got 2.5)")
    out = run([APP] + WALL_SCENE + ["-structure_load_steps", "2e0"])
    assert "load step 2/2" in out, out[-1500:]


@case
def mesh_not_a_file():
    """A mesh that is a FIFO (the run hung), a device (/dev/zero: memory grew without bound) or a
    file whose $Nodes header announces more nodes than it can hold: a sentence, quickly."""
    tmp = tempfile.mkdtemp()
    fifo = os.path.join(tmp, "fifo.msh")
    os.mkfifo(fifo)
    for mesh in (fifo, "/dev/zero"):
        refused([APP] + WALL_SCENE + ["-mesh", mesh], f"-mesh {mesh}: not a regular file; give a gmsh .msh file", 2)
    huge = os.path.join(tmp, "huge.msh")
    text = open(os.path.join(MESHES, "cube_L0.msh")).read()
    header = text[text.index("$Nodes\n") + 7:].split("\n")[0].split()
    text = text.replace("$Nodes\n" + " ".join(header), f"$Nodes\n{header[0]} 1000000000000 1 2000000000", 1)
    open(huge, "w").write(text)
    refused([APP] + CUBE + ["-mesh", huge], f"the $Nodes header announces 1000000000000 nodes, more than a file of {len(text)} bytes can hold")
    shutil.rmtree(tmp)


@case
def inflow_on_coupled_wall():
    """-fluid_inflow_velocity on the coupled tube: the inlet's rim nodes lie on the wall and move
    with it (u = d_t d_s, the coupling's row), so the interface velocity jump is round-off (it was
    the imposed 10 cm/s, without a word), and the volume balance holds; the inlet flux's sign is
    explained where it is printed."""
    tmp = tempfile.mkdtemp()
    r = os.path.join(tmp, "r.json")
    out = run([APP] + FSI_SCENE + ["-t_final", 1e-3, "-fluid_inlet_pressure", 0, "-structure_pressure", 0, "-fluid_inflow_velocity", "0,0,10", "-report", r], 2)
    res = report(r)["results"]
    print(res)
    assert res["interface_velocity_jump"] < 1e-12 and res["volume_balance"] < 1e-12 * res["max_inflow"], res
    # the inlet's flux is negative: the summary says why (it did not)
    assert res["inlet_flux"] < 0 and "(int u.n with the outward normal: an inflow is negative)" in out, out[-1500:]
    shutil.rmtree(tmp)


@case
def centerline_bad():
    """A centreline file for the fibres' frame that is missing, has a branch of one point, a
    number that is not finite, a point repeated (a segment of length 0), a branch turning back on
    itself, or runs through the wall rather than the lumen; or a centreline for a law without
    fibres: one sentence naming the option, the file (and line), on 2 ranks, before the first
    step."""
    tmp = tempfile.mkdtemp()
    files = {"one.dat": "0 0 0\n", "nan.dat": "0 0 0\n0 0 nan\n", "repeat.dat": "0 0 0\n0 0 0\n0 0 1\n", "back.dat": "0 0 0\n0 0 1\n0 0 0.5\n",
             "wall.dat": "0.18 0 0\n0.18 0 2.5\n", "axis.dat": "0 0 0\n0 0 2.5\n"}
    for name, text in files.items():
        open(os.path.join(tmp, name), "w").write(text)
    f = lambda name: os.path.join(tmp, name)  # noqa: E731
    base = [APP, "-mesh", os.path.join(MESHES, "tube1_L0.msh"), "-structure_region", "wall", "-structure_clamp", "wall_inlet_ring,wall_outlet_ring", "-structure_pressure", 1330]
    arterial = ["-structure_material", "arterial"]
    for opts, msg in ((arterial + ["-structure_centerline", f("missing.dat")], f"-structure_centerline {f('missing.dat')}: no such file"),
                      (arterial + ["-structure_centerline", f("one.dat")], f"-structure_centerline {f('one.dat')}: branch 1 has fewer than 2 points"),
                      (arterial + ["-structure_centerline", f("nan.dat")], f"-structure_centerline {f('nan.dat')} line 2: '0 0 nan' is not three finite numbers"),
                      (arterial + ["-structure_centerline", f("repeat.dat")], f"-structure_centerline {f('repeat.dat')} line 2: the point repeats the previous one"),
                      (arterial + ["-structure_centerline", f("back.dat")], f"-structure_centerline {f('back.dat')}: the centreline turns back on itself at point 2"),
                      (arterial + ["-structure_centerline", f("wall.dat")], f"-structure_centerline {f('wall.dat')}: the centreline passes through the wall"),
                      (["-structure_centerline", f("axis.dat")], f"-structure_centerline {f('axis.dat')}: only the arterial law (-structure_material arterial) has fibres")):
        refused(base + opts, msg, np=2)
    shutil.rmtree(tmp)


@case
def outlets_bad():
    """The outlets' 0D models: R, C, R_d <= 0 or not finite, two conditions on one outlet, an
    outlet that is also the inlet or a group of the wall, an outlet named twice, a model for a
    group that is no outlet, models without the outlets block or the block without a model, a
    backflow coefficient outside [0, 1]: one sentence naming the option, before the first step."""
    base = [APP, "-mesh", os.path.join(MESHES, "split_tube_L0.msh"), "-blocks", "fluid,outlets", "-fluid_region", "fluid", "-fluid_noslip", "interface",
            "-fluid_inlet", "inlet", "-fluid_outlet", "outlet_a,outlet_b", "-fluid_inlet_pressure", 100, "-dt", 0.01]
    for opts, msg in ((["-outlets_outlet_a_resistance", 0], "-outlets_outlet_a_resistance: give R > 0 (and optionally P_d): R,P_d"),
                      (["-outlets_outlet_a_resistance", "nan"], "-outlets_outlet_a_resistance: value must be a finite number (got nan)"),
                      (["-outlets_outlet_b_rcr", "100,0,10"], "-outlets_outlet_b_rcr: give R_p >= 0, C > 0 and R_d > 0"),
                      (["-outlets_outlet_b_rcr", "100,1e-4,-10"], "-outlets_outlet_b_rcr: give R_p >= 0, C > 0 and R_d > 0"),
                      (["-outlets_outlet_a_rcr", "100,1e-4,10", "-outlets_outlet_a_resistance", 5], "-outlets_outlet_a_*: one condition per outlet"),
                      (["-outlets_outlet_a_pressure_fourier", "0.1,5", "-outlets_outlet_a_resistance", 5], "-outlets_outlet_a_*: one condition per outlet"),
                      (["-outlets_outlet_a_pressure_waveform", "missing.dat"], "-outlets_outlet_a_pressure_waveform missing.dat: no such file"),
                      (["-outlets_outlet_a_pressure_fourier", "0.1,5", "-dt", 0], "-outlets_outlet_a_pressure_fourier: the outlet pressure is a function of time: give a time step (-dt)"),
                      (["-outlets_outlet_a_resistance", 10, "-fluid_inlet_pressure", 0, "-fluid_inflow_waveform", "missing.dat"], "-fluid_inflow_waveform missing.dat: no such file"),
                      (["-fluid_outlet", "inlet", "-outlets_inlet_resistance", 10], "-fluid_outlet inlet: the outlet with a 0D model is also the inlet (-fluid_inlet)"),
                      (["-fluid_outlet", "wall_outlet_ring", "-outlets_wall_outlet_ring_resistance", 10], "-fluid_outlet wall_outlet_ring: no face of the group bounds a cell of -fluid_region fluid"),
                      (["-fluid_outlet", "outlet_a,outlet_a", "-outlets_outlet_a_resistance", 10], "-fluid_outlet outlet_a,outlet_a: the group outlet_a is named twice"),
                      (["-outlets_outlet_a_resistance", 10, "-outlets_outlet_c_resistance", 10], "-outlets_outlet_c_resistance: no such option"),
                      (["-blocks", "fluid", "-outlets_outlet_a_resistance", 10], "-outlets_outlet_a_resistance: the 0D outlet models are the outlets block's; add outlets to -blocks"),
                      ([], "-blocks ...,outlets: no outlet of -fluid_outlet outlet_a,outlet_b has a model"),
                      (["-blocks", "outlets", "-outlets_outlet_a_resistance", 10], "-blocks: the outlets block models the vessels beyond the fluid's outlets; name fluid too"),
                      (["-outlets_outlet_a_resistance", 10, "-fluid_backflow_stabilization", 1.5], "-fluid_backflow_stabilization: value must be in [0, 1] (got 1.5)")):
        refused(base + opts, msg, np=2)


@case
def waveform_bad():
    """A waveform file missing, empty, with one sample, times that do not increase, a NaN, a
    line of three numbers, a last value that does not repeat the first; a Fourier series without
    coefficients or with T <= 0; a waveform with another inlet condition, or in statics: one
    sentence naming the option and the file (and line), before the mesh is read."""
    tmp = tempfile.mkdtemp()
    f = lambda name: os.path.join(tmp, name)
    base = [APP, "-options_file", os.path.join(SCENES, "fluid_tube1_pulse.opts"), "-fluid_inlet_pressure", 0]
    files = {"empty.dat": "# nothing\n", "one.dat": "0 1\n", "back.dat": "0 1\n0.5 2\n0.4 3\n1 1\n", "nan.dat": "0 1\n0.5 nan\n0.7 2\n1 1\n",
             "three.dat": "0 1 2\n", "open.dat": "0 1\n0.3 2\n0.6 3\n1 4\n", "good.dat": "0 1\n0.3 2\n0.6 3\n1 1\n"}
    for name, text in files.items():
        open(f(name), "w").write(text)
    option = "-fluid_inlet_pressure_waveform"
    for name, msg in (("missing.dat", "no such file"), ("empty.dat", "0 samples; give at least 4"), ("one.dat", "1 samples; give at least 4"),
                      ("back.dat", "line 3: the time 0.4 does not follow the previous one: the times must increase"),
                      ("nan.dat", "line 2: '0.5 nan': the time and the value must be finite"), ("three.dat", "line 1: give two numbers, the time and the value"),
                      ("open.dat", "the last sample's value differs from the first's")):
        out = refused(base + [option, f(name)], msg, np=2)
        assert f"{option} {f(name)}" in out, out[-2000:]
    refused(base + ["-fluid_inlet_pressure_fourier", "0.01"], "-fluid_inlet_pressure_fourier: give the period and the coefficients, T,a0,a1,b1,a2,b2,... (got 1 values)")
    refused(base + ["-fluid_inlet_pressure_fourier", "0,1"], "-fluid_inlet_pressure_fourier: the period T (the first value) must be positive (got 0)")
    refused(base + [option, f("good.dat"), "-fluid_inlet_pressure", 100], f"{option}: the inlet cannot also take")
    refused(base + [option, f("good.dat"), "-fluid_inlet_pressure_fourier", "1,2"], f"{option}: the inlet cannot also take")
    refused(base + [option, f("good.dat"), "-dt", 0], f"{option}: the inlet pressure is a function of time: give a time step (-dt)")
    shutil.rmtree(tmp)


@case
def report_norms():
    """The report's displacement_norm is the 2-norm of the wall's displacement alone (it was the
    whole solution's, pressure included): on the coupled tube it lies between the largest
    nodal value and sqrt(structure unknowns) times it."""
    tmp = tempfile.mkdtemp()
    r = os.path.join(tmp, "r.json")
    run([APP] + FSI_SCENE + ["-t_final", 5e-4, "-report", r], 2)
    rep = report(r)
    dmax, norm, n = rep["results"]["max_displacement"], rep["results"]["displacement_norm"], rep["unknowns"]["structure"]
    print("max", dmax, "norm", norm, "unknowns", n)
    assert 0 < dmax <= norm <= n ** 0.5 * dmax, (dmax, norm, n)
    shutil.rmtree(tmp)


@case
def new_user_output():
    """A one-step run prints its step line; -help with a scene lists every option with all its
    values, units and range, then stops without solving (it ran the whole simulation)."""
    out = run([APP] + CUBE + ["-dt", 0.1, "-t_final", 0.1])
    assert re.search(r"^step 1/1 t 1\.0000e-01 newton 1 ", out, re.M), out[-1500:]
    out = run([APP] + FSI_SCENE + ["-help"], 2)
    assert "nothing was solved" in out and not re.search(r"^step 1/", out, re.M), out[-1500:]
    for line in (r"  -structure_arterial <175000,4.998e\+06,2.4,3.00019e\+08,5.1>: ",
                 r"  -structure_E <400000>: Young's modulus \(linear elastic; dyn/cm\^2\) \(a number, positive; default 1\)",
                 r"  -dt <0.0005>: time step \(s\); 0 solves the static problem \(a number, >= 0; default 0\)",
                 r"  -time_scheme <backward_euler>: .* \(one of: backward_euler, bdf2\)"):
        assert re.search(line, out), line
    ours = [l for l in out.splitlines() if re.match(r"  -(structure|fluid|geometry|mesh|dt|t_final|blocks|output|checkpoint)\S* <", l)]
    assert len(ours) >= 40 and not [l for l in ours if l.endswith("(None)")], ours[:5]


if __name__ == "__main__":
    main("fsi_input")
