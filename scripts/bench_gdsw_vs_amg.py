#!/usr/bin/python3
# SPDX-License-Identifier: BSD-2-Clause
"""gdsw against what a PETSc user would otherwise type on ordinary elasticity: GAMG, ML,
BoomerAMG, PETSc's own GDSW and BDDC (deluxe scaling, one subdomain per rank, on MATIS: every
problem but ex56, whose driver assembles AIJ only), with gdsw's defaults (balanced combination), the additive combination
and each of its levers.
  ex56   PETSc's ksp/tutorials/ex56 -ne 31 -use_mat_nearnullspace (98,304 dofs, a soft inclusion),
         1 rank; and 2 ranks, where ex56 puts every row on rank 0
  ex71   PETSc's ksp/tutorials/ex71 -pde_type Elasticity -dim 3 -cells 31,31,31 (MATIS; the AMGs
         get the same matrix as AIJ), 2 ranks
  cube   pc_gdsw/examples/elasticity.cxx -n 54 (Q1, 499,125 dofs), 2 ranks
  plate  PETSc's snes/tutorials/ex17 clamped and stretched plate (its ge testset) 10 x 10 x t,
         80 x 80 x 2 Q1 cells (58,077 dofs), t = 0.5, 0.05, 0.005 (cells of aspect ratio 0.5, 5,
         50), PTScotch's mesh partition on 2 ranks; and t = 0.05 with PETSc's simple partition,
         which gives each rank one layer of cells (gdsw with and without -pc_gdsw_repartition)
CG to rtol 1e-8 in the unpreconditioned norm, zero initial guess. Per run: iterations, set-up
(PCSetUp) and solve (KSPSolve) time from -log_view (max over ranks), peak memory (sum over ranks);
each command runs --repeat times (default 3) back to back and the row holds the median time.
Writes bench/results/gdsw_vs_amg.{csv,cmd,png}.
Usage: scripts/bench_gdsw_vs_amg.py [--quick] [--repeat N] [--only PROBLEM,...] [--methods METHOD,...] [--hugepages] [--plot]
(--only, --methods: those problems (first words: ex56, ex71, cube, plate) or methods (names as
in the table, e.g. "BDDC deluxe") alone; their rows and commands replace the same ones in the
files, the others stay)
(--quick: small sizes, one run each, files in /tmp; --plot redraws the PNG from the CSV;
--hugepages: every run with glibc's GLIBC_TUNABLES=glibc.malloc.hugetlb=1, so that malloc takes
transparent huge pages where the kernel gives them only on request, as Debian's does; files
gdsw_vs_amg_hugepages.*)
The build directory is $GDSW_BUILD (default <top>/build)."""
import csv
import os
import statistics
import sys

from benchlib import check_command_line, loadavg, measure_solve, portable, write_results

check_command_line(__doc__, valued=("--only", "--methods", "--repeat"), flags=("--plot", "--quick", "--hugepages"))

top = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
build = os.environ.get("GDSW_BUILD", os.path.join(top, "build"))
EX56 = os.path.join(build, "tests", "petsc_ksp_ksp_ex56")
EX71 = os.path.join(build, "tests", "petsc_ksp_ksp_ex71")
EX17 = os.path.join(build, "tests", "petsc_snes_ex17")
ELASTICITY = os.path.join(build, "pc_gdsw", "gdsw_elasticity")
LIB = os.path.join(build, "pc_gdsw", "libpetscgdsw.so")
quick = "--quick" in sys.argv
results = "/tmp/gdsw_vs_amg_quick" if quick else os.path.join(top, "bench", "results")
hugepages = "--hugepages" in sys.argv
OUTNAME = "gdsw_vs_amg_hugepages" if hugepages else "gdsw_vs_amg"
repeat = 1 if quick else int(sys.argv[sys.argv.index("--repeat") + 1]) if "--repeat" in sys.argv else 3

KRYLOV = "-ksp_type cg -ksp_rtol 1e-8 -ksp_norm_type unpreconditioned -ksp_max_it 3000"
MEASURE = "-ksp_converged_reason -log_view -memory_view"
GDSW = f"-dll_append {LIB} -pc_type gdsw"
PETSC_GDSW = ("-pc_type mg -pc_mg_levels 2 -pc_mg_galerkin -pc_mg_adapt_interp_coarse_space gdsw -pc_mg_type additive "
              "-mg_levels_ksp_type richardson -mg_levels_ksp_max_it 1 -mg_levels_pc_type asm -mg_levels_pc_asm_overlap 1 "
              "-mg_levels_pc_asm_type basic -mg_levels_sub_pc_type lu -mg_levels_sub_pc_factor_mat_solver_type mumps "
              "-mg_coarse_pc_type redundant -mg_coarse_redundant_pc_type lu")
# gdsw's defaults first, then its levers alone and together
METHODS = {
    "gdsw (defaults)": GDSW,
    "gdsw additive": f"{GDSW} -pc_gdsw_combination additive",
    "gdsw RGDSW": f"{GDSW} -pc_gdsw_coarse_space rgdsw",
    "gdsw exact, 3000-dof subdomains": f"{GDSW} -pc_gdsw_subdomain_size 3000",
    "gdsw incomplete": f"{GDSW} -pc_gdsw_local_solver incomplete",
    "gdsw incomplete, RGDSW": f"{GDSW} -pc_gdsw_local_solver incomplete -pc_gdsw_coarse_space rgdsw",
    "gdsw adaptive": f"{GDSW} -pc_gdsw_local_solver adaptive",
    "gdsw fast": f"{GDSW} -pc_gdsw_configuration fast",
    "GAMG": "-pc_type gamg",
    "ML": "-pc_type ml",
    "BoomerAMG": "-pc_type hypre",
    "BoomerAMG nodal": "-pc_type hypre -pc_hypre_boomeramg_nodal_coarsen 4 -pc_hypre_boomeramg_vec_interp_variant 2 "
                       "-pc_hypre_boomeramg_strong_threshold 0.5 -pc_hypre_boomeramg_agg_nl 1",
    "PETSc GDSW (PCMG)": PETSC_GDSW,
    # one subdomain per rank, subassembled: {matis} becomes the driver's option for MATIS
    "BDDC deluxe": "{matis} -pc_type bddc -pc_bddc_use_deluxe_scaling",
}
# how each driver makes its operator a MATIS (ex71 always does; ex56 cannot)
MATIS = {"ex71": "", "cube": "-mat_type is", "plate": "-dm_mat_type is"}
AMG = ["GAMG", "ML", "BoomerAMG", "BoomerAMG nodal"]
# PETSc's GDSW converts an AIJ operator to MATIS with one subdomain per rank: 266 s on the cube
NO_PETSC_GDSW = [m for m in METHODS if m != "PETSc GDSW (PCMG)"]
NO_MATIS = [m for m in METHODS if m != "BDDC deluxe"]
METHODS["gdsw repartitioned"] = f"{GDSW} -pc_gdsw_repartition"
# BoomerAMG is left out: on the thickest plate it needs 179 iterations and 52 s (ML 0.5 s), and its
# nodal variant stops with a segmentation fault (block size 1: DMPlex removes the clamped dofs)
PLATE_METHODS = ["gdsw (defaults)", "gdsw additive", "gdsw RGDSW", "gdsw adaptive", "gdsw fast", "GAMG", "ML", "PETSc GDSW (PCMG)", "BDDC deluxe"]


def plate(thickness, faces, partitioner):
    """snes ex17's ge plate, 10 x 10 x thickness; -ksp_view_mat ::ascii_info prints its size."""
    h = thickness / 2
    return (f"{EX17} -dm_plex_dim 3 -dm_plex_simplex 0 -dm_plex_box_lower -5,-5,{-h:g} -dm_plex_box_upper 5,5,{h:g} "
            f"-dm_plex_box_faces {faces} -dm_plex_separate_marker -petscpartitioner_type {partitioner} -sol_type elas_ge "
            "-displacement_petscspace_degree 1 -snes_type ksponly -ksp_view_mat ::ascii_info")


def problems():
    """(name, ranks, command before the solver options, methods)."""
    ne, cells, n, faces = (11, 11, 20, "20,20,2") if quick else (31, 31, 54, "80,80,2")
    ex56 = f"{EX56} -ne {ne} -use_mat_nearnullspace"
    plates = [(f"plate t={t:g}", 2, f"mpiexec -n 2 {plate(t, faces, 'ptscotch')}", PLATE_METHODS) for t in (0.5, 0.05, 0.005)]
    return [("ex56", 1, f"mpiexec -n 1 {ex56}", NO_MATIS),
            ("ex56 (2 ranks, all rows on rank 0)", 2, f"mpiexec -n 2 {ex56}", [m for m in METHODS if m.startswith("gdsw")] + ["ML"]),
            ("ex71 MATIS", 2, f"mpiexec -n 2 {EX71} -pde_type Elasticity -dim 3 -cells {cells},{cells},{cells}", list(METHODS)),
            ("cube", 2, f"mpiexec -n 2 {ELASTICITY} -n {n}", NO_PETSC_GDSW)] + plates + [
            ("plate t=0.05 (simple partition: one layer per rank)", 2, f"mpiexec -n 2 {plate(0.05, faces, 'simple')}",
             ["gdsw (defaults)", "gdsw repartitioned", "GAMG", "ML"])]


def main():
    if "--plot" in sys.argv:
        plot(list(csv.DictReader(open(os.path.join(results, OUTNAME + ".csv")))))
        return
    os.makedirs(results, exist_ok=True)
    only = sys.argv[sys.argv.index("--only") + 1].split(",") if "--only" in sys.argv else None
    chosen = sys.argv[sys.argv.index("--methods") + 1].split(",") if "--methods" in sys.argv else None
    if chosen and set(chosen) - set(METHODS):
        sys.exit(f"bench_gdsw_vs_amg.py: --methods: no method {', '.join(sorted(set(chosen) - set(METHODS)))}; the methods: {', '.join(METHODS)}")
    load, rows, cmds = loadavg(), [], []
    for name, ranks, base, methods in problems():
        if only and name.split()[0] not in only:
            continue
        for method in methods:
            if chosen and method not in chosen:
                continue
            # the AMGs take no MATIS: ex71 assembles the same matrix as AIJ for them
            aij = " -dm_mat_type aij" if name.startswith("ex71") and method in AMG else ""
            cmd = f"{base}{aij} {KRYLOV} {METHODS[method].format(matis=MATIS.get(name.split()[0], ''))} {MEASURE}"
            if hugepages:
                cmd = cmd.replace("mpiexec ", "mpiexec -x GLIBC_TUNABLES=glibc.malloc.hugetlb=1 ", 1)
            runs = [measure_solve(cmd, 900) for _ in range(repeat)]
            ok = [r for r in runs if r["status"] == "ok"]
            row = dict(runs[0] if not ok else min(ok, key=lambda r: abs(r["total_s"] - statistics.median(x["total_s"] for x in ok))))
            if ok:
                row["total_s"] = round(statistics.median(r["total_s"] for r in ok), 3)
                row["setup_s"] = round(statistics.median(r["setup_s"] for r in ok), 3)
                row["solve_s"] = round(statistics.median(r["solve_s"] for r in ok), 3)
            row = {"problem": name, "ranks": ranks, "method": method, **row, "runs": len(runs),
                   "total_min_s": min((r["total_s"] for r in ok), default=""), "total_max_s": max((r["total_s"] for r in ok), default="")}
            print(f"{name:34s} {method:34s} {row['status']:8.40s} its {row['iterations']!s:>5} setup {row['setup_s']:8.3f} "
                  f"solve {row['solve_s']:8.3f} total {row['total_s']:8.3f} mem {row['memory_MB']!s:>6} MB", flush=True)
            rows.append(row)
            cmds.append(cmd)
    out = os.path.join(results, OUTNAME)
    if (only or chosen) and os.path.exists(out + ".csv"):  # the other rows and commands stay as they were
        ran = {(r["problem"], r["method"]) for r in rows}
        old = [r for r in csv.DictReader(open(out + ".csv")) if (r["problem"], r["method"]) not in ran]
        new = {portable(c) for c in cmds}
        oldcmds = [c for c in open(out + ".cmd").read().splitlines() if not c.startswith("#") and c not in new]
        order = {p: k for k, (p, _, _, _) in enumerate(problems())}
        rows = sorted(old + rows, key=lambda r: (order.get(r["problem"], len(order)), list(METHODS).index(r["method"]) if r["method"] in METHODS else len(METHODS)))
        cmds = oldcmds + cmds
    for r in rows:
        amg = [float(o["total_s"]) for o in rows if o["problem"] == r["problem"] and o["method"] in AMG and o["status"] == "ok"]
        r["ratio_to_best_amg"] = round(float(r["total_s"]) / min(amg), 2) if amg and r["status"] == "ok" else ""
    write_results(out, rows, cmds, f"scripts/bench_gdsw_vs_amg.py (medians of {repeat} back-to-back runs, OMP_NUM_THREADS=1)", load, keep_earlier=bool(only or chosen))
    plot(rows)


def plot(rows):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    names = list(dict.fromkeys(r["problem"] for r in rows))
    cols = min(4, len(names))
    rows_ = -(-len(names) // cols)
    fig, axes = plt.subplots(rows_, cols, figsize=(5.5 * cols, 4.5 * rows_), squeeze=False)
    for ax in axes.flat[len(names):]:
        ax.axis("off")
    for ax, name in zip(axes.flat, names):
        group = [r for r in rows if r["problem"] == name and r["status"] == "ok"]
        labels = [r["method"] for r in group]
        setup = [float(r["setup_s"]) for r in group]
        solve = [float(r["solve_s"]) for r in group]
        y = range(len(group))
        ax.barh(y, setup, color="tab:blue", label="set-up")
        ax.barh(y, solve, left=setup, color="tab:orange", label="solve")
        for k, r in enumerate(group):
            ax.text(setup[k] + solve[k], k, f" {r['iterations']} its", va="center", fontsize=7)
        ax.set_yticks(list(y))
        ax.set_yticklabels(labels, fontsize=7)
        ax.invert_yaxis()
        ax.set_xlabel("seconds (median)")
        ax.set_title(name, fontsize=9)
    axes.flat[0].legend(fontsize=7)
    fig.suptitle("PCSetUp + KSPSolve, CG to 1e-8 (unpreconditioned norm)", fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(results, OUTNAME + ".png"), dpi=110)


if __name__ == "__main__":
    main()
