#!/usr/bin/python3
# SPDX-License-Identifier: BSD-2-Clause
"""The experiment of Heinlein, Klawonn, Rheinbach (2016), Table 2 and Fig. 2, in kind: the
coupled pressure wave in tube #1 solved by Newton + FGMRES with FaCSI (scenes/fsi_facsi.opts),
for the three walls x four time steps, with only the structure split's preconditioner changed:
  (a) ASM       algebraic one-level Schwarz (PCASM, overlap 2, as many blocks as subdomains;
                the role IFPACK plays in the paper)
  (b) OS1       one-level Schwarz with geometric overlap (gdsw without coarse space, overlap 2)
  (c) GDSW-nr   GDSW without rotations (overlap 2)
  (d) GDSW      GDSW (overlap 2)
The same subdomains for all four (-structure_subdomains per rank, 2 ranks), the same geometry
(AMG) and fluid (SIMPLE with AMG) preconditioners. Each run simulates t in [0, T] (--t-final);
per run: Newton steps per time step, GMRES iterations per Newton step, seconds per time step
split into assembly / structure set-up / other set-up / Krylov, and peak memory.
Usage: scripts/bench_fsi_table2.py [--mesh M] [--subdomains N] [--t-final T] [--dts a,b,..]
           [--materials linear,neohooke,arterial] [--pcs a,b,c,d] [--out NAME] [--plot] [--table]
Results: bench/results/<NAME>.{csv,cmd,png} (default NAME fsi_table2); --plot redraws the PNG,
--table prints the paper's layout as markdown (GMRES per Newton step, the paper's in brackets,
and seconds per time step, by material and time step)."""
import argparse
import csv
import os
import sys
import tempfile

from benchlib import loadavg, run_report, step_costs, write_results

top = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
app = os.path.join(os.environ.get("GDSW_BUILD", os.path.join(top, "build")), "fsi_app", "fsi_app")
PCS = {
    "a": ("ASM", "-fieldsplit_structure_pc_type asm -fieldsplit_structure_pc_asm_overlap 2 -fieldsplit_structure_pc_asm_blocks {blocks} "
                 "-fieldsplit_structure_sub_pc_type cholesky -fieldsplit_structure_sub_pc_factor_mat_solver_type cholmod"),
    "b": ("OS1", "-fieldsplit_structure_pc_gdsw_coarse_space none"),
    "c": ("GDSW-nr", "-fieldsplit_structure_pc_gdsw_rotations false"),
    "d": ("GDSW", ""),
}
MATERIALS = {"linear": "LE", "neohooke": "NH", "arterial": "PsiA"}
# the paper's Table 2 (mesh #1, 128 cores): GMRES iterations per Newton step, by material,
# time step and preconditioner (IFPACK, OS1, GDSW-nr, GDSW); None: no convergence
SEED = {
    ("LE", 1e-4): (53.4, 50.8, 51.8, 50.8), ("NH", 1e-4): (89.8, 59.3, 55.0, 52.7), ("PsiA", 1e-4): (214.7, 82.0, 81.0, 79.1),
    ("LE", 2e-4): (95.8, 74.5, 60.7, 58.0), ("NH", 2e-4): (152.4, 87.5, 77.2, 66.0), ("PsiA", 2e-4): (316.7, 96.9, 94.1, 90.7),
    ("LE", 4e-4): (147.2, 124.5, 84.4, 71.9), ("NH", 4e-4): (226.5, 145.7, 117.9, 88.4), ("PsiA", 4e-4): (399.9, 145.4, 135.5, 108.5),
    ("LE", 5e-4): (169.0, 142.0, 93.7, 76.3), ("NH", 5e-4): (261.5, 171.0, 133.2, 96.1), ("PsiA", 5e-4): None,
}


def one(material, dt, pc, args):
    tmp = tempfile.mkdtemp()
    name, opts = PCS[pc]
    cmd = (f"mpiexec -n 2 --mca mpi_yield_when_idle 1 {app} -options_file scenes/fsi_tube1_{material}.opts -options_file scenes/fsi_facsi.opts "
           f"-mesh {args.mesh} -structure_subdomains {args.subdomains} -dt {dt} -t_final {args.t_final} "
           f"{opts.format(blocks=2 * args.subdomains)} -report {tmp}/r.json")
    r = run_report(cmd, f"{tmp}/r.json", args.timeout)
    row = {"material": MATERIALS[material], "dt": dt, "pc": name, "mesh": os.path.basename(args.mesh), "subdomains": 2 * args.subdomains}
    row.update(step_costs(r) if r else {"converged": 0})
    seed = SEED.get((row["material"], dt))
    row["seed_gmres_per_newton"] = "" if seed is None else seed["abcd".index(pc)]
    print({k: (float(f"{v:.4g}") if isinstance(v, float) else v) for k, v in row.items()}, flush=True)
    return row, cmd


def plot(out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = list(csv.DictReader(open(out + ".csv")))
    mats = [m for m in MATERIALS.values() if any(r["material"] == m for r in rows)]
    fig, ax = plt.subplots(2, len(mats), figsize=(4.2 * len(mats), 7), squeeze=False)
    for j, m in enumerate(mats):
        for name, _ in PCS.values():
            sel = sorted((float(r["dt"]), r) for r in rows if r["material"] == m and r["pc"] == name and r["converged"] == "1")
            if not sel:
                continue
            dts = [d * 1e3 for d, _ in sel]
            ax[0][j].plot(dts, [float(r["gmres_per_newton"]) for _, r in sel], "o-", label=name)
            ax[1][j].plot(dts, [float(r["seconds_per_step"]) for _, r in sel], "o-", label=name)
        ax[0][j].set_title(f"{m}, {rows[0]['mesh']}, {rows[0]['subdomains']} subdomains")
        ax[0][j].set_ylabel("GMRES iterations per Newton step")
        ax[1][j].set_ylabel("seconds per time step (2 ranks)")
        ax[1][j].set_xlabel("time step (ms)")
        for a in (ax[0][j], ax[1][j]):
            a.grid(True, alpha=0.3)
            a.legend()
    fig.tight_layout()
    fig.savefig(out + ".png", dpi=110)


def table(out):
    rows = list(csv.DictReader(open(out + ".csv")))
    names = [n for n, _ in PCS.values() if any(r["pc"] == n for r in rows)]
    print("| wall | Δt (ms) | Newton per step | " + " | ".join(f"{n}: GMRES (paper) · s/step" for n in names) + " |")
    print("|---|---|---|" + "---|" * len(names))
    for m in MATERIALS.values():
        for dt in sorted({float(r["dt"]) for r in rows}):
            sel = {r["pc"]: r for r in rows if r["material"] == m and float(r["dt"]) == dt}
            if not sel:
                continue
            newton = "/".join(sorted({f"{float(r['newton_per_step']):.2g}" for r in sel.values() if r["converged"] == "1"}))
            cells = []
            for n in names:
                r = sel.get(n)
                if not r or r["converged"] != "1":
                    cells.append("did not converge" if r else "")
                    continue
                seed = f" ({float(r['seed_gmres_per_newton']):.0f})" if r["seed_gmres_per_newton"] else " (no conv.)"
                cells.append(f"{float(r['gmres_per_newton']):.1f}{seed} · {float(r['seconds_per_step']):.2f}")
            print(f"| {m} | {dt * 1e3:g} | {newton} | " + " | ".join(cells) + " |")


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--mesh", default="meshes/tube1_L0.msh")
    p.add_argument("--subdomains", type=int, default=16, help="per rank (2 ranks)")
    p.add_argument("--t-final", type=float, default=2e-3)
    p.add_argument("--dts", default="1e-4,2e-4,4e-4,5e-4")
    p.add_argument("--materials", default="linear,neohooke,arterial")
    p.add_argument("--pcs", default="a,b,c,d")
    p.add_argument("--timeout", type=float, default=3600)
    p.add_argument("--out", default="fsi_table2")
    p.add_argument("--plot", action="store_true")
    p.add_argument("--table", action="store_true")
    args = p.parse_args()
    out = os.path.join(top, "bench", "results", args.out)
    if args.table:
        return table(out)
    if not args.plot:
        rows, cmds, load = [], [], loadavg()
        for material in args.materials.split(","):
            for dt in [float(d) for d in args.dts.split(",")]:
                for pc in args.pcs.split(","):
                    row, cmd = one(material, dt, pc, args)
                    rows.append(row)
                    cmds.append(cmd)
        keys = max(rows, key=len).keys()
        write_results(out, [{k: r.get(k, "") for k in keys} for r in rows], cmds, " ".join(["scripts/bench_fsi_table2.py"] + sys.argv[1:]), load)
    plot(out)


if __name__ == "__main__":
    main()
