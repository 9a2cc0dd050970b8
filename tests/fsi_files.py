#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""ctest cases for fsi_app: what a run writes and reads back: restart = uninterrupted run, the run
report, XDMF output as ParaView reads it, output paths and locks, damaged checkpoints. Each case
runs fsi_app and asserts numbers of its run report (tests/fsilib.py) against references
independent of the code."""
import socket
import stat

from fsilib import *  # noqa: F401,F403 (the cases' shared runners, meshes and scenes)
from testlib import between, case, main, run


@case
def structure_restart():
    """A Neo-Hooke cube in motion (BDF2): a run stopped after 4 of 6 steps and restarted from
    its checkpoint ends in the same state as the uninterrupted run (same Newton and Krylov
    counts in the last steps, displacement equal to round-off), and its XDMF series holds all 7
    frames; a restart on another number of ranks, or from a missing file, stops with a
    sentence saying why."""
    tmp = tempfile.mkdtemp()
    f = lambda name: os.path.join(tmp, name)
    base = CUBE_DYNAMIC + ["-structure_material", "neohooke", "-structure_pressure", 2e4, "-time_scheme", "bdf2", "-dt", 0.05]
    run([APP] + base + ["-t_final", 0.3, "-report", f("full.json")])
    run([APP] + base + ["-t_final", 0.2, "-checkpoint", f("c.chk"), "-checkpoint_every", 2, "-output", f("o.xdmf")])
    out = run([APP] + base + ["-t_final", 0.3, "-restart", f("c.chk"), "-output", f("o.xdmf"), "-report", f("resumed.json")])
    assert "restart from" in out and "step 4 t 2.0000e-01" in out, out
    full, resumed = report(f("full.json")), report(f("resumed.json"))
    assert resumed["restarted_at_step"] == 4 and [s["step"] for s in resumed["steps"]] == [5, 6], resumed
    for a, b in zip(full["steps"][4:], resumed["steps"]):
        assert (a["newton"], a["krylov"]) == (b["newton"], b["krylov"]), (a, b)
    for key in ("max_displacement", "displacement_norm"):
        between(abs(full["results"][key] - resumed["results"][key]) / full["results"][key], 0, 1e-12, f"restarted / uninterrupted {key}")
    frames = re.findall(r"/fields/displacement_\d+", subprocess_out(["h5ls", "-r", f("o.h5")]))
    assert len(frames) == 7 and open(f("o.xdmf")).read().count("<Time ") == 7, frames
    out = run([APP] + base + ["-t_final", 0.3, "-restart", f("c.chk")], np=2, fail=True)
    assert "written by 1 ranks; restart on as many (mpiexec -n 1)" in out
    shutil.rmtree(tmp)


@case
def run_report():
    """The run report's seconds and memory (-report), one rank: the phases are present, positive
    and bounded by the time loop's wall time (check_seconds) for the wall with gdsw (one PC: the
    three phases sum to at most the total) and for the fluid with the Schur fieldsplit, whose
    steps' phases add up to the run's (check_step_seconds); the peak
    resident memory exceeds the assembled operator's AIJ storage (12 bytes per nonzero: a value
    and a 32-bit column index; the nonzeros from -ksp_view; measured 14 times as much)."""
    tmp = tempfile.mkdtemp()
    out = run([APP, "-mesh", os.path.join(MESHES, "tube1_L0.msh"), "-structure_pressure", 1330, "-structure_E", 4e5, "-structure_nu", 0.3] + WALL +
              ["-pc_type", "gdsw", "-structure_subdomains", 4, "-ksp_view", "-report", os.path.join(tmp, "wall.json")])
    wall = report(os.path.join(tmp, "wall.json"))
    check_seconds(wall, "wall, gdsw", split=False)
    n = sum(wall["unknowns"].values())
    nonzeros = int(re.findall(rf"rows={n}, cols={n}(?:, bs=\d+)?\s+total: nonzeros=(\d+)", out)[-1])
    between(wall["peak_memory_mib"] * 2**20 / (12 * nonzeros), 1, 1e4, f"peak memory / AIJ storage of the operator ({nonzeros} nonzeros)")
    run([APP, "-options_file", os.path.join(MESHES, "..", "scenes", "fluid_tube1_pulse.opts"), "-mesh", os.path.join(MESHES, "tube1_L0.msh"),
         "-t_final", 1e-3, "-report", os.path.join(tmp, "fluid.json")])
    fluid = report(os.path.join(tmp, "fluid.json"))
    check_seconds(fluid, "fluid, Schur fieldsplit", split=True)
    check_step_seconds(fluid, "fluid, Schur fieldsplit")
    shutil.rmtree(tmp)


@case
def structure_output():
    """XDMF + HDF5 output of the pulsed wall on 2 ranks: one mesh (4240 P2 nodes, 2089
    quadratic tetrahedra), one dataset per frame; ParaView (pvbatch) reads the series with the
    same counts and renders the last frame to a PNG."""
    tmp = tempfile.mkdtemp()
    xdmf = os.path.join(tmp, "wall.xdmf")
    run([APP, "-options_file", os.path.join(MESHES, "..", "scenes", "wall_tube1_pulse.opts"), "-mesh", os.path.join(MESHES, "tube1_L0.msh"),
         "-structure_material", "linear", "-structure_E", 4e5, "-t_final", 1.5e-3, "-output", xdmf], np=2)
    listing = subprocess_out(["h5ls", "-r", os.path.join(tmp, "wall.h5")])
    assert "/mesh/topology           Dataset {2089, 10}" in listing and "/mesh/coordinates        Dataset {4240, 3}" in listing, listing
    assert len(re.findall(r"/fields/displacement_\d+ +Dataset \{4240, 3\}", listing)) == 4, listing
    png = os.path.join(tmp, "wall.png")
    seen = paraview_reads(xdmf, png, 50)
    assert (seen["frames"], seen["points"], seen["cells"]) == (4, 4240, 2089), seen
    between(seen["displacement_max"], 5e-4, 5e-3, "largest displacement ParaView read (cm)")
    assert os.path.getsize(png) > 10000
    shutil.rmtree(tmp)


@case
def fluid_ale_restart():
    """The unsteady manufactured flow on the moving mesh (BDF2, 6 steps), stopped after 4 and
    restarted from its checkpoint (velocity, pressure, mesh displacement and their past states):
    the same Newton and Krylov counts in the last two steps and the same final state (largest
    velocity, largest mesh displacement, velocity error) to round-off."""
    tmp = tempfile.mkdtemp()
    f = lambda name: os.path.join(tmp, name)
    base = [APP] + ALE_CUBE + ["-dt", 1 / 6, "-geometry_ramp", 1, "-mms_ramp", 1]
    run(base + ["-t_final", 1, "-report", f("full.json")])
    run(base + ["-t_final", 4 / 6, "-checkpoint", f("c.chk"), "-checkpoint_every", 4])
    run(base + ["-t_final", 1, "-restart", f("c.chk"), "-report", f("resumed.json")])
    full, resumed = report(f("full.json")), report(f("resumed.json"))
    assert resumed["restarted_at_step"] == 4 and [s["step"] for s in resumed["steps"]] == [5, 6], resumed
    for a, b in zip(full["steps"][4:], resumed["steps"]):
        assert (a["newton"], a["krylov"]) == (b["newton"], b["krylov"]), (a, b)
    for key in ("max_velocity", "max_mesh_displacement", "l2_error"):
        between(abs(full["results"][key] - resumed["results"][key]) / full["results"][key], 0, 1e-10, f"restarted / uninterrupted {key}")
    shutil.rmtree(tmp)


@case
def fsi_restart_output():
    """A coupled run stopped after 2 of 3 steps and restarted ends in the uninterrupted run's
    state; the XDMF series holds the fluid (velocity, pressure, mesh displacement) and the wall
    (displacement) as two parts of each frame, and each part is also a series of its own that
    ParaView reads as one dataset (1894 and 4240 nodes, all 4 frames)."""
    tmp = tempfile.mkdtemp()
    f = lambda name: os.path.join(tmp, name)
    full = fsi("-t_final", 1.5e-3)
    fsi("-t_final", 1e-3, "-checkpoint", f("c.chk"), "-checkpoint_every", 2, "-output", f("o.xdmf"))
    resumed = fsi("-t_final", 1.5e-3, "-restart", f("c.chk"), "-output", f("o.xdmf"))
    assert resumed["restarted_at_step"] == 2, resumed["restarted_at_step"]
    for key in ("max_displacement", "displacement_norm", "velocity_l2_norm", "pressure_l2_norm"):
        between(abs(full["results"][key] - resumed["results"][key]) / full["results"][key], 0, 1e-10, f"restarted / uninterrupted {key}")
    listing = subprocess_out(["h5ls", "-r", f("o.h5")])
    for dataset in ("/fluid/mesh/topology", "/wall/mesh/topology", "/fluid/fields/velocity_3", "/fluid/fields/pressure_3", "/fluid/fields/displacement_3", "/wall/fields/displacement_3"):
        assert dataset in listing, (dataset, listing)
    xdmf = open(f("o.xdmf")).read()
    assert xdmf.count('CollectionType="Spatial"') == 4 and xdmf.count("<Time ") == 4 * 3, xdmf[:2000]
    # each part alone, as ParaView opens it: a dataset of its own (the spatial collection's parts
    # are pieces of one dataset to ParaView's reader, the wall and the fluid merged)
    for part, points, cells in (("fluid", 1894, 909), ("wall", 4240, 2089)):
        seen = paraview_reads(f(f"o_{part}.xdmf"), f(f"{part}.png"))
        assert (seen["frames"], seen["points"], seen["cells"]) == (4, points, cells), (part, seen)
    shutil.rmtree(tmp)


@case
def output_paths_bad():
    """-output, -report and -checkpoint where they cannot be written stop before the mesh is read,
    naming the option and the path (the output used to fail after pages of HDF5 diagnostics,
    the report after the whole run)."""
    tmp = tempfile.mkdtemp()
    missing, afile = os.path.join(tmp, "missing"), os.path.join(tmp, "afile")
    open(afile, "w").close()
    cube = ["-mesh", os.path.join(MESHES, "cube_L0.msh"), "-structure_clamp", "x0", "-dt", 0.1, "-t_final", 0.2]
    for opt, path, why in (("-output", os.path.join(missing, "o.xdmf"), f"the directory {missing} does not exist"),
                           ("-report", os.path.join(missing, "r.json"), f"the directory {missing} does not exist"),
                           ("-checkpoint", os.path.join(afile, "c.chk"), f"{afile} is not a directory"),
                           ("-report", tmp, "it is a directory")):
        for np in (1, 2):
            out = refused([APP] + cube + [opt, path], f"{opt} {path}: the run cannot write this file ({why})", np)
            assert "unknowns:" not in out
    assert os.listdir(tmp) == ["afile"], os.listdir(tmp)
    shutil.rmtree(tmp)


@case
def output_faults():
    """Output that would be lost or would destroy something stops the run with a sentence: a
    checkpoint named after a FIFO (it was replaced by a regular file), a report on a full disk
    (/dev/full: lost with exit 0), a series another live run is writing (its files were
    destroyed); a lock left by a run that has ended is taken over, and a finished run leaves none."""
    tmp = tempfile.mkdtemp()
    base = [APP, "-mesh", os.path.join(MESHES, "cube_L0.msh"), "-structure_clamp", "x0", "-structure_pressure_group", "x1", "-structure_pressure", 0.01,
            "-ksp_type", "preonly", "-pc_type", "lu"]
    fifo = os.path.join(tmp, "fifo")
    os.mkfifo(fifo)
    refused(base + ["-checkpoint", fifo], f"-checkpoint {fifo}: the run cannot write this file (it is not a regular file but a device, FIFO or socket, which the run would replace)", 2)
    assert stat.S_ISFIFO(os.stat(fifo).st_mode)
    out = run(base + ["-report", "/dev/full"], 2, fail=True)
    assert out.count("-report /dev/full: writing it failed (No space left on device); the file is incomplete") == 1, out[-2000:]
    series, h5 = os.path.join(tmp, "s.xdmf"), os.path.join(tmp, "s.h5")
    open(h5, "w").write("the other run's data")
    open(series + ".lock", "w").write(f"{socket.gethostname()} {os.getpid()}\n")  # this test's process: alive
    refused(base + ["-output", series], f"-output {series}: another run (process {os.getpid()}) is writing it", 2)
    assert open(h5).read() == "the other run's data"
    ended = subprocess.Popen(["true"])
    ended.wait()
    open(series + ".lock", "w").write(f"{socket.gethostname()} {ended.pid}\n")
    run(base + ["-output", series], 2)
    assert not os.path.exists(series + ".lock") and os.path.getsize(h5) > 100
    shutil.rmtree(tmp)


@case
def restart_bad():
    """A restart from a truncated checkpoint, from a file that is not one, and with other
    boundary conditions (the same number of unknowns), another modulus or another numbering of
    the mesh's points (-mesh_reorder): a sentence naming
    the file and what differs; the same problem with other solver options restarts. A run that
    ends at or before the checkpoint's step, a checkpoint with one byte changed (its size
    intact), and a mesh file whose nodes moved under the same name: a sentence each."""
    tmp = tempfile.mkdtemp()
    chk, half = os.path.join(tmp, "c.chk"), os.path.join(tmp, "half.chk")
    base = ["-mesh", os.path.join(MESHES, "cube_L0.msh"), "-structure_pressure_group", "x1", "-structure_pressure", 0.01, "-structure_density", 1,
            "-dt", 0.1, "-ksp_type", "preonly", "-pc_type", "lu"]
    run([APP] + base + ["-structure_clamp", "x0", "-t_final", 0.2, "-checkpoint", chk])
    size = os.path.getsize(chk)
    open(half, "wb").write(open(chk, "rb").read()[:size // 2])
    resume = [APP] + base + ["-t_final", 0.4]
    for np in (1, 2):
        refused(resume + ["-structure_clamp", "x0", "-restart", half], f"-restart {half}: {size // 2} bytes where its header announces {size}: the file is truncated", np)
    mesh = os.path.join(MESHES, "cube_L0.msh")
    refused(resume + ["-structure_clamp", "x0", "-restart", mesh], f"-restart {mesh}: not an fsi_app checkpoint")
    refused(resume + ["-structure_clamp", "y0", "-restart", chk], f"-restart {chk}: written with -structure_clamp x0, this run has -structure_clamp y0")
    refused(resume + ["-structure_clamp", "x0", "-structure_E", 2, "-restart", chk], f"-restart {chk}: written with -structure_E 1, this run has -structure_E 2")
    # another numbering of the points would read the stored states in the wrong order
    refused(resume + ["-structure_clamp", "x0", "-mesh_reorder", "false", "-restart", chk], f"-restart {chk}: written with -mesh_reorder true, this run has -mesh_reorder false")
    out = run(resume + ["-structure_clamp", "x0", "-restart", chk, "-ksp_type", "cg", "-pc_type", "jacobi", "-ksp_rtol", 1e-10])
    assert "restart from" in out and "step 4/4" in out, out
    # a run that would end where the checkpoint is, or before (exit 0 with nothing done, before)
    for t_final, steps in ((0.2, 2), (0.1, 1)):
        refused([APP] + base + ["-structure_clamp", "x0", "-t_final", t_final, "-restart", chk],
                f"-restart {chk}: the checkpoint is at step 2 (t 0.2) and this run ends at step {steps}: nothing is left to do; give a -t_final beyond it")
    # one byte changed in the last stored state, the size unchanged (blamed on Newton, before)
    damaged = os.path.join(tmp, "damaged.chk")
    data = bytearray(open(chk, "rb").read())
    data[-20] ^= 0x40
    open(damaged, "wb").write(data)
    refused(resume + ["-structure_clamp", "x0", "-restart", damaged], f"-restart {damaged}: a past state stored in it does not match its checksum: the file was damaged after it was written")
    # the mesh file changed under the same name: its nodes moved, the unknowns the same (accepted, before)
    moved = os.path.join(tmp, "cube.msh")
    shutil.copy(mesh, moved)
    on_moved = [APP] + [moved if a == mesh else a for a in base] + ["-structure_clamp", "x0"]
    run(on_moved + ["-t_final", 0.2, "-checkpoint", chk])
    lines, inside = open(moved).read().split("\n"), False
    for k, line in enumerate(lines):
        inside = (inside or line == "$Nodes") and line != "$EndNodes"
        if inside and len(line.split()) == 3:  # a node's x y z
            x, y, z = line.split()
            lines[k] = f"{1.5 * float(x):.17g} {y} {z}"
    open(moved, "w").write("\n".join(lines))
    refused(on_moved + ["-t_final", 0.4, "-restart", chk], f"-restart {chk}: the mesh file {moved} has changed since the checkpoint was written (its contents differ)")
    shutil.rmtree(tmp)


if __name__ == "__main__":
    main("fsi_files")
