#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""ctest cases for pc_gdsw as its users meet it: messages on bad input and bad options, -help and
-ksp_view, the API's setters and getters, the installed library, petsc4py. The numerics are in
gdsw_cases.py; both list their cases as gdsw.NAME."""
import os
import re
import subprocess

from gdsw_common import API, BAD_INPUT, DIAGNOSTICS, ELASTICITY, LIB, PETSC_DIR, api_lines, elasticity, solves, suitesparse_major
from testlib import BUILD, ENV, between, case, main, run


# ---- bad input: a clear message, no crash, no hang --------------------------------------------
LOCAL_SOLVERS = (("cholesky", "cholmod"), ("cholesky", "cholmod_single"), ("cholesky", "petsc"), ("lu", "umfpack"), ("lu", "petsc"), ("lu", "mumps"))


@case
def singular_subdomain():
    """ex2's 2D Laplacian with row and column 100 zeroed, GMRES, 3 subdomains per rank: the
    interior solve of the extension and (with no coarse level) the overlapping subdomain solve
    stop with a sentence naming the subdomain's matrix and dof 100, whichever local solver is
    chosen (UMFPACK only warns: the factor's solve gives Inf/NaN), instead of DIVERGED_NANORINF."""
    for np in (1, 3):
        for prefix, opts, what in (("extension", [], "interior"), ("sub", ["-pc_gdsw_coarse_space", "none"], "overlapping")):
            for t, s in ((None, None),) + LOCAL_SOLVERS:
                solver = [f"-pc_gdsw_{prefix}_pc_type", t, f"-pc_gdsw_{prefix}_pc_factor_mat_solver_type", s] if t else []
                out = run([BAD_INPUT, "-case", "zero_row_2d", "-pc_gdsw_subdomains", 3, "-ksp_converged_reason"] + opts + solver, np, fail=True)
                assert re.search(rf"PCGDSW: the {what} matrix of subdomain \d+ \(\d+ dofs\) could not be factored \(FACTOR_NUMERIC_ZEROPIVOT\): "
                                 r"the operator is singular there, its row of global dof 100 is zero", out), (np, what, t, s)
                assert "DIVERGED" not in out and "Segmentation" not in out


BAD = {
    "nonsquare": "the operator must be square; it is 12 x 10",
    "unassembled": "the operator is not assembled",
    "coordinates": "PCSetCoordinates() gave",
    "nullspace_length": "near-null space vector 0 has local length",
    "floating": "the operator is singular: it has no Dirichlet row",
    "singular": "could not be factored (FACTOR_NUMERIC_ZEROPIVOT)",
    "partial_node": "it must contain every dof of each node it touches",
    "uncovered": "lies in no subdomain",
    "index_negative": "the nonoverlapping index set of subdomain 0 on rank 0 holds the index -1",
    "index_large": "holds the index 120 at position",
    "coordinates_nan": "PCSetCoordinates() coordinate 1 of local node 0 is not finite",
    "coordinates_2d": "PCSetCoordinates() gave 2-D coordinates but the operator has 3 dofs per node",
    "nullspace_nan": "near-null space vector 0 is not finite (NaN or Inf) in its local row 0",
    "nullspace_zero": "near-null space vector 1 is zero",
    "matrix_nan": "PCGDSW: the matrix has a non-finite entry (nan) in row 25, column 25",
    "matrix_inf": "PCGDSW: the matrix has a non-finite entry (inf) in row 25, column 25",
}


@case
def bad_input():
    for name, msg in BAD.items():
        for np in (1, 2):
            out = run([BAD_INPUT, "-case", name], np, fail=True)
            assert msg in out, f"case {name}: message {msg!r} not found"
            # a crash: PETSc's "Caught signal number 11", Open MPI's "exited on signal 11"
            assert "Segmentation" not in out and not re.search(r"signal (number )?\d", out)
            if name.startswith("matrix_"):
                assert "ZEROPIVOT" not in out and "shift" not in out.lower().replace("no shift helps", ""), f"case {name}: a non-finite entry reported as a zero pivot"


@case
def bad_options():
    for opts, msg in ((["-pc_gdsw_overlap", -1], "-pc_gdsw_overlap -1 is out of range"),
                      (["-pc_gdsw_subdomains", 0], "-pc_gdsw_subdomains 0 is out of range"),
                      (["-pc_gdsw_subdomain_size", 0], "-pc_gdsw_subdomain_size 0 is out of range"),
                      (["-pc_gdsw_coarse_space", "fancy"], "-pc_gdsw_coarse_space fancy is not one of: gdsw, rgdsw, none")):
        out = run([ELASTICITY, "-n", 4] + opts, 2, fail=True)
        assert msg in out, msg


@case
def bad_option_values():
    """A malformed or out-of-range value of every -pc_gdsw_* option on 2 ranks: exit status
    nonzero, one message (printed once) that names the option and what it takes."""
    for opt, value, msg in (("subdomains", "two", "is not an integer: give the number of subdomains per MPI rank, at least 1, or -1"),
                            ("subdomains", 0, "is out of range: give the number of subdomains per MPI rank"),
                            ("subdomain_size", 1.5, "is not an integer: give the target number of dofs per subdomain, at least 1"),
                            ("subdomain_size", -3, "is out of range: give the target number of dofs per subdomain, at least 1"),
                            ("overlap", "x", "is not an integer: give the number of layers, 0 or more"),
                            ("overlap", -1, "is out of range: give the number of layers, 0 or more"),
                            ("coarse_space", "fancy", "is not one of: gdsw, rgdsw, none"),
                            ("rgdsw_weights", "far", "is not one of: equal, distance"),
                            ("combination", "both", "is not one of: additive, multiplicative, symmetric_multiplicative"),
                            ("first_level_type", "ras", "is not one of: additive, restricted"),
                            ("rotations", "maybe", "is not true or false"),
                            ("repartition", "always", "is not true or false"),
                            ("reuse_coarse_basis", 2, "is not true or false"),
                            ("huge_pages", "often", "is not true or false"),
                            ("local_solver", "fast", "is not one of: exact, incomplete, adaptive"),
                            ("configuration", "quick", "is not one of: robust, fast"),
                            ("local_precision", "half", "is not one of: double, single"),
                            ("local_condition_max", "big", "is not a number: give the largest condition number estimate"),
                            ("local_condition_max", "inf", "is not a number: give the largest condition number estimate"),
                            ("local_condition_max", 0.5, "is out of range: give the largest condition number estimate")):
        out = run([ELASTICITY, "-n", 4, f"-pc_gdsw_{opt}", value], 2, fail=True)
        full = f"PCGDSW: -pc_gdsw_{opt} {value} {msg}"
        assert full in out, f"missing: {full!r}"
        assert out.count("PCGDSW:") == 1, f"-pc_gdsw_{opt}: the message is printed {out.count('PCGDSW:')} times"


@case
def help_prefix():
    """-help lists the inner solvers' options of a prefixed gdsw under their whole prefix. PETSc
    3.18 cuts the list-valued ones (-pc_type, -ksp_type) of a prefix longer than 32 characters, as
    gdsw's are under PCFIELDSPLIT: fieldsplit_structure_pc_gdsw_sub_ came out as
    -fieldsplit_structure_pc_gdsw_supc_type. A setter's range message names the prefixed option."""
    for prefix in ("foo_", "fieldsplit_structure_", "fieldsplit_structure_inner_ksp_"):
        out = run([DIAGNOSTICS, "-n", 4, "-boxes", 2, "-prefix", prefix, "-help"])
        for line in ("pc_gdsw_sub_pc_type <now cholesky", "pc_gdsw_sub_ksp_type <now preonly", "pc_gdsw_extension_pc_type <now cholesky",
                     "pc_gdsw_coarse_ksp_type <now preonly", "pc_gdsw_sub_pc_factor_mat_ordering_type <now"):
            assert f"  -{prefix}{line}" in out, f"missing in -help: -{prefix}{line}"
        assert "supc_" not in out and "_pc_gpc" not in out, prefix
    out = run([DIAGNOSTICS, "-n", 4, "-prefix", "foo_", "-foo_pc_gdsw_overlap", -1], 2, fail=True)
    assert "PCGDSW: -foo_pc_gdsw_overlap -1 is out of range: give the number of layers, 0 or more" in out


@case
def empty_subdomain():
    """An empty subdomain from the application is dropped; the solve still converges."""
    for np in (1, 2):
        out = run([BAD_INPUT, "-case", "empty_subdomain", "-ksp_type", "cg", "-ksp_rtol", "1e-8"], np)
        between(solves(out)[0]["iterations"], 1, 10, "iterations")


# ---- the PC as seen by PETSc users -----------------------------------------------------------
@case
def view_and_log():
    out = run([ELASTICITY, "-n", 8, "-boxes", 2, "-ksp_view", "-log_view"])
    for s in ("type: gdsw", "coarse space gdsw, symmetric_multiplicative combination", "8 subdomains (given by the application)",
              "12 faces, 6 edges, 1 vertices", "coarse dimension 105", "prefix -pc_gdsw_coarse_", "prefix -pc_gdsw_sub_",
              "GDSWDecomp", "GDSWInterface", "GDSWBasis", "GDSWExtension", "GDSWCoarseSetUp", "GDSWLocalFactor", "GDSWApply"):
        assert s in out, f"missing in -ksp_view/-log_view output: {s!r}"
    for opts, line in (([], "subdomains per rank: chosen by the size rule, about 12000 dofs each (-pc_gdsw_subdomain_size): 1 on rank 0"),
                       (["-pc_gdsw_subdomain_size", 1000], "about 1000 dofs each (-pc_gdsw_subdomain_size): 7 on rank 0"),
                       (["-pc_gdsw_subdomains", 3], "subdomains per rank: 3, given (-pc_gdsw_subdomains)")):
        assert line in run([ELASTICITY, "-n", 16, "-ksp_view"] + opts, 2), f"missing in -ksp_view: {line!r}"
    out = run([ELASTICITY, "-n", 4, "-boxes", 2, "-help"])
    for opt, default in (("subdomains", "-1"), ("overlap", "1"), ("coarse_space", "gdsw"), ("rgdsw_weights", "distance"), ("rotations", "TRUE"), ("repartition", "FALSE"),
                         ("combination", "symmetric_multiplicative"), ("first_level_type", "additive"), ("reuse_coarse_basis", "FALSE"), ("huge_pages", "TRUE"),
                         ("configuration", "robust"), ("local_solver", "exact"), ("local_condition_max", "25."), ("local_precision", "double"), ("subdomain_size", "12000")):
        # PETSc 3.18 prints "-opt <now v" ("-opt: <v" for booleans, "-opt <v" for reals), 3.22 "-opt: <now v"
        assert re.search(rf"-pc_gdsw_{opt}:? <(now )?{re.escape(default)}", out), f"missing in -help: -pc_gdsw_{opt} <{default}"
    for s in ("-pc_gdsw_sub_pc_type", "-pc_gdsw_extension_pc_type", "-pc_gdsw_coarse_pc_type"):
        assert s in out, f"missing in -help: {s!r}"


@case
def installed_consumer():
    """The installed library, header and pkg-config file serve an outside C program (a 2D
    Laplacian, 16 METIS subdomains per rank, scalar null space), built against the library's
    PETSc (petscgdsw.pc requires PETSc: PKG_CONFIG_PATH names that PETSc's pkgconfig too)."""
    import shutil
    import tempfile
    prefix = tempfile.mkdtemp(prefix="gdsw-install-")
    try:
        subprocess.run(["cmake", "--install", BUILD, "--prefix", prefix], check=True, stdout=subprocess.DEVNULL)
        pc = subprocess.run(["pkg-config", "--cflags", "--libs", "petscgdsw"], check=True, text=True, stdout=subprocess.PIPE,
                            env=dict(ENV, PKG_CONFIG_PATH=os.path.join(prefix, "lib", "pkgconfig") + os.pathsep + os.path.join(PETSC_DIR, "lib", "pkgconfig"))).stdout.split()
        exe = os.path.join(prefix, "consumer")
        subprocess.run(["mpicc", "-O2", "-o", exe, os.path.join(os.path.dirname(__file__), "consumer", "main.c")] + pc, check=True)
        one = run([exe, "-pc_type", "gdsw", "-pc_gdsw_subdomains", 16])
        gd = solves(one)[0]["iterations"]
        os1 = solves(run([exe, "-pc_type", "gdsw", "-pc_gdsw_subdomains", 16, "-pc_gdsw_coarse_space", "none"]))[0]["iterations"]
        two = solves(run([exe, "-pc_type", "gdsw", "-pc_gdsw_subdomains", 8], 2))[0]["iterations"]
        print("gdsw", gd, "one-level", os1, "2 ranks", two)
        between(gd, 15, 32, "GDSW CG iterations, 2D Laplacian")
        assert os1 > gd, (os1, gd)
        between(two, 15, 32, "GDSW CG iterations, 2 ranks")
    finally:
        shutil.rmtree(prefix)


@case
def petsc4py_elasticity():
    """pc_gdsw/examples/elasticity.py, the C driver's problem written with petsc4py, on 2 ranks
    with -pc_type gdsw given as an option and the library loaded by -dll_append: the PC's type is
    gdsw, CG converges (true relative residual below 1e-6: 100 times the rtol CG applies to the
    preconditioned residual; measured 2e-7 and 5e-7), and the iterations equal the C
    driver's on the same matrix, load, clamp and row layout within 1 (the two assemble in
    different orders), at most 30, on 8^3 and 12^3 elements."""
    example = os.path.join(os.path.dirname(__file__), "..", "pc_gdsw", "examples", "elasticity.py")
    for n in (8, 12):
        out = run(["/usr/bin/python3", example, "-n", n, "-dll_append", LIB, "-pc_type", "gdsw"], 2)
        m = re.search(r"dofs (\d+) ranks 2 pc (\w+) iterations (\d+) reason (-?\d+) residual (\S+)", out)
        assert m, out[-2000:]
        dofs, pc, its, reason, residual = int(m.group(1)), m.group(2), int(m.group(3)), int(m.group(4)), float(m.group(5))
        c = elasticity("-n", n, np=2)
        assert (dofs, pc) == (c["dofs"], "gdsw") and reason > 0, (m.group(0), c)
        between(residual, 0, 1e-6, f"true relative residual, petsc4py, n {n}")
        between(its, c["iterations"] - 1, min(c["iterations"] + 1, 30), f"petsc4py iterations, n {n} (C driver {c['iterations']})")
    out = run(["/usr/bin/python3", example, "-n", 0], 2, fail=True)
    assert out.count("elasticity.py: -n 0 -nu 0.3: need at least one element") == 1, "the message of a bad option, once (rank 0)"


# ---- the API (tests/gdsw_api.cxx) and the set-up's use of the machine ------------------------
@case
def api_setters_reset():
    """Each setter that changes the decomposition, the coarse space or the combination, called
    after a solve, makes the next solve rebuild the PC: it equals a fresh run with the option
    (iterations, overlapping dofs, coarse dimension) and differs from the first solve (2 ranks,
    default size rule: one subdomain per rank)."""
    for name, value in (("subdomains", 4), ("subdomain_size", 200), ("overlap", 2), ("coarse_space", "none"),
                        ("combination", "additive"), ("first_level_type", "restricted"), ("local_solver", "incomplete"), ("configuration", "fast")):
        r = api_lines("-case", "setters", "-set", name, np=2)
        fresh = api_lines("-case", "transpose", f"-pc_gdsw_{name}", value, np=2)["forward"]
        keys = ("iterations", "overlap_dofs", "coarse")
        assert [r["second"][k] for k in keys] == [fresh[k] for k in keys], (name, r["second"], fresh)
        assert [r["second"][k] for k in keys] != [r["first"][k] for k in keys], (name, r)
        assert r["settings"][name] == str(value), (name, r["settings"])


@case
def api_getters():
    """Every -pc_gdsw_* option reaches its setter: the getters return what the options say."""
    opts = {"subdomains": 3, "repartition": 1, "subdomain_size": 500, "overlap": 2, "coarse_space": "rgdsw", "rgdsw_weights": "equal",
            "rotations": 0, "combination": "multiplicative", "first_level_type": "restricted", "reuse_coarse_basis": 1,
            "local_solver": "adaptive", "local_condition_max": 40.5, "local_precision": "double", "huge_pages": 0, "configuration": "fast"}
    # the repartition by PETSc's own partitioner "average": PTScotch hangs in Debian 12's 64-bit-index PETSc
    args = ["-pc_gdsw_mat_partitioning_type", "average"]
    for k, v in opts.items():
        args += [f"-pc_gdsw_{k}", v]
    got = api_lines("-case", "transpose", *args)["settings"]
    assert got == {k: str(v) for k, v in opts.items()}, got


@case
def api_petsc_reinit():
    """PetscInitialize/PetscFinalize twice in one program (MPI initialized by the program): gdsw
    is registered again after PetscFinalize emptied PETSc's list of PC types, and the second
    round prints what the first printed."""
    out = run([API, "-rounds", 2, "-pc_gdsw_subdomains", 4], 2)
    rounds = [line for line in out.splitlines() if line.startswith(("adjoint", "forward", "transpose"))]
    assert len(rounds) == 6 and rounds[:3] == rounds[3:], rounds


@case
def setup_threads():
    """The set-up runs on one thread per rank: CHOLMOD (SuiteSparse 5) opens OpenMP teams of a
    fixed 4 threads to zero its factor, whatever OMP_NUM_THREADS says, and a team once opened
    stays in the process. On the Laplacian (beta 0: Cholesky, CHOLMOD), one 8192-dof subdomain per
    rank, 2 ranks: without OMP_NUM_THREADS and with OMP_NUM_THREADS=1 the process has as many
    threads after KSPSetUp as before, and the OpenMP max-active-levels the caller set (2) is
    restored; with OMP_NUM_THREADS=4 (the user asked for threads) the runtime is left alone and
    CHOLMOD's team appears (3 more threads), so the case does exercise it. SuiteSparse 7 sizes
    CHOLMOD's teams by the work (128000 entries per thread) and opens none at this size: there the
    subdomains have 131072 dofs, and with OMP_NUM_THREADS=4 one to three threads appear (2
    measured)."""
    n, team = (128, (3, 3)) if suitesparse_major() < 7 else (512, (1, 3))
    opts = ["-case", "threads", "-beta", 0, "-n", n, "-pc_gdsw_subdomains", 1]
    for env, (lo, hi) in ((["env", "-u", "OMP_NUM_THREADS"], (0, 0)), (["env", "OMP_NUM_THREADS=1"], (0, 0)), (["env", "OMP_NUM_THREADS=4"], team)):
        out = run(env + [API] + opts, np=2)
        rows = [l.split() for l in out.splitlines() if l.startswith("threads before")]
        assert len(rows) == 2, out
        for w in rows:
            between(int(w[4]) - int(w[2]), lo, hi, f"threads opened by the set-up, {' '.join(env[1:])}")
            assert w[9] == "2", f"max-active-levels not restored: {w}"


@case
def huge_pages():
    """-pc_gdsw_huge_pages (the default) maps the set-up's blocks of 2 MiB or more (CHOLMOD's
    factors, the subdomain matrices) on transparent huge pages where the kernel gives them on
    request. It must not change the arithmetic: Q1 elasticity, 4 subdomains of about 12000 dofs on
    2 ranks, the same iterations and residual history with and without it. Where the kernel's mode
    is madvise, -ksp_view reports the bytes, at least the overlapping matrices' CSR arrays (46875
    rows of 24 or more nonzeros, 12 bytes each: 12.9 MiB), and -info says so; elsewhere neither
    appears. Every other gdsw case runs with it on, UMFPACK's LU and MUMPS among them."""
    opts = [ELASTICITY, "-n", 24, "-ksp_view", "-ksp_monitor", "-info", ":pc"]
    on, off = run(opts, 2), run(opts + ["-pc_gdsw_huge_pages", "false"], 2)
    history = [re.findall(r"^\s*\d+ KSP Residual norm (\S+)", o, re.M) for o in (on, off)]
    assert history[0] and history[0] == history[1], "the residual history changed"
    with open("/sys/kernel/mm/transparent_hugepage/enabled") as f:
        on_request = "[madvise]" in f.read()
    line = re.search(r"blocks of 2 MiB or more on transparent huge pages in the last set-up: (\d+) MiB", on)
    assert "blocks of 2 MiB or more on transparent huge pages" not in off
    if on_request:
        assert line and "the set-up's blocks of 2 MiB or more go on transparent huge pages" in on, "no huge pages in -ksp_view / -info"
        between(int(line.group(1)), 12.9, 1e4, "MiB on huge pages")
    else:
        assert not line and "-pc_gdsw_huge_pages changes nothing" in on


if __name__ == "__main__":
    main("gdsw")
