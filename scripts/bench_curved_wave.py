#!/usr/bin/python3
# SPDX-License-Identifier: BSD-2-Clause
"""The coupled pressure wave in tube #1 on straight and on curved (isoparametric P2) cells, at
mesh levels 0 and 1 (meshes/tube1_L{0,1}_o2.msh; -mesh_order 1 reads them straight): linear
wall, FaCSI (scenes/fsi_facsi.opts), backward Euler, dt 0.1 ms to 10 ms, probes on the axis and
in the wall's middle at z = 0.625, 1.25, 1.875 cm. Per run: unknowns, the front's arrival
(the axis pressure reaching half the inlet's) and the first peaks of axis pressure and of the
wall's radial displacement at each station (the first local maximum above half the largest),
seconds (total, assembly per Newton step).
Writes bench/results/fsi_curved_wave.{csv,cmd}. Usage: scripts/bench_curved_wave.py"""
import os
import tempfile

from benchlib import TOP, check_command_line, loadavg, run_report, write_results

check_command_line(__doc__)

APP = os.path.join(TOP, "install", "bin", "fsi_app")
Z = (0.625, 1.25, 1.875)
PROBES = "-fluid_probes " + ",".join(f"0,0,{z}" for z in Z) + " -structure_probes " + ",".join(f"0.18,0,{z}" for z in Z)
BASE = (f"mpiexec -n 2 {APP} -options_file scenes/fsi_tube1_linear.opts -options_file scenes/fsi_facsi.opts "
        f"-structure_subdomains 16 -dt 1e-4 -t_final 1e-2 {PROBES}")


def first_peaks(series, component):
    """Per point, the first local maximum of the component over time above half its largest
    value (the pulse's first peak, not the noise before the front), and its time."""
    n, nc, t = len(series["points"]) // 3, series["components"], series["t"]
    peaks = []
    for i in range(n):
        x = [series["values"][nc * (n * k + i) + component] for k in range(len(t))]
        k = next((k for k in range(1, len(x) - 1) if x[k - 1] < x[k] >= x[k + 1] and x[k] > max(x) / 2), len(x) - 1)
        peaks.append((x[k], t[k]))
    return peaks


def main():
    load, rows, cmds = loadavg(), [], []
    tmp = tempfile.mkdtemp()
    for level in (0, 1):
        for geometry, order in (("straight", 1), ("curved", 2)):
            report = os.path.join(tmp, "report.json")
            cmd = f"{BASE} -mesh meshes/tube1_L{level}_o2.msh -mesh_order {order} -report {report}"
            r = run_report(cmd, report)
            series = {s["field"]: s for s in r["probes"]}
            newton = sum(s["newton"] for s in r["steps"])
            row = {"level": level, "geometry": geometry, "unknowns": sum(r["unknowns"].values()), "newton": newton,
                   "seconds": round(r["seconds"]["total"], 1), "assembly_per_newton": round(r["seconds"]["assembly"] / newton, 3)}
            for i, z in enumerate(Z):
                row[f"arrival_{z}"] = r["results"].get(f"arrival_{i}", "")
            for i, (p, d) in enumerate(zip(first_peaks(series["pressure"], 0), first_peaks(series["displacement"], 0))):
                row[f"peak_pressure_{Z[i]}"], row[f"peak_displacement_{Z[i]}"] = round(p[0], 3), f"{d[0]:.4e}"
                row[f"peak_pressure_time_{Z[i]}"] = f"{p[1]:.4e}"
            print(row, flush=True)
            rows.append(row)
            cmds.append(cmd)
    write_results(os.path.join(TOP, "bench", "results", "fsi_curved_wave"), rows, cmds,
                  "scripts/bench_curved_wave.py (one run each, back to back)", load)


if __name__ == "__main__":
    main()
