#!/usr/bin/python3
# SPDX-License-Identifier: BSD-2-Clause
"""The structure's share of the benchmark-size coupled step: tube #1 at the seed's size
(meshes/tube1_seed_fsi.msh, 1.67 M unknowns), arterial wall, one step of 0.5 ms, FaCSI with the
inexact options (scenes/fsi_inexact_newton.opts), with variants of the structure split's GDSW.
Per run: Newton steps, GMRES per Newton step, seconds (step, assembly, the structure's set-up,
its applications = the GDSWApply event, the rest), peak memory. Each run takes 4-5 minutes and
18 GiB on 2 ranks. Writes bench/results/fsi_seed_structure.{csv,cmd} and each run's -log_view
(fsi_seed_structure_K.log_view.txt).
Usage: scripts/bench_fsi_seed_structure.py [--only NAME,...]"""
import os
import re
import sys
import tempfile

from benchlib import TOP, loadavg, run, run_report, step_costs, write_results

APP = os.path.join(TOP, "install", "bin", "fsi_app")
MESH = os.path.join(TOP, "meshes", "tube1_seed_fsi.msh")
BASE = (f"mpiexec -n 2 {APP} -options_file scenes/fsi_tube1_arterial.opts -options_file scenes/fsi_facsi.opts "
        f"-options_file scenes/fsi_inexact_newton.opts -mesh {MESH} -dt 5e-4 -t_final 5e-4 -snes_monitor -ksp_converged_reason")
VARIANTS = {
    "GDSW, 64 subdomains per rank (the scene's)": "-structure_subdomains 64",
    "GDSW, 64 per rank, double-precision factors, GMRES (the scene before)": "-structure_subdomains 64 -fieldsplit_structure_pc_gdsw_local_precision double -ksp_type gmres",
    "RGDSW, 64 per rank": "-structure_subdomains 64 -fieldsplit_structure_pc_gdsw_coarse_space rgdsw",
    "GDSW, 32 per rank": "-structure_subdomains 32",
}


def main():
    if not os.path.exists(MESH):
        print(run(os.path.join(TOP, "scripts", "make-meshes") + " tube1 seed_fsi"))
    only = sys.argv[sys.argv.index("--only") + 1].split(",") if "--only" in sys.argv else None
    load, rows, cmds = loadavg(), [], []
    tmp = tempfile.mkdtemp()
    for k, (name, opts) in enumerate(VARIANTS.items()):
        if only and not any(name.startswith(o) for o in only):
            continue
        report = os.path.join(tmp, "report.json")
        log = os.path.join(TOP, "bench", "results", f"fsi_seed_structure_{k}.log_view.txt")
        cmd = f"{BASE} {opts} -log_view :{log} -report {report}"
        r = run_report(cmd, report)
        row = {"structure_split": name}
        if r is None:
            row["converged"] = 0
        else:
            row.update(step_costs(r))
            m = re.search(r"^GDSWApply\s+\d+ \S+ (\S+)", open(log).read(), re.M)
            row["structure_apply_per_step"] = round(float(m.group(1)) / row["steps"], 1) if m else ""
            row["structure_share_per_step"] = round(row["structure_setup_per_step"] + (row["structure_apply_per_step"] or 0), 1)
        print(row, flush=True)
        rows.append(row)
        cmds.append(cmd)
    write_results(os.path.join(TOP, "bench", "results", "fsi_seed_structure"), rows, cmds,
                  "scripts/bench_fsi_seed_structure.py (one run each, back to back)", load)


if __name__ == "__main__":
    main()
