#!/usr/bin/python3
# SPDX-License-Identifier: BSD-2-Clause
"""The coupled tube #1 (linear wall, scenes/fsi_tube1_linear.opts), 2 MPI ranks.
  solvers: FaCSI (scenes/fsi_facsi.opts) against MUMPS on the whole Jacobian
           (scenes/fsi_mumps.opts) and the multiplicative fieldsplit with MUMPS on the
           structure and fluid splits (scenes/fsi_fieldsplit.opts), on tube1_L0 and tube1_L1,
           Delta t = 0.5 ms, 2 time steps: GMRES per Newton step, seconds per time step and
           its parts, peak memory -> bench/results/fsi_solvers.{csv,cmd}
  scaling: the paper's Figs. 3-4 in iterations: GMRES iterations per Newton step of FaCSI
           with GDSW on the structure for 16 ... 256 structure subdomains (8 ... 128 per rank)
           and overlap 1 and 2, tube1_L1, Delta t = 0.2 ms, 2 time steps
           -> bench/results/fsi_scaling.{csv,cmd,png}
  setup:   how often the structure split's GDSW is set up (-structure_pc_setup every_newton,
           every_step, once) for the linear and the arterial wall, FaCSI, tube1_L1 with 128
           subdomains, Delta t = 0.5 ms, 3 time steps -> bench/results/fsi_setup_reuse.{csv,cmd}
Usage: scripts/bench_fsi_solvers.py [solvers|scaling|setup] [--plot]"""
import csv
import os
import sys
import tempfile

from benchlib import loadavg, run_report, step_costs, write_results

top = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
app = os.path.join(os.environ.get("GDSW_BUILD", os.path.join(top, "build")), "fsi_app", "fsi_app")
SOLVERS = {
    "MUMPS": "",
    "fieldsplit (MUMPS | GAMG | MUMPS)": "-options_file scenes/fsi_fieldsplit.opts",
    "FaCSI (GDSW | GAMG | SIMPLE)": "-options_file scenes/fsi_facsi.opts -structure_subdomains 16",
}


def coupled(opts, material="linear"):
    report = os.path.join(tempfile.mkdtemp(), "r.json")
    cmd = f"mpiexec -n 2 --mca mpi_yield_when_idle 1 {app} -options_file scenes/fsi_tube1_{material}.opts {opts} -report {report}"
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


def scaling():
    rows, cmds, load = [], [], loadavg()
    for overlap in (1, 2):
        for per_rank in (8, 16, 32, 64, 128):
            row, cmd = coupled(f"-options_file scenes/fsi_facsi.opts -mesh meshes/tube1_L1.msh -dt 2e-4 -t_final 4e-4 "
                               f"-structure_subdomains {per_rank} -fieldsplit_structure_pc_gdsw_overlap {overlap}")
            rows.append(dict({"subdomains": 2 * per_rank, "overlap": overlap}, **row))
            cmds.append(cmd)
            print(rows[-1], flush=True)
    out = os.path.join(top, "bench", "results", "fsi_scaling")
    write_results(out, rows, cmds, "scripts/bench_fsi_solvers.py scaling", load)
    plot_scaling(out)


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


def plot_scaling(out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = list(csv.DictReader(open(out + ".csv")))
    fig, ax = plt.subplots(figsize=(5.5, 4))
    for overlap in ("1", "2"):
        sel = [r for r in rows if r["overlap"] == overlap]
        ax.plot([int(r["subdomains"]) for r in sel], [float(r["gmres_per_newton"]) for r in sel], "o-", label=f"GDSW, overlap {overlap}")
    ax.set_xscale("log", base=2)
    ax.set_xlabel("structure subdomains (2 ranks)")
    ax.set_ylabel("GMRES iterations per Newton step")
    ax.set_title("FaCSI, tube1_L1, linear wall, dt = 0.2 ms")
    ax.set_ylim(bottom=0)
    ax.grid(True, alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(out + ".png", dpi=110)


if __name__ == "__main__":
    mode = sys.argv[1] if len(sys.argv) > 1 else "solvers"
    if "--plot" in sys.argv:
        plot_scaling(os.path.join(top, "bench", "results", "fsi_scaling"))
    else:
        {"solvers": solvers, "scaling": scaling, "setup": setup}[mode]()
