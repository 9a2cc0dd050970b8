#!/usr/bin/python3
# SPDX-License-Identifier: BSD-2-Clause
"""The benchmark suite: -pc_type gdsw side by side with every PETSc alternative on the
same matrices, 2 MPI ranks, CG to rtol 1e-8 (MUMPS: one direct solve).
  P1 Q1 elasticity on the unit cube (pc_gdsw/examples/elasticity.cxx), homogeneous
  P2 the same with Young's modulus jumping by 1e6 between checkerboard boxes
  P3 nearly incompressible, nu = 0.45, 0.49, 0.499, 0.4999
  P4 the tube #3 wall (P2 tetrahedra, fsi_app) with the mass term rho/dt^2, dt = 1e-4, 5e-4
Per run: iterations, setup (PCSetUp) and solve (KSPSolve) time from -log_view (max over ranks),
peak memory from -memory_view (sum over ranks), and total time over the best other method of the
same problem. Failures (no convergence, error, timeout) are rows too.
Then iterations vs number of subdomains (8 -> 216) at H/h = 4: gdsw with several box subdomains
per rank on 2 ranks; PETSc's GDSW, gdsw and BDDC (deluxe scaling) one subdomain per rank on
PETSc's ex71 (oversubscribed).
Writes bench/results/gdsw_suite.{csv,cmd,png} and gdsw_suite_scaling.{csv,cmd,png}.
With --sweep instead: gdsw's time to solution on P1 against subdomains per rank and problem
size, which fixed the default rule (bench/results/gdsw_subdomains_per_rank.{csv,cmd,png}).
With --scaling: the iterations vs subdomains alone.
Usage: scripts/bench_gdsw_suite.py [--quick] [--sweep | --scaling] [--plot | --tables]
(--plot redraws the PNGs from the CSVs; --tables prints the CSVs as markdown tables)
The build directory is $GDSW_BUILD (default <top>/build)."""
import csv
import math
import os
import sys

from benchlib import check_command_line, measure_solve as measure, write_results

check_command_line(__doc__, flags=("--plot", "--quick", "--scaling", "--sweep", "--tables"))

top = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
build = os.environ.get("GDSW_BUILD", os.path.join(top, "build"))
ELASTICITY = os.path.join(build, "pc_gdsw", "gdsw_elasticity")
FSI = os.path.join(build, "fsi_app", "fsi_app")
EX71 = os.path.join(build, "tests", "petsc_ksp_ksp_ex71")
quick = "--quick" in sys.argv
# a quick run only checks the script: its files go to /tmp, not over the full run's
results = "/tmp/gdsw_suite_quick" if quick else os.path.join(top, "bench", "results")

KRYLOV = "-ksp_type cg -ksp_rtol 1e-8 -ksp_max_it 2000"
MEASURE = "-ksp_converged_reason -log_view -memory_view"
PETSC_GDSW = ("-pc_type mg -pc_mg_levels 2 -pc_mg_galerkin -pc_mg_adapt_interp_coarse_space gdsw -pc_mg_type additive "
              "-mg_levels_ksp_type richardson -mg_levels_ksp_max_it 1 -mg_levels_pc_type asm -mg_levels_pc_asm_overlap 1 "
              "-mg_levels_pc_asm_type basic -mg_levels_sub_pc_type lu -mg_levels_sub_pc_factor_mat_solver_type mumps "
              "-mg_coarse_pc_type redundant -mg_coarse_redundant_pc_type lu")
# {matis} becomes the driver's option for a subassembled (MATIS) operator
METHODS = {
    "GDSW": "-pc_type gdsw",
    "GDSW overlap 2": "-pc_type gdsw -pc_gdsw_overlap 2",
    "GDSW-nr": "-pc_type gdsw -pc_gdsw_rotations 0",
    "RGDSW": "-pc_type gdsw -pc_gdsw_coarse_space rgdsw",
    "RGDSW overlap 2": "-pc_type gdsw -pc_gdsw_coarse_space rgdsw -pc_gdsw_overlap 2",
    "gdsw one-level": "-pc_type gdsw -pc_gdsw_coarse_space none",
    "PETSc GDSW (PCMG)": PETSC_GDSW,
    "PCASM": "-pc_type asm -pc_asm_overlap 1 -pc_asm_type basic -sub_pc_type cholesky -sub_pc_factor_mat_solver_type cholmod",
    "GAMG": "-pc_type gamg",
    "BoomerAMG": "-pc_type hypre",
    "BoomerAMG nodal": "-pc_type hypre -pc_hypre_boomeramg_nodal_coarsen 4 -pc_hypre_boomeramg_vec_interp_variant 2 "
                       "-pc_hypre_boomeramg_strong_threshold 0.5 -pc_hypre_boomeramg_agg_nl 1",
    "ML": "-pc_type ml",
    # deluxe scaling: with the default (multiplicity) scaling BDDC took 507 iterations on P2
    "BDDC deluxe": "{matis} -pc_type bddc -pc_bddc_use_deluxe_scaling",
    "MUMPS (direct)": "-ksp_type preonly -pc_type lu -pc_factor_mat_solver_type mumps",
}
DIRECT = {"MUMPS (direct)"}

# gdsw's default subdomains per rank (pc_gdsw/src/decomposition.cxx): about this many dofs each
DOFS_PER_SUBDOMAIN = 12000


def default_subdomains(dofs_per_rank):
    return max(1, round(dofs_per_rank / DOFS_PER_SUBDOMAIN))


# P1 at half a million dofs: the methods that finish there in minutes (PETSc's GDSW: 266 s);
# BDDC and MUMPS factor one 250 k-dof subdomain per rank, or the whole matrix
LARGE = ["GDSW", "RGDSW", "PETSc GDSW (PCMG)", "PCASM", "GAMG", "BoomerAMG", "ML"]


def problems():
    """(problem, variant, command prefix, methods) of every case. fsi_app hands gdsw its own
    element subdomains (-structure_subdomains), so P4 sizes them by gdsw's default rule here."""
    n1, n2, n3, nl = (8, 8, 6, 10) if quick else (31, 24, 16, 54)
    el = f"mpiexec -n 2 {ELASTICITY}"
    cases = [("P1", f"n={n1}", f"{el} -n {n1}"), ("P1", f"n={nl}", f"{el} -n {nl}", LARGE),
             ("P2", f"n={n2} jump 1e6", f"{el} -n {n2} -jump 1e6 -jump_boxes {2 if quick else 4}")]
    cases += [("P3", f"nu={nu}", f"{el} -n {n3} -nu {nu}") for nu in ("0.45", "0.49", "0.499", "0.4999")]
    mesh, dofs = ("tube1_L0", 12240) if quick else ("tube3_L0", 100827)
    wall = (f"mpiexec -n 2 {FSI} -mesh {top}/meshes/{mesh}.msh -structure_region wall -structure_clamp wall_inlet_ring,wall_outlet_ring "
            f"-structure_pressure 1330 -structure_pressure_group interface -structure_material linear -structure_E 4e5 -structure_nu 0.3 -structure_density 1.2 "
            f"-snes_type ksponly -structure_subdomains {default_subdomains(dofs / 2)}")
    cases += [("P4", f"{mesh} dt={dt}", f"{wall} -dt {dt} -t_final {dt}") for dt in ("1e-4", "5e-4")]
    return [c if len(c) == 4 else (*c, list(METHODS)) for c in cases]


def suite():
    rows, cmds = [], []
    for prob, variant, base, methods in problems():
        matis = "-dm_mat_type is" if prob == "P4" else "-mat_type is"
        group = []
        for name in methods:
            cmd = f"{base} {KRYLOV} {METHODS[name].format(matis=matis)} {MEASURE}"
            row = {"problem": prob, "variant": variant, "method": name, **measure(cmd, 60 if quick else 400 if methods is LARGE else 300)}
            print(f"{prob} {variant:18s} {name:18s} {row['status']:10.40s} its {row['iterations']!s:>5} setup {row['setup_s']:8.3f} "
                  f"solve {row['solve_s']:8.3f} total {row['total_s']:8.3f} mem {row['memory_MB']!s:>6} MB", flush=True)
            group.append(row)
            cmds.append(cmd)
        # time to solution over the best other iterative method of the same problem
        for r in group:
            others = [o["total_s"] for o in group if o is not r and o["status"] == "ok" and o["method"] not in DIRECT]
            r["ratio_to_best_other"] = round(r["total_s"] / min(others), 2) if r["status"] == "ok" and others else ""
        rows += group
    return rows, cmds


# 216 ranks of ex71 filled this machine's 23 GB (about 100 MB per rank) without finishing in 3 min
EX71_MAX_RANKS = 125


def scaling():
    """Iterations vs subdomains at H/h = 4: gdsw box subdomains on 2 ranks (b^3 of them, several
    per rank); PETSc's GDSW and gdsw on ex71's MATIS (one subdomain per rank, p^3 ranks)."""
    rows, cmds = [], []
    for b in (2,) if quick else (2, 3, 4, 5, 6):
        # coordinates (PCSetCoordinates): RGDSW's distance weights need them
        runs = {name: f"mpiexec -n 2 {ELASTICITY} -n {4 * b} -boxes {b} -nullspace coords {KRYLOV} -ksp_converged_reason {opts}"
                for name, opts in (("GDSW (2 ranks, box subdomains)", "-pc_type gdsw"),
                                   ("RGDSW (2 ranks, box subdomains)", "-pc_type gdsw -pc_gdsw_coarse_space rgdsw"))}
        ex71 = (f"mpiexec --oversubscribe --mca mpi_yield_when_idle 1 -n {b**3} {EX71} -pde_type Elasticity -dim 3 "
                f"-cells {4 * b - 1},{4 * b - 1},{4 * b - 1} {KRYLOV} -ksp_converged_reason")
        if b**3 <= EX71_MAX_RANKS:
            runs["PETSc GDSW (ex71, 1 per rank)"] = f"{ex71} {PETSC_GDSW}"
            runs["GDSW (ex71 MATIS, 1 per rank)"] = f"{ex71} -dll_append {build}/pc_gdsw/libpetscgdsw.so -pc_type gdsw"
            runs["BDDC deluxe (ex71, 1 per rank)"] = f"{ex71} -pc_type bddc -pc_bddc_use_deluxe_scaling"
        for name, cmd in runs.items():
            r = measure(cmd, 120 if quick else 400)
            print(f"{b**3:4d} subdomains {name:32s} {r['status']:10.40s} its {r['iterations']}", flush=True)
            rows.append({"subdomains": b**3, "method": name, "status": r["status"], "iterations": r["iterations"]})
            cmds.append(cmd)
    return rows, cmds


def sweep():
    """gdsw (GDSW, defaults otherwise) on P1 against METIS subdomains per rank; the faster of two
    runs, against the noise of a shared machine."""
    rows, cmds = [], []
    for n in (8, 12) if quick else (23, 31, 39):
        for k in (1, 2, 4) if quick else (1, 2, 4, 8, 16, 32):
            cmd = f"mpiexec -n 2 {ELASTICITY} -n {n} -pc_gdsw_subdomains {k} {KRYLOV} {MEASURE}"
            r = min((measure(cmd, 60 if quick else 300) for _ in range(2)), key=lambda r: r["total_s"] if r["status"] == "ok" else math.inf)
            dofs = r["dofs"] or 3 * (n + 1) ** 3
            row = {"n": n, "dofs": dofs, "subdomains_per_rank": k, "dofs_per_subdomain": round(dofs / (2 * k)),
                   **{key: r[key] for key in ("status", "iterations", "setup_s", "solve_s", "total_s", "memory_MB")}}
            print(row, flush=True)
            rows.append(row)
            cmds.append(cmd)
    return rows, cmds


def load(name):
    with open(os.path.join(results, name + ".csv")) as f:
        return list(csv.DictReader(f))


def plot_suite(rows):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    keys = list(dict.fromkeys((r["problem"], r["variant"]) for r in rows))
    cols = 4
    fig, axes = plt.subplots(math.ceil(len(keys) / cols), cols, figsize=(5 * cols, 4.2 * math.ceil(len(keys) / cols)), squeeze=False)
    for ax, (prob, variant) in zip(axes.flat, keys):
        group = [r for r in rows if (r["problem"], r["variant"]) == (prob, variant)]
        names = [r["method"] for r in group]
        ok = [r["status"] == "ok" for r in group]
        times = [float(r["total_s"]) if o else 0 for r, o in zip(group, ok)]
        colors = ["tab:red" if r["method"].startswith(("GDSW", "RGDSW", "gdsw")) else "tab:gray" for r in group]
        ax.barh(range(len(group)), times, color=colors)
        longest = max(times) if any(ok) else 1
        for i, (r, o) in enumerate(zip(group, ok)):
            if not o:  # failures stay visible
                ax.text(0.011, i, r["status"].split(":")[0], va="center", fontsize=7)
        ax.set_xscale("log")
        ax.set_xlim(0.01, longest * 3)
        ax.set_yticks(range(len(group)))
        ax.set_yticklabels([f"{n} ({r['iterations']})" for n, r in zip(names, group)], fontsize=7)
        ax.invert_yaxis()
        ax.set_xlabel("total time PCSetUp + KSPSolve (s), log")
        ax.set_title(f"{prob} {variant}", fontsize=9)
        ax.grid(True, axis="x", alpha=0.3)
    for ax in axes.flat[len(keys):]:
        ax.axis("off")
    fig.suptitle("time to solution, 2 MPI ranks, CG rtol 1e-8 (iterations in brackets; red: -pc_type gdsw)")
    fig.tight_layout()
    fig.savefig(os.path.join(results, "gdsw_suite.png"), dpi=100)


def plot_lines(rows, x, y, series, xlabel, ylabel, title, out, logx=False):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    for s in dict.fromkeys(r[series] for r in rows):
        pts = [(float(r[x]), float(r[y])) for r in rows if r[series] == s and r["status"] == "ok"]
        if pts:
            ax.plot(*zip(*pts), "o-", label=str(s))
    if logx:
        ax.set_xscale("log", base=2)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title, fontsize=10)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(results, out + ".png"), dpi=110)


def plot_scaling(rows):
    plot_lines(rows, "subdomains", "iterations", "method", "subdomains", "CG iterations to 1e-8",
               "Q1 elasticity, H/h = 4, overlap 1", "gdsw_suite_scaling")


def plot_sweep(rows):
    rows = [dict(r, series=f"{r['dofs']} dofs") for r in rows]
    plot_lines(rows, "subdomains_per_rank", "total_s", "series", "METIS subdomains per rank (2 ranks)",
               "gdsw total time PCSetUp + KSPSolve (s)", "P1 elasticity: time to solution vs subdomains per rank",
               "gdsw_subdomains_per_rank", logx=True)


def tables():
    """The CSVs as markdown tables (for bench/results/gdsw_suite.md)."""
    lines = []
    rows = load("gdsw_suite")
    for key in dict.fromkeys((r["problem"], r["variant"]) for r in rows):
        group = [r for r in rows if (r["problem"], r["variant"]) == key]
        lines += [f"\n**{key[0]} {key[1]}** ({group[0]['dofs']} dofs)\n",
                  "| preconditioner | status | iterations | setup (s) | solve (s) | total (s) | memory (MB) | total / best other |",
                  "|---|---|---|---|---|---|---|---|"]
        for r in group:
            timed = r["status"] == "ok" or r["status"].startswith("diverged")
            t = [r[c] if timed else "" for c in ("setup_s", "solve_s", "total_s")]
            lines.append(f"| {r['method']} | {r['status']} | {r['iterations']} | {' | '.join(t)} | {r['memory_MB']} | {r['ratio_to_best_other']} |")
    scal = load("gdsw_suite_scaling")
    sizes = sorted({int(r["subdomains"]) for r in scal})
    lines += ["\n| method | " + " | ".join(f"{n} subdomains" for n in sizes) + " |", "|---|" + "---|" * len(sizes)]
    for m in dict.fromkeys(r["method"] for r in scal):
        its = {int(r["subdomains"]): (r["iterations"] if r["status"] == "ok" else r["status"]) for r in scal if r["method"] == m}
        lines.append(f"| {m} | " + " | ".join(str(its.get(n, "")) for n in sizes) + " |")
    sw = load("gdsw_subdomains_per_rank")
    ks = sorted({int(r["subdomains_per_rank"]) for r in sw}, key=int)
    lines += ["\n| dofs | " + " | ".join(f"{k} per rank" for k in ks) + " |", "|---|" + "---|" * len(ks)]
    for d in dict.fromkeys(r["dofs"] for r in sw):
        cell = {int(r["subdomains_per_rank"]): f"{r['total_s']} s ({r['iterations']})" for r in sw if r["dofs"] == d}
        lines.append(f"| {d} | " + " | ".join(cell.get(k, "") for k in ks) + " |")
    print("\n".join(lines))


def main():
    os.makedirs(results, exist_ok=True)
    sweeping = "--sweep" in sys.argv
    parts = [("gdsw_subdomains_per_rank", sweep, plot_sweep)] if sweeping else \
            [("gdsw_suite_scaling", scaling, plot_scaling)] if "--scaling" in sys.argv else \
            [("gdsw_suite", suite, plot_suite), ("gdsw_suite_scaling", scaling, plot_scaling)]
    if "--tables" in sys.argv:
        return tables()
    if "--plot" in sys.argv:
        for name, _, draw in parts:
            draw(load(name))
        return
    loadavg = lambda: " ".join(open("/proc/loadavg").read().split()[:3])
    start = f"# load average (1, 5, 15 min) at start: {loadavg()}"
    outputs = [(name, *measure_part(), draw) for name, measure_part, draw in parts]
    header = [f"# GDSW_BUILD={build}", start, f"# load average (1, 5, 15 min) at end: {loadavg()}"]
    for name, rows, cmds, draw in outputs:
        write_results(os.path.join(results, name), rows, header + cmds, "scripts/bench_gdsw_suite.py " + " ".join(sys.argv[1:]))
        draw(rows)
    print("results in", results)


if __name__ == "__main__":
    main()
