#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""ctest cases for fsi_app's handling of mistakes: options, options files, file names, meshes
and checkpoints that a run must refuse with one sentence (naming the option, file or cause),
a nonzero exit status and nothing lost; and what a new user meets on the way (-help, a scene
run from another folder, a one-step run)."""
import json
import os
import re
import shutil
import socket
import subprocess
import tempfile

from testlib import BUILD, ENV, TOP, case, main, run

MESHES = os.path.join(TOP, "meshes")
SCENES = os.path.join(TOP, "scenes")
APP = os.path.join(BUILD, "fsi_app", "fsi_app")
WALL = ["-options_file", os.path.join(SCENES, "wall_tube1_static.opts")]
FSI = ["-options_file", os.path.join(SCENES, "fsi_tube1_linear.opts")]
CUBE = ["-mesh", os.path.join(MESHES, "cube_L0.msh"), "-structure_clamp", "x0", "-structure_pressure_group", "x1", "-structure_pressure", 0.01,
        "-structure_density", 1, "-ksp_type", "preonly", "-pc_type", "lu"]


def refused(cmd, msg, np=1, cwd=TOP):
    """Run cmd, which must fail with msg, printed once (by rank 0 for all ranks), without a
    signal and before any step."""
    full = ["mpiexec", "-n", str(np)] + [str(c) for c in cmd]
    p = subprocess.run(full, env=ENV, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=300, cwd=cwd)
    out = p.stdout
    print("$", " ".join(full), "\n" + out[-3000:])
    assert p.returncode != 0, "exit status 0"
    assert out.count(msg) == 1, (msg, out[-3000:])
    assert not re.search(r"^\[[1-9]\d*\]PETSC ERROR", out, re.M) and "Caught signal" not in out, out[-3000:]
    assert not re.search(r"^(load )?step 1/", out, re.M), "a step was solved"
    return out


def report(path):
    with open(path) as f:
        return json.load(f)


@case
def empty_group_names():
    """An option that names a group of faces given an empty value, or no value at all, is
    refused with its name (it segfaulted)."""
    for extra, option in ((["-structure_pressure_group", ""], "-structure_pressure_group"), (["-structure_clamp", "wall_inlet_ring", "-structure_pressure_group"], "-structure_pressure_group")):
        refused([APP] + WALL + extra, f"{option}: the value is empty; name a physical group of faces of")
    for extra, option in ((["-fluid_inlet", ""], "-fluid_inlet"), (["-geometry_interface", ""], "-geometry_interface"), (["-geometry_interface"], "-geometry_interface")):
        refused([APP] + FSI + extra, f"{option}: the value is empty; name a physical group of faces of", np=2)
    refused([APP] + FSI + ["-fluid_region", ""], "-fluid_region: name the fluid's group (the wall's cells are not the fluid's)", np=2)


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
    wall = WALL + ["-mesh", mesh]
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
    time[7 * 4 + 3] ^= 0x01  # the stored time t: the first real after the seven integers of the header
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
        refused([APP] + FSI + extra, msg, np=2)
    typo = os.path.join(tmp, "typo.opts")
    open(typo, "w").write("-options_file " + os.path.join(SCENES, "wall_tube1_static.opts") + "\n-structure_nuu 0.4\n")
    refused([APP, "-options_file", typo], "-structure_nuu: no such option; did you mean -structure_nu?")
    shutil.rmtree(tmp)


@case
def numbers_without_values():
    """A number given without its value, or an integer past what a PetscInt holds, is refused
    (-dt alone kept dt = 0 and solved statics; 4294967297 load steps wrapped to 1)."""
    refused([APP] + WALL + ["-dt"], "-dt: give a value (a number, >= 0)")
    refused([APP] + WALL + ["-structure_subdomains"], "-structure_subdomains: give a value (an integer, >= 1)")
    refused([APP] + WALL + ["-structure_load_steps", 4294967297], "-structure_load_steps: value must be at most 2147483647 in size (got 4294967297)")
    refused([APP] + WALL + ["-structure_load_steps", "2.5"], "-structure_load_steps: value must be an integer (got 2.5)")
    out = run([APP] + WALL + ["-structure_load_steps", "2e0"])
    assert "load step 2/2" in out, out[-1500:]


@case
def mesh_not_a_file():
    """A mesh that is a FIFO (the run hung), a device (/dev/zero: memory grew without bound) or a
    file whose $Nodes header announces more nodes than it can hold: a sentence, quickly."""
    tmp = tempfile.mkdtemp()
    fifo = os.path.join(tmp, "fifo.msh")
    os.mkfifo(fifo)
    for mesh in (fifo, "/dev/zero"):
        refused([APP] + WALL + ["-mesh", mesh], f"-mesh {mesh}: not a regular file; give a gmsh .msh file", 2)
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
    the imposed 10 cm/s, without a word), and the volume balance holds."""
    tmp = tempfile.mkdtemp()
    r = os.path.join(tmp, "r.json")
    run([APP] + FSI + ["-t_final", 1e-3, "-fluid_inlet_pressure", 0, "-structure_pressure", 0, "-fluid_inflow_velocity", "0,0,10", "-report", r], 2)
    res = report(r)["results"]
    print(res)
    assert res["interface_velocity_jump"] < 1e-12 and res["volume_balance"] < 1e-12 * res["max_inflow"], res
    shutil.rmtree(tmp)


@case
def report_norms():
    """The report's displacement_norm is the 2-norm of the wall's displacement alone (it was the
    whole solution's, pressure included): on the coupled tube it lies between the largest
    nodal value and sqrt(structure unknowns) times it."""
    tmp = tempfile.mkdtemp()
    r = os.path.join(tmp, "r.json")
    run([APP] + FSI + ["-t_final", 5e-4, "-report", r], 2)
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
    out = run([APP] + FSI + ["-help"], 2)
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
