#!/usr/bin/python3
# SPDX-License-Identifier: BSD-2-Clause
"""Error against run time, one line per preconditioner (points: mesh levels), 2 MPI ranks. Time
is the solve loop's wall clock from the run report (assembly + set-up + iterations), error the
relative L2 norm of the displacement or velocity against the exact solution.
  structure: Lame's cylinder (quarter, levels 0-2) and the manufactured solution on the unit
             cube (refined 0-2), linear elastic P2, CG to rtol 1e-10 -> bench/results/work_precision.*
  fluid:     the manufactured Navier-Stokes flow on the cube displaced by the harmonic field
             (refined 0-2), steady and with the mesh moving under it (4 BDF2 steps), and the
             unsteady flow on the moving mesh with dt ~ h^1.5 (BDF2's error then falls like the
             spatial h^3), FGMRES to rtol 1e-8 -> bench/results/work_precision_fluid.*
  poiseuille: Hagen-Poiseuille flow in the rigid tube #1 (tube1_L0-L2; make-meshes makes L2),
             FGMRES to rtol 1e-8 -> bench/results/work_precision_poiseuille.*
The coupled problem's study is scripts/bench_fsi_work_precision.py.
Usage: scripts/bench_work_precision.py [structure|fluid|poiseuille] [--plot]
(--plot redraws the PNG from the CSV)"""
import csv
import math
import os
import subprocess
import sys
import tempfile

from benchlib import check_command_line, run_report, write_results

check_command_line(__doc__, modes=("structure", "fluid", "poiseuille"), flags=("--plot",))

top = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
app = os.path.join(os.environ.get("GDSW_BUILD", os.path.join(top, "build")), "fsi_app", "fsi_app")
ALE = f"-options_file {top}/scenes/fluid_ale_mms_cube.opts"
FAMILIES = {
    "structure": {
        "out": "work_precision", "unknowns": ("structure",), "solver": "-ksp_rtol 1e-10",
        "pcs": {
            "gdsw": "-ksp_type cg -pc_type gdsw",
            "PCASM": "-ksp_type cg -pc_type asm -pc_asm_overlap 1 -pc_asm_type basic -sub_pc_type cholesky -sub_pc_factor_mat_solver_type cholmod",
            "GAMG": "-ksp_type cg -pc_type gamg",
            "MUMPS (direct)": "-ksp_type preonly -pc_type cholesky -pc_factor_mat_solver_type mumps",
        },
        "scenes": {
            "Lame cylinder": [f"-options_file {top}/scenes/lame_cylinder.opts -mesh {top}/meshes/quarter_cylinder_L{k}.msh" for k in range(3)],
            "manufactured (cube)": [f"-options_file {top}/scenes/mms_elasticity_cube.opts -refine {k}" for k in range(3)],
        },
    },
    "fluid": {
        "out": "work_precision_fluid", "unknowns": ("fluid", "pressure", "geometry"), "solver": "-ksp_rtol 1e-8",
        "pcs": {
            "fieldsplit: GAMG | Schur selfp, BoomerAMG": "-fieldsplit_fluid_pc_type fieldsplit",
            "fieldsplit: GAMG | flow by MUMPS": "",
            "MUMPS (direct, monolithic)": "-ksp_type preonly -pc_type lu -pc_factor_mat_solver_type mumps",
        },
        "scenes": {
            "manufactured flow, displaced cube": [f"{ALE} -refine {k}" for k in range(3)],
            "the same, mesh moving (4 BDF2 steps)": [f"{ALE} -refine {k} -dt 0.25 -t_final 1 -geometry_ramp 1" for k in range(3)],
            "unsteady flow, mesh moving, dt ~ h^1.5 (4/11/32 steps)": [f"{ALE} -refine {k} -dt {dt:.10g} -t_final 1 -geometry_ramp 1 -mms_ramp 1" for k, dt in ((0, 1 / 4), (1, 1 / 11), (2, 1 / 32))],
        },
    },
    "poiseuille": {
        "out": "work_precision_poiseuille", "unknowns": ("fluid", "pressure"), "solver": "-ksp_rtol 1e-8",
        "pcs": {
            "fieldsplit: Schur selfp, BoomerAMG": "",
            "MUMPS (direct)": "-ksp_type preonly -pc_type lu -pc_factor_mat_solver_type mumps",
        },
        "scenes": {
            "Poiseuille, rigid tube #1": [f"-options_file {top}/scenes/fluid_poiseuille.opts -mesh {top}/meshes/tube1_L{k}.msh" for k in range(3)],
        },
    },
}
FAMILY = next((a for a in sys.argv[1:] if a in FAMILIES), "structure")
PCS, SCENES = FAMILIES[FAMILY]["pcs"], FAMILIES[FAMILY]["scenes"]
out = os.path.join(top, "bench", "results", FAMILIES[FAMILY]["out"])


def main():
    if "--plot" in sys.argv:
        with open(out + ".csv") as f:
            plot(list(csv.DictReader(f)))
        return
    rows, cmds = [], []
    report = os.path.join(tempfile.mkdtemp(), "r.json")
    if FAMILY == "poiseuille" and not os.path.exists(f"{top}/meshes/tube1_L2.msh"):
        subprocess.run([f"{top}/scripts/make-meshes", "tube1", "2"], check=True)
    for scene, levels in SCENES.items():
        for level, sopts in enumerate(levels):
            for pc, popts in PCS.items():
                cmd = f"mpiexec -n 2 {app} {sopts} {popts} {FAMILIES[FAMILY]['solver']} -report {report}"
                r = run_report(cmd, report, 1800)
                if not r:
                    continue
                row = {"scene": scene, "level": level, "preconditioner": pc, "dofs": sum(r["unknowns"][u] for u in FAMILIES[FAMILY]["unknowns"]),
                       "l2_relative": r["results"]["l2_relative"], "h1_relative": r["results"]["h1_relative"],
                       "pressure_l2_relative": r["results"].get("pressure_l2_relative", ""),
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
    fig, axes = plt.subplots(1, len(SCENES), figsize=(5.5 * len(SCENES), 4.2), squeeze=False)
    for ax, scene in zip(axes[0], SCENES):
        for pc in PCS:
            pts = sorted((int(r["dofs"]), float(r["seconds"]), float(r["l2_relative"])) for r in rows if r["scene"] == scene and r["preconditioner"] == pc)
            if pts:  # joined in the order of the mesh levels
                ax.loglog([p[1] for p in pts], [p[2] for p in pts], "o-", label=pc)
        ax.set_title(f"{scene}, P2, 2 ranks", fontsize=9)
        ax.set_xlabel("time to solution (s)")
        ax.set_ylabel("relative L2 error")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend()
    fig.tight_layout()
    fig.savefig(out + ".png", dpi=110)


if __name__ == "__main__":
    main()
