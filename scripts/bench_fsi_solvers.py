#!/usr/bin/python3
# SPDX-License-Identifier: BSD-2-Clause
"""The coupled tube #1 (linear wall, scenes/fsi_tube1_linear.opts), 2 MPI ranks.
  solvers: FaCSI (scenes/fsi_facsi.opts) against MUMPS on the whole Jacobian
           (scenes/fsi_mumps.opts) and the multiplicative fieldsplit with MUMPS on the
           structure and fluid splits (scenes/fsi_fieldsplit.opts), on tube1_L0 and tube1_L1,
           Delta t = 0.5 ms, 2 time steps: GMRES per Newton step, seconds per time step and
           its parts, peak memory -> bench/results/fsi_solvers.{csv,cmd}
  setup:   how often the structure split's GDSW is set up (-structure_pc_setup every_newton,
           every_step, once) for the linear and the arterial wall, FaCSI, tube1_L1 with 128
           subdomains, Delta t = 0.5 ms, 3 time steps -> bench/results/fsi_setup_reuse.{csv,cmd}
  per_core: one rank, tube1_L1, backward Euler, Delta t = 0.1 ms, the first 20 steps: MUMPS with
           its Jacobian kept for up to 30 Newton steps (scenes/fsi_mumps_lagged.opts) against
           FaCSI with GDSW (16 subdomains), with and without the inexact options
           -> bench/results/fsi_per_core.{csv,cmd}
Usage: scripts/bench_fsi_solvers.py [solvers|setup|per_core]
(the paper's Figs. 3-4, iterations against structure subdomains: scripts/bench_fsi_scalability.py)"""
import os
import sys
import tempfile

from benchlib import check_command_line, loadavg, run_report, step_costs, write_results

check_command_line(__doc__, modes=("solvers", "setup", "per_core"))

top = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
app = os.path.join(os.environ.get("GDSW_BUILD", os.path.join(top, "build")), "fsi_app", "fsi_app")
SOLVERS = {
    "MUMPS": "",
    "fieldsplit (MUMPS | GAMG | MUMPS)": "-options_file scenes/fsi_fieldsplit.opts",
    "FaCSI (GDSW | GAMG | SIMPLE)": "-options_file scenes/fsi_facsi.opts -structure_subdomains 16",
}


PER_CORE = {
    "MUMPS, Jacobian kept up to 30 Newton steps": "-options_file scenes/fsi_mumps_lagged.opts",
    "FaCSI (GDSW | GAMG | SIMPLE)": "-options_file scenes/fsi_facsi.opts -structure_subdomains 16",
    "FaCSI, inexact options": "-options_file scenes/fsi_facsi.opts -options_file scenes/fsi_inexact_newton.opts -structure_subdomains 16",
}


def coupled(opts, material="linear", ranks=2):
    report = os.path.join(tempfile.mkdtemp(), "r.json")
    cmd = f"mpiexec -n {ranks} --mca mpi_yield_when_idle 1 {app} -options_file scenes/fsi_tube1_{material}.opts {opts} -report {report}"
    r = run_report(cmd, report, timeout=3600)
    return (step_costs(r) if r else {"converged": 0}), cmd


def solvers():
    rows, cmds, load = [], [], loadavg()
    for mesh in ("tube1_L0", "tube1_L1"):
        for name, opts in SOLVERS.items():
            row, cmd = coupled(f"{opts} -mesh meshes/{mesh}.msh -dt 5e-4 -t_final 1e-3")
            rows.append(dict({"mesh": mesh, "solver": name}, **row))
            cmds.append(cmd)
            print(rows[-1], flush=True)
    write_results(os.path.join(top, "bench", "results", "fsi_solvers"), rows, cmds, "scripts/bench_fsi_solvers.py solvers", load)


def setup():
    rows, cmds, load = [], [], loadavg()
    for material, policies in (("linear", ("every_newton", "every_step", "once")), ("arterial", ("every_newton", "every_step"))):
        for policy in policies:
            row, cmd = coupled(f"-options_file scenes/fsi_facsi.opts -mesh meshes/tube1_L1.msh "
                               f"-structure_subdomains 64 -dt 5e-4 -t_final 1.5e-3 -structure_pc_setup {policy}", material)
            rows.append(dict({"material": material, "structure_pc_setup": policy}, **row))
            cmds.append(cmd)
            print(rows[-1], flush=True)
    write_results(os.path.join(top, "bench", "results", "fsi_setup_reuse"), rows, cmds, "scripts/bench_fsi_solvers.py setup", load)


def per_core():
    rows, cmds, load = [], [], loadavg()
    for name, opts in PER_CORE.items():
        row, cmd = coupled(f"{opts} -mesh meshes/tube1_L1.msh -dt 1e-4 -t_final 2e-3", ranks=1)
        rows.append(dict({"solver": name}, **row))
        cmds.append(cmd)
        print(rows[-1], flush=True)
    write_results(os.path.join(top, "bench", "results", "fsi_per_core"), rows, cmds, "scripts/bench_fsi_solvers.py per_core", load)


if __name__ == "__main__":
    mode = sys.argv[1] if len(sys.argv) > 1 else "solvers"
    {"solvers": solvers, "setup": setup, "per_core": per_core}[mode]()
