#!/usr/bin/python3
"""The fluid block's linear solver as the mesh is refined and the step varies: the seed's inflow
pulse in the rigid tube #1 (fluid alone, backward Euler, 4 steps), FGMRES with the fieldsplit
Schur/selfp + BoomerAMG preconditioner of scenes/fluid_simple.opts against a MUMPS direct solve:
Newton steps per time step, Krylov iterations per Newton step, time per step split into
assembly, set-up and iterations (from the run report), peak memory. 2 MPI ranks.
Writes bench/results/fluid_solver.{csv,cmd}.   Usage: scripts/bench_fluid.py"""
import json
import os
import subprocess
import tempfile

from benchlib import run, write_results

top = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
app = os.path.join(os.environ.get("GDSW_BUILD", os.path.join(top, "build")), "fsi_app", "fsi_app")
SOLVERS = {"fieldsplit (Schur selfp, BoomerAMG)": "",
           "MUMPS (direct)": "-ksp_type preonly -pc_type lu -pc_factor_mat_solver_type mumps"}


def main():
    rows, cmds = [], []
    report = os.path.join(tempfile.mkdtemp(), "r.json")
    load = subprocess.run(["uptime"], stdout=subprocess.PIPE, text=True).stdout.strip()
    for mesh in ("tube1_L0", "tube1_L1"):
        for dt in ("1e-4", "5e-4", "2e-3"):
            for name, opts in SOLVERS.items():
                cmd = (f"mpiexec -n 2 {app} -options_file {top}/scenes/fluid_tube1_pulse.opts -mesh {top}/meshes/{mesh}.msh "
                       f"-dt {dt} -t_final {4 * float(dt)} {opts} -report {report}")
                if os.path.exists(report):
                    os.remove(report)
                log = run(cmd, timeout=1800)
                row = {"mesh": mesh, "dt": dt, "solver": name}
                if not os.path.exists(report):
                    print(log[-1500:])
                    row["newton_per_step"] = "failed"
                else:
                    r = json.load(open(report))
                    steps, sec = r["steps"], r["seconds"]
                    newton = sum(s["newton"] for s in steps)
                    row.update(velocity_dofs=r["unknowns"]["fluid"], pressure_dofs=r["unknowns"]["pressure"],
                               newton_per_step=round(newton / len(steps), 2), krylov_per_newton=round(sum(s["krylov"] for s in steps) / newton, 1),
                               time_per_step_s=round(sec["total"] / len(steps), 3), assembly_per_step_s=round(sec["assembly"] / len(steps), 3),
                               setup_per_step_s=round(sec["preconditioner_setup"] / len(steps), 3), krylov_per_step_s=round(sec["krylov"] / len(steps), 3),
                               peak_memory_mib=r["peak_memory_mib"])
                print(row, flush=True)
                rows.append(row)
                cmds.append(cmd)
    load += " / after: " + subprocess.run(["uptime"], stdout=subprocess.PIPE, text=True).stdout.strip()
    write_results(os.path.join(top, "bench", "results", "fluid_solver"), rows, cmds, f"scripts/bench_fluid.py (load: {load})")


if __name__ == "__main__":
    main()
