#!/usr/bin/python3
# SPDX-License-Identifier: BSD-2-Clause
"""The fluid block's linear solver as the mesh is refined twice and the step varies: the seed's
inflow pulse in the rigid tube #1 (fluid alone, backward Euler, 4 steps; tube1_L0-L2, make-meshes
makes L2), FGMRES with the fieldsplit Schur/selfp + BoomerAMG preconditioner of
scenes/fluid_schur.opts and SIMPLE (scenes/fluid_simple.opts) against a MUMPS direct solve (on L2 at one step size: its factorisation
is the cost): Newton steps per time step, Krylov iterations per Newton step, time per step split
into assembly, set-up and iterations (from the run report), peak memory. 2 MPI ranks.
Writes bench/results/fluid_solver.{csv,cmd}.
`seed`: the fluid of tube #1 at the seed's size (make-meshes tube1 seed_fluid: ~390 k velocity
dofs), fieldsplit, 2 steps of 5e-4 -> bench/results/fluid_seed.{csv,cmd}.
Usage: scripts/bench_fluid.py [seed]"""
import json
import os
import subprocess
import sys
import tempfile

from benchlib import check_command_line, run, write_results

check_command_line(__doc__, modes=("seed",))

top = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
app = os.path.join(os.environ.get("GDSW_BUILD", os.path.join(top, "build")), "fsi_app", "fsi_app")
SOLVERS = {"fieldsplit (Schur selfp, BoomerAMG)": "",
           "SIMPLE (fieldsplit, BoomerAMG)": f"-options_file {top}/scenes/fluid_simple.opts",
           "MUMPS (direct)": "-ksp_type preonly -pc_type lu -pc_factor_mat_solver_type mumps"}


def main():
    seed = sys.argv[1:] == ["seed"]
    rows, cmds = [], []
    report = os.path.join(tempfile.mkdtemp(), "r.json")
    load = subprocess.run(["uptime"], stdout=subprocess.PIPE, text=True).stdout.strip()
    for mesh, level in ((("tube1_seed_fluid", "seed_fluid"),) if seed else (("tube1_L0", "0"), ("tube1_L1", "1"), ("tube1_L2", "2"))):
        if not os.path.exists(f"{top}/meshes/{mesh}.msh"):
            subprocess.run([f"{top}/scripts/make-meshes", "tube1", level], check=True)
        for dt in (("5e-4",) if seed else ("1e-4", "5e-4", "2e-3")):
            for name, opts in SOLVERS.items():
                if (seed or mesh == "tube1_L2") and "MUMPS" in name and (seed or dt != "5e-4") or seed and "SIMPLE" in name:
                    continue
                steps = 2 if seed else 4
                cmd = (f"mpiexec -n 2 {app} -options_file {top}/scenes/fluid_tube1_pulse.opts -mesh {top}/meshes/{mesh}.msh "
                       f"-dt {dt} -t_final {steps * float(dt)} {opts} -report {report}")
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
    name = "fluid_seed" if seed else "fluid_solver"
    write_results(os.path.join(top, "bench", "results", name), rows, cmds, f"scripts/bench_fluid.py{' seed' if seed else ''} (load: {load})")


if __name__ == "__main__":
    main()
