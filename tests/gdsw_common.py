# SPDX-License-Identifier: BSD-2-Clause
"""What the gdsw case files share: the programs they run and the numbers a solve prints."""
import os
import re

from testlib import BUILD, ENV, cmake_cache, run

LIB = os.path.join(BUILD, "pc_gdsw", "libpetscgdsw.so")
ELASTICITY = os.path.join(BUILD, "pc_gdsw", "gdsw_elasticity")
DIAGNOSTICS = os.path.join(BUILD, "tests", "gdsw_diagnostics")  # the tutorial's solve, then looked into
BAD_INPUT = os.path.join(BUILD, "tests", "gdsw_bad_input")
API = os.path.join(BUILD, "tests", "gdsw_api")
EX56 = os.path.join(BUILD, "tests", "petsc_ksp_ksp_ex56")
EX71 = os.path.join(BUILD, "tests", "petsc_ksp_ksp_ex71")
EX17 = os.path.join(BUILD, "tests", "petsc_snes_ex17")
FSI_APP = os.path.join(BUILD, "fsi_app", "fsi_app")
PETSC_DIR = ENV.get("PETSC_DIR", "")  # the PETSc the build found

# the elasticity programs' summary line, the diagnostics driver's residual line after it, PETSc's
# -ksp_converged_reason line, and the bare "iterations N" of the bad-input driver and the consumer
SUMMARY = re.compile(r"^dofs (?P<dofs>\d+) ranks \d+ iterations (?P<iterations>\d+) reason (?P<reason>\w+) coarse (?P<coarse>\d+) "
                     r"faces (?P<faces>\d+) edges (?P<edges>\d+) vertices (?P<vertices>\d+)"
                     r"(?:.*\ntrue relative residual (?P<residual>\S+))?", re.M)
REASON = re.compile(r"Linear solve (?:converged|did not converge) due to (?P<reason>\w+) iterations (?P<iterations>\d+)")
BARE = re.compile(r"^iterations (?P<iterations>\d+)$", re.M)


def solves(out):
    """Each solve a program printed, in order, as a dict of numbers (and its reason, a string):
    the summary lines if it printed any, else PETSc's -ksp_converged_reason lines, else bare
    "iterations N" lines."""
    for pattern in (SUMMARY, REASON, BARE):
        found = [{k: v if k == "reason" else float(v) if k == "residual" else int(v) for k, v in m.groupdict().items() if v is not None}
                 for m in pattern.finditer(out)]
        if found:
            return found
    raise AssertionError("no solve in the output")


def solved(out):
    """The first solve of out (see solves()), which must have converged."""
    first = solves(out)[0]
    assert first.get("reason", "CONVERGED").startswith("CONVERGED"), f"did not converge: {first}"
    return first


def elasticity(*opts, np=1, driver=ELASTICITY):
    """The solve(s) of the Q1 elasticity tutorial (or of the diagnostics driver), each converged."""
    rows = solves(run([driver] + list(opts), np))
    for r in rows:
        assert r["reason"].startswith("CONVERGED"), f"did not converge: {r['reason']}"
    return rows[-1] if len(rows) == 1 else rows


def api_lines(*opts, np=1):
    """gdsw_api's lines as {first word: {key: value}} (the last of each kind)."""
    out = run([API] + list(opts), np)
    lines = {}
    for line in out.splitlines():
        w = line.replace(":", "").split()
        if w and w[0] in ("settings", "adjoint", "forward", "transpose", "first", "second", "coarse"):
            lines[w[0]] = {w[i]: w[i + 1] for i in range(1, len(w) - 1, 2)} if w[0] != "adjoint" else \
                {"error": float(w[4]), "asymmetry": float(w[6])}
    return lines


def suitesparse_major():
    """SUITESPARSE_MAIN_VERSION of the SuiteSparse headers the build was made with."""
    with open(os.path.join(cmake_cache("SUITESPARSE_INCLUDE_DIR"), "SuiteSparse_config.h")) as f:
        return int(re.search(r"^#define SUITESPARSE_MAIN_VERSION\s+(\d+)", f.read(), re.M).group(1))
