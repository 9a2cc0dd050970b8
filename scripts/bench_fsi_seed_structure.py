#!/usr/bin/python3
# SPDX-License-Identifier: BSD-2-Clause
"""The structure's share of the benchmark-size coupled step: tube #1 at the seed's size
(meshes/tube1_seed_fsi.msh, 1.67 M unknowns), arterial wall, one step of 0.5 ms, FaCSI with the
inexact options (scenes/fsi_inexact_newton.opts), with variants of the structure split's GDSW.
Per run: Newton steps, GMRES per Newton step, seconds (step, assembly, the structure's set-up,
its applications = the GDSWApply event, the rest), peak memory. Each run takes 4-5 minutes and
18 GiB on 2 ranks. Writes bench/results/fsi_seed_structure.{csv,cmd} and each run's -log_view
(fsi_seed_structure_K.log_view.txt).
With --repeat N it runs the scene's variant N times and writes
bench/results/fsi_seed_share_ab.{csv,cmd} with each run and the medians, which settle the
structure's share over the machine's fast and slow phases; with --against DIR (a built checkout
of an earlier commit, meshes/tube1_seed_fsi.msh in it) each of the N rounds also runs that
commit's fsi_app with its scenes, alternating which goes first.
Usage: scripts/bench_fsi_seed_structure.py [--only NAME,...] | --repeat N [--against DIR]"""
import os
import re
import statistics
import subprocess
import sys
import tempfile

from benchlib import TOP, check_command_line, loadavg, run, run_report, step_costs, write_results

check_command_line(__doc__, valued=("--against", "--only", "--repeat"))

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


def measure(cmd, report, log, cwd=TOP):
    """One run's step costs and the structure's applications (the GDSWApply event), or None; run
    in cwd, whose scene files it reads."""
    r = run_report(f"{cmd} -log_view :{log} -report {report}", report, cwd=cwd)
    if r is None:
        return None
    row = step_costs(r)
    m = re.search(r"^GDSWApply\s+\d+ \S+ (\S+)", open(log).read(), re.M)
    row["structure_apply_per_step"] = round(float(m.group(1)) / row["steps"], 1) if m else ""
    row["structure_share_per_step"] = round(row["structure_setup_per_step"] + (row["structure_apply_per_step"] or 0), 1)
    return row


def repeat(rounds, base_dir=None):
    """The scene's variant `rounds` times (alternating with base_dir's commit if given), then the medians."""
    def commit(d):
        return subprocess.run(["git", "-C", d, "rev-parse", "--short", "HEAD"], capture_output=True, text=True).stdout.strip()
    opts = list(VARIANTS.values())[0]
    sides = {commit(TOP): (TOP, BASE)}
    if base_dir:
        sides = {commit(base_dir): (base_dir, BASE.replace(TOP, base_dir)), **sides}
    load, rows, cmds, tmp = loadavg(), [], [], tempfile.mkdtemp()
    for p in range(rounds):
        names = list(sides) if p % 2 == 0 else list(sides)[::-1]
        for name in names:
            cwd, base = sides[name]
            log = os.path.join(TOP, "bench", "results", f"fsi_seed_share_ab_{len(rows)}.log_view.txt")
            row = measure(f"{base} {opts}", os.path.join(tmp, "report.json"), log, cwd)  # the commit's own scene files
            row = {"round": p + 1, "commit": name, "load": loadavg(), **(row or {"converged": 0})}
            print(row, flush=True)
            rows.append(row)
            where = "." if cwd == TOP else f"<checkout of {name}>"
            cmds.append(f"(cd {where} && {base.replace(cwd + '/', '')} {opts} -log_view :{log} -report report.json)")
    for name in sides:
        mine = [r for r in rows if r["commit"] == name and r.get("converged")]
        if mine:
            rows.append({"round": "median", "commit": name, **{k: round(statistics.median(r[k] for r in mine), 2) for k in mine[0] if k not in ("round", "commit", "load", "converged")}})
    write_results(os.path.join(TOP, "bench", "results", "fsi_seed_share_ab"), rows, cmds,
                  f"scripts/bench_fsi_seed_structure.py --repeat {rounds}{' --against <checkout>' if base_dir else ''} (back to back)", load)


def main():
    if not os.path.exists(MESH):
        print(run(os.path.join(TOP, "scripts", "make-meshes") + " tube1 seed_fsi"))
    if "--repeat" in sys.argv:
        base = os.path.abspath(sys.argv[sys.argv.index("--against") + 1]) if "--against" in sys.argv else None
        return repeat(int(sys.argv[sys.argv.index("--repeat") + 1]), base)
    only = sys.argv[sys.argv.index("--only") + 1].split(",") if "--only" in sys.argv else None
    load, rows, cmds = loadavg(), [], []
    tmp = tempfile.mkdtemp()
    for k, (name, opts) in enumerate(VARIANTS.items()):
        if only and not any(name.startswith(o) for o in only):
            continue
        log = os.path.join(TOP, "bench", "results", f"fsi_seed_structure_{k}.log_view.txt")
        row = {"structure_split": name, **(measure(f"{BASE} {opts}", os.path.join(tmp, "report.json"), log) or {"converged": 0})}
        print(row, flush=True)
        rows.append(row)
        cmds.append(f"{BASE} {opts} -log_view :{log} -report report.json")
    write_results(os.path.join(TOP, "bench", "results", "fsi_seed_structure"), rows, cmds,
                  "scripts/bench_fsi_seed_structure.py (one run each, back to back)", load)


if __name__ == "__main__":
    main()
