#!/usr/bin/python3
"""Error against run time for the structure's verification scenes: Lame's cylinder (quarter,
levels 0-2) and the manufactured solution on the unit cube (refined 0-2), linear elastic P2,
one line per preconditioner (points: mesh levels), 2 MPI ranks, CG to rtol 1e-10. Time is the
solve loop's wall clock from the run report (assembly + set-up + iterations), error the
relative L2 norm against the exact solution. Writes bench/results/work_precision.{csv,cmd,png}.
Usage: scripts/bench_work_precision.py [--plot]   (--plot redraws the PNG from the CSV)"""
import csv
import json
import os
import sys
import tempfile

from benchlib import run, write_results

top = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
app = os.path.join(os.environ.get("GDSW_BUILD", os.path.join(top, "build")), "fsi_app", "fsi_app")
out = os.path.join(top, "bench", "results", "work_precision")

PCS = {
    "gdsw": "-ksp_type cg -pc_type gdsw",
    "PCASM": "-ksp_type cg -pc_type asm -pc_asm_overlap 1 -pc_asm_type basic -sub_pc_type cholesky -sub_pc_factor_mat_solver_type cholmod",
    "GAMG": "-ksp_type cg -pc_type gamg",
    "MUMPS (direct)": "-ksp_type preonly -pc_type cholesky -pc_factor_mat_solver_type mumps",
}
SCENES = {
    "Lame cylinder": [f"-options_file {top}/scenes/lame_cylinder.opts -mesh {top}/meshes/quarter_cylinder_L{k}.msh" for k in range(3)],
    "manufactured (cube)": [f"-options_file {top}/scenes/mms_elasticity_cube.opts -refine {k}" for k in range(3)],
}


def main():
    if "--plot" in sys.argv:
        with open(out + ".csv") as f:
            plot(list(csv.DictReader(f)))
        return
    rows, cmds = [], []
    report = os.path.join(tempfile.mkdtemp(), "r.json")
    for scene, levels in SCENES.items():
        for level, sopts in enumerate(levels):
            for pc, popts in PCS.items():
                cmd = f"mpiexec -n 2 {app} {sopts} {popts} -ksp_rtol 1e-10 -report {report}"
                if os.path.exists(report):
                    os.remove(report)
                log = run(cmd, timeout=1800)
                if not os.path.exists(report):
                    print(log[-1500:])
                    continue
                r = json.load(open(report))
                row = {"scene": scene, "level": level, "preconditioner": pc, "dofs": r["unknowns"]["structure"],
                       "l2_relative": r["results"]["l2_relative"], "h1_relative": r["results"]["h1_relative"],
                       "seconds": r["seconds"]["total"], "krylov": sum(s["krylov"] for s in r["steps"]), "peak_memory_mib": r["peak_memory_mib"]}
                print(row, flush=True)
                rows.append(row)
                cmds.append(cmd)
    write_results(out, rows, cmds, "scripts/bench_work_precision.py")
    plot(rows)


def plot(rows):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, len(SCENES), figsize=(11, 4.2))
    for ax, scene in zip(axes, SCENES):
        for pc in PCS:
            pts = sorted((int(r["dofs"]), float(r["seconds"]), float(r["l2_relative"])) for r in rows if r["scene"] == scene and r["preconditioner"] == pc)
            if pts:  # joined in the order of the mesh levels
                ax.loglog([p[1] for p in pts], [p[2] for p in pts], "o-", label=pc)
        ax.set_title(f"{scene}, P2, 2 ranks")
        ax.set_xlabel("time to solution (s)")
        ax.set_ylabel("relative L2 error")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend()
    fig.tight_layout()
    fig.savefig(out + ".png", dpi=110)


if __name__ == "__main__":
    main()
