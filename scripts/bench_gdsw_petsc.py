#!/usr/bin/python3
# SPDX-License-Identifier: BSD-2-Clause
"""Iteration counts of -pc_type gdsw against PETSc's own GDSW (PCMG with the adaptive GDSW
coarse space) and one-level PCASM, on the same matrices: PETSc's ksp/tutorials/ex71 3D
elasticity, one subdomain per MPI rank (p^3 ranks, oversubscribed: counts only, no timings),
CG to rtol 1e-8, overlap 1, exact local solves. Writes bench/results/gdsw_vs_petsc.{csv,png,cmd}.
Usage: scripts/bench_gdsw_petsc.py [--quick | --plot]   (--plot redraws the PNG from the CSV)"""
import csv
import os
import re
import sys

from benchlib import check_command_line, run, write_results

check_command_line(__doc__, flags=("--plot", "--quick"))

top = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ex71 = os.path.join(top, "build", "tests", "petsc_ksp_ksp_ex71")
lib = os.path.join(top, "build", "pc_gdsw", "libpetscgdsw.so")
out = os.path.join(top, "bench", "results", "gdsw_vs_petsc")

METHODS = {
    "gdsw (MATIS subdomains)": f"-dll_append {lib} -pc_type gdsw",
    "gdsw (AIJ, graph subdomains)": f"-dm_mat_type aij -dll_append {lib} -pc_type gdsw",
    "rgdsw (MATIS subdomains)": f"-dll_append {lib} -pc_type gdsw -pc_gdsw_coarse_space rgdsw",
    "PETSc GDSW (PCMG)": "-pc_type mg -pc_mg_levels 2 -pc_mg_galerkin -pc_mg_adapt_interp_coarse_space gdsw -pc_mg_type additive "
                         "-mg_levels_ksp_type richardson -mg_levels_ksp_max_it 1 -mg_levels_pc_type asm -mg_levels_pc_asm_overlap 1 "
                         "-mg_levels_pc_asm_type basic -mg_levels_sub_pc_type lu -mg_levels_sub_pc_factor_mat_solver_type mumps "
                         "-mg_coarse_pc_type redundant -mg_coarse_redundant_pc_type lu",
    "PCASM one-level": "-dm_mat_type aij -pc_type asm -pc_asm_overlap 1 -pc_asm_type basic -sub_pc_type lu -sub_pc_factor_mat_solver_type mumps",
}


def main():
    if "--plot" in sys.argv:
        with open(out + ".csv") as f:
            rows = [dict(r, H_over_h=int(r["H_over_h"]), subdomains=int(r["subdomains"]), iterations=int(r["iterations"])) for r in csv.DictReader(f)]
        plot(rows)
        return
    quick = "--quick" in sys.argv
    ratios = (4,) if quick else (4, 8)
    ps = (2, 3) if quick else (2, 3, 4)
    rows, cmds = [], []
    for hh in ratios:
        for p in ps:
            c = hh * p - 1
            for name, opts in METHODS.items():
                cmd = (f"mpiexec --oversubscribe --mca mpi_yield_when_idle 1 -n {p**3} {ex71} -pde_type Elasticity -dim 3 "
                       f"-cells {c},{c},{c} -ksp_type cg -ksp_rtol 1e-8 -ksp_converged_reason {opts}")
                m = re.search(r"CONVERGED_\w+ iterations (\d+)", run(cmd))
                its = int(m.group(1)) if m else -1
                print(f"H/h={hh} N={p**3:3d} {name:32s} {its}", flush=True)
                rows.append({"H_over_h": hh, "subdomains": p**3, "method": name, "iterations": its})
                cmds.append(cmd)
    write_results(out, rows, cmds, "scripts/bench_gdsw_petsc.py" + (" --quick" if quick else ""))
    plot(rows)


def plot(rows):
    ratios = sorted({r["H_over_h"] for r in rows})
    sizes = sorted({r["subdomains"] for r in rows})
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, len(ratios), figsize=(6 * len(ratios), 4.5), squeeze=False)
    for ax, hh in zip(axes[0], ratios):
        for name in METHODS:
            pts = [(r["subdomains"], r["iterations"]) for r in rows if r["H_over_h"] == hh and r["method"] == name and r["iterations"] > 0]
            ax.plot(*zip(*pts), "o-", label=name)
        ax.set_xticks(sizes)
        ax.set_xlabel("subdomains (= MPI ranks)")
        ax.set_ylabel("CG iterations to 1e-8")
        ax.set_title(f"ex71 3D elasticity, H/h = {hh}, overlap 1")
        ax.grid(True, alpha=0.3)
    axes[0][0].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out + ".png", dpi=110)


if __name__ == "__main__":
    main()
