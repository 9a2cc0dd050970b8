#!/usr/bin/python3
# SPDX-License-Identifier: BSD-2-Clause
"""The whole pulse at the benchmark's size in one run: tube #1 (meshes/tube1_seed_fsi.msh), the
arterial wall, backward Euler, dt 0.5 ms to T = 10 ms (20 steps), FaCSI with GDSW and the
inexact Newton options, 2 ranks; probes on the axis and on the inner wall at z = 0.625, 1.25 and
1.875 cm. Writes bench/results/fsi_pulse.{csv,cmd,png}: one row per time step (Newton steps,
GMRES iterations, step cuts, seconds by phase, peak memory after the step),
fsi_pulse_probes.csv (the probes' time series) and fsi_pulse.log (the run's output).

Usage: scripts/bench_fsi_pulse.py [--app PATH] [--plot]   (--plot: redraw from the CSVs)"""
import csv
import json
import os
import subprocess
import sys
import tempfile

from benchlib import ENV, TOP, check_command_line, loadavg, write_results

check_command_line(__doc__, valued=("--app",), flags=("--plot",))

Z = (0.625, 1.25, 1.875)
RI = 0.15  # tube #1's inner radius (scripts/make-meshes)
PROBES = "-fluid_probes " + ",".join(f"0,0,{z}" for z in Z) + " -structure_probes " + ",".join(f"{RI},0,{z}" for z in Z)
OUT = os.path.join(TOP, "bench", "results", "fsi_pulse")


def command(app, report):
    return (f"mpiexec -n 2 {app} -options_file scenes/fsi_tube1_arterial.opts -options_file scenes/fsi_facsi.opts "
            f"-options_file scenes/fsi_inexact_newton.opts -mesh meshes/tube1_seed_fsi.msh -structure_subdomains 64 "
            f"-dt 5e-4 -t_final 1e-2 {PROBES} -report {report}")


def main():
    app = sys.argv[sys.argv.index("--app") + 1] if "--app" in sys.argv else os.path.join(TOP, "install", "bin", "fsi_app")
    if not os.path.exists(os.path.join(TOP, "meshes", "tube1_seed_fsi.msh")):  # before the log is written over
        sys.exit("bench_fsi_pulse: meshes/tube1_seed_fsi.msh is missing; scripts/make-meshes tube1 seed_fsi makes it")
    report = os.path.join(tempfile.mkdtemp(), "report.json")
    cmd, load = command(app, report), loadavg()
    with open(OUT + ".log", "w") as log:  # the run's progress, one line per step, as it comes
        p = subprocess.run(cmd.split(), env=ENV, cwd=TOP, stdout=log, stderr=subprocess.STDOUT)
    if not os.path.exists(report):
        sys.exit(f"bench_fsi_pulse: the run wrote no report (exit {p.returncode}); see {OUT}.log")
    r = json.load(open(report))
    rows = []
    for s in r["steps"]:
        sec = s["seconds"]
        structure = sec.get("setup_structure", 0.0)
        rows.append({"step": s["step"], "t": s["t"], "newton": s["newton"], "gmres": s["krylov"], "cuts": s["cuts"], "reason": s["reason"],
                     "seconds": sec["total"], "assembly": sec["assembly"], "structure_setup": structure,
                     "other_setup": round(sec["preconditioner_setup"] - structure, 4), "krylov": sec["krylov"],
                     "peak_memory_mib": s["peak_memory_mib"]})
    write_results(OUT, rows, [command(app.replace(TOP + "/", ""), report)], "scripts/bench_fsi_pulse.py (one run)", load)
    series = {s["field"]: s for s in r["probes"]}
    p, d = series["pressure"], series["displacement"]
    with open(OUT + "_probes.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["t"] + [f"pressure_z{z}" for z in Z] + [f"radial_displacement_z{z}" for z in Z])
        n = len(Z)
        for k, t in enumerate(p["t"]):
            w.writerow([t] + [p["values"][p["components"] * (n * k + i)] for i in range(n)] +
                       [d["values"][d["components"] * (n * k + i)] for i in range(n)])  # x: radial at (RI, 0, z)
    print(f"steps {len(rows)}, total {r['seconds']['total']:.0f} s, peak memory {r['peak_memory_mib']:.0f} MiB, "
          f"arrivals {[r['results'].get(f'arrival_{i}') for i in range(len(Z))]}")
    plot()


def plot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    steps = list(csv.DictReader(open(OUT + ".csv")))
    probes = list(csv.DictReader(open(OUT + "_probes.csv")))
    fig, ax = plt.subplots(1, 3, figsize=(15, 4.2))
    t = [1e3 * float(x["t"]) for x in probes]
    for z in Z:
        ax[0].plot(t, [float(x[f"pressure_z{z}"]) for x in probes], label=f"z = {z} cm")
        ax[1].plot(t, [1e4 * float(x[f"radial_displacement_z{z}"]) for x in probes], label=f"z = {z} cm")
    ax[0].set(xlabel="t (ms)", ylabel="pressure on the axis (dyn/cm²)")
    ax[1].set(xlabel="t (ms)", ylabel="inner wall's radial displacement (µm)")
    k = [int(x["step"]) for x in steps]
    bottom = [0.0] * len(steps)
    for key, name in (("assembly", "assembly"), ("structure_setup", "structure set-up (GDSW)"), ("other_setup", "other set-up"), ("krylov", "Krylov")):
        v = [float(x[key]) for x in steps]
        ax[2].bar(k, v, bottom=bottom, label=name)
        bottom = [b + y for b, y in zip(bottom, v)]
    for x in steps:
        ax[2].text(int(x["step"]), float(x["seconds"]) * 1.01, f"{x['newton']}/{x['gmres']}", ha="center", fontsize=6)
    ax[2].set(xlabel="time step (labels: Newton / GMRES)", ylabel="seconds")
    for a in ax:
        a.grid(alpha=0.3)
        a.legend(fontsize=8)
    total = sum(float(x["seconds"]) for x in steps)
    fig.suptitle(f"tube #1 at the benchmark's size, arterial wall, dt 0.5 ms, 2 ranks: {len(steps)} steps in {total / 60:.1f} min, "
                 f"peak memory {max(float(x['peak_memory_mib']) for x in steps) / 1024:.1f} GiB", fontsize=10)
    fig.tight_layout()
    fig.savefig(OUT + ".png", dpi=110)


if __name__ == "__main__":
    plot() if "--plot" in sys.argv else main()
