# SPDX-License-Identifier: BSD-2-Clause
"""Shared helpers of the ctest case files: run a program under mpiexec, assert bounds."""
import os
import re
import subprocess
import sys

TOP = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BUILD = os.environ.get("GDSW_BUILD", os.path.join(TOP, "build"))


def cmake_cache(name):
    """The value of name in the build's CMakeCache.txt, or None."""
    try:
        with open(os.path.join(BUILD, "CMakeCache.txt")) as f:
            m = re.search(rf"^{name}:\w+=(.*)$", f.read(), re.M)
    except FileNotFoundError:
        return None
    return m.group(1) if m else None


# one OpenMP thread per rank: the tests run up to 27 ranks on 2 cores (gdsw keeps CHOLMOD's fixed
# teams closed itself; test setup_threads unsets this). More ranks than cores: Open MPI 4 reads
# OMPI_MCA_rmaps_base_oversubscribe, Open MPI 5 (Debian 13) PRTE_MCA_rmaps_default_mapping_policy.
# Every rank is on this machine: shared memory only, no TCP (Open MPI 5 warns on every rank where
# it finds no pair of reachable interfaces, and the cases count the lines a run prints).
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1", PRTE_MCA_rmaps_default_mapping_policy=":oversubscribe",
           OMPI_MCA_btl="^tcp", OMPI_MCA_mpi_yield_when_idle="1", OMP_NUM_THREADS="1")
# the PETSc the build found (another with -DPETSC_DIR), for Debian's petsc4py, which reads it, and PETSc's test harness
if cmake_cache("PETSC_PREFIX"):
    ENV["PETSC_DIR"] = cmake_cache("PETSC_PREFIX")
CASES = {}


def case(f):
    CASES[f.__name__] = f
    return f


def run(cmd, np=1, fail=False, stderr=True):
    """Run cmd on np ranks; return its output (stderr merged into it unless stderr=False).
    fail=True expects a nonzero exit status, None accepts either."""
    full = ["mpiexec", "-n", str(np)] + [str(c) for c in cmd]
    p = subprocess.run(full, env=ENV, stdout=subprocess.PIPE, stderr=subprocess.STDOUT if stderr else subprocess.DEVNULL, text=True, timeout=500, cwd=TOP)  # scenes name files from the top
    print("$", " ".join(full), "\n" + p.stdout[-3000:])
    assert fail is None or (p.returncode != 0) == fail, f"exit status {p.returncode}, expected {'failure' if fail else 'success'}"
    return p.stdout


def between(value, lo, hi, what):
    print(f"{what}: {value} (expected {lo}..{hi})")
    assert lo <= value <= hi, f"{what} = {value} is outside [{lo}, {hi}]"


def main(prefix):
    """`FILE --list` names the cases as PREFIX.name; `FILE NAME` runs one (exit status 0 = pass)."""
    if sys.argv[1:] == ["--list"]:
        print("\n".join(f"{prefix}.{n}" for n in CASES))
        sys.exit(0)
    CASES[sys.argv[1].removeprefix(prefix + ".")]()
    print("PASS")
