#!/usr/bin/python3
# SPDX-License-Identifier: BSD-2-Clause
"""The paper's Figs. 3 and 4 in kind: the coupled tubes with the linear wall
(scenes/fsi_tube{1,2,3}_linear.opts), FaCSI with GDSW on the structure (scenes/fsi_facsi.opts),
GMRES iterations per Newton step and Newton steps per time step against the number of
structure subdomains, overlap 1 and 2. One run per point, `mpiexec -n RANKS` with
SUBDOMAINS / RANKS subdomains per rank, a few time steps each; one CSV row per run, the
seconds per step and its parts included (meaningful where every rank has its own core).
Usage: scripts/bench_fsi_scalability.py [--tubes 1,2,3] [--mesh L0] [--dt 1e-4,2e-4]
         [--subdomains 16,32,64,128,256] [--overlap 1,2] [--ranks 2] [--steps 2] [--out fsi_scalability] [--plot]
--mesh names the level of meshes/tube<N>_<mesh>.msh: L0 (committed), L1, ... or seed_fsi (the
paper's size; both made by scripts/make-meshes when missing). On a cluster, e.g.:
  scripts/bench_fsi_scalability.py --mesh seed_fsi --ranks 64 --subdomains 64,128,256,512
Writes bench/results/<out>.{csv,cmd,png}; --plot redraws the PNG from the CSV."""
import csv
import os
import sys
import tempfile

from benchlib import TOP, check_command_line, loadavg, run, run_report, step_costs, write_results

check_command_line(__doc__, valued=("--tubes", "--mesh", "--dt", "--subdomains", "--overlap", "--ranks", "--steps", "--out"), flags=("--plot",))

APP = os.path.join(os.environ.get("GDSW_BUILD", os.path.join(TOP, "build")), "fsi_app", "fsi_app")


def arg(name, default):
    return sys.argv[sys.argv.index(name) + 1] if name in sys.argv else default


def command(tube, mesh, dt, ranks, subdomains, overlap, steps, report):
    return (f"mpiexec -n {ranks} --mca mpi_yield_when_idle 1 {APP} -options_file scenes/fsi_tube{tube}_linear.opts "
            f"-options_file scenes/fsi_facsi.opts -mesh {os.path.join(TOP, 'meshes', mesh + '.msh')} -dt {dt} "
            f"-t_final {steps * float(dt):g} -structure_subdomains {subdomains // ranks} "
            f"-fieldsplit_structure_pc_gdsw_overlap {overlap} -report {report}")


def main():
    tubes = [int(t) for t in arg("--tubes", "1,2,3").split(",")]
    level, ranks, steps = arg("--mesh", "L0"), int(arg("--ranks", "2")), int(arg("--steps", "2"))
    dts = arg("--dt", "1e-4,2e-4").split(",")
    counts = [int(s) for s in arg("--subdomains", "16,32,64,128,256").split(",")]
    overlaps = arg("--overlap", "1,2").split(",")
    out = os.path.join(TOP, "bench", "results", arg("--out", "fsi_scalability"))
    if "--plot" in sys.argv:
        plot(out)
        return
    bad = [s for s in counts if s % ranks]
    if bad:
        sys.exit(f"bench_fsi_scalability: --subdomains {bad} are not multiples of --ranks {ranks}")
    # rows are kept across calls: a point already in out.csv is not run again (delete its row to
    # repeat it), so a long sweep can be stopped and resumed
    rows = list(csv.DictReader(open(out + ".csv"))) if os.path.exists(out + ".csv") else []
    cmds = [command(r["tube"], r["mesh"], r["dt"], int(r["ranks"]), int(r["subdomains"]), r["overlap"], int(r.get("steps") or steps), "r.json")
            for r in rows]
    load = loadavg()
    for tube in tubes:
        mesh = f"tube{tube}_{level}"
        if not os.path.exists(os.path.join(TOP, "meshes", mesh + ".msh")):
            print(run(f"{os.path.join(TOP, 'scripts', 'make-meshes')} tube{tube} {level.removeprefix('L')}"))
        for dt in dts:
            for overlap in overlaps:
                for s in counts:
                    key = {"tube": str(tube), "mesh": mesh, "dt": dt, "ranks": str(ranks), "subdomains": str(s), "overlap": overlap}
                    if any(all(r[k] == v for k, v in key.items()) for r in rows):
                        continue
                    report = os.path.join(tempfile.mkdtemp(), "r.json")
                    cmd = command(tube, mesh, dt, ranks, s, overlap, steps, report)
                    r = run_report(cmd, report, timeout=7200)
                    row = {**key, **(step_costs(r) if r else {"converged": 0})}
                    print(row, flush=True)
                    rows.append(row)
                    cmds.append(cmd)
                    write_results(out, rows, cmds, "scripts/bench_fsi_scalability.py " + " ".join(sys.argv[1:]) +
                                  " (one run per point; the rows of earlier calls kept)", load, keep_earlier=True)
    plot(out)


def plot(out):
    import matplotlib
    import matplotlib.ticker
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = [r for r in csv.DictReader(open(out + ".csv")) if r["converged"] == "1"]
    meshes = list(dict.fromkeys(r["mesh"] for r in rows))
    all_ranks = sorted({r["ranks"] for r in rows}, key=lambda n: -sum(r["ranks"] == n for r in rows))  # the sweep's first
    fig, axes = plt.subplots(2, len(meshes), figsize=(5 * len(meshes), 7), squeeze=False, sharex="col")
    for col, mesh in enumerate(meshes):
        for dt in dict.fromkeys(r["dt"] for r in rows if r["mesh"] == mesh):
            for overlap in ("1", "2"):
                for ranks in all_ranks:
                    sel = sorted((r for r in rows if (r["mesh"], r["dt"], r["overlap"], r["ranks"]) == (mesh, dt, overlap, ranks)),
                                 key=lambda r: int(r["subdomains"]))
                    for ax, column in zip(axes[:, col], ("gmres_per_newton", "newton_per_step")):
                        if sel:
                            ax.plot([int(r["subdomains"]) for r in sel], [float(r[column]) for r in sel],
                                    ("o" if overlap == "2" else "s") + ("-" if ranks == all_ranks[0] else ":"),
                                    label=f"dt = {float(dt) * 1e3:g} ms, overlap {overlap}" + (f", {ranks} ranks" if len(all_ranks) > 1 else ""))
        axes[0, col].set_title(f"FaCSI + GDSW, {mesh}, linear wall", fontsize=9)
        axes[0, col].set_ylabel("GMRES iterations per Newton step")
        axes[1, col].set_ylabel("Newton steps per time step")
        axes[1, col].set_xlabel("structure subdomains")
        for ax in axes[:, col]:
            ax.set_xscale("log", base=2)
            ax.xaxis.set_major_formatter(matplotlib.ticker.ScalarFormatter())
            ax.set_ylim(0, ax.get_ylim()[1] * 1.15)  # room above a flat line
            ax.grid(True, alpha=0.3)
        axes[0, col].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out + ".png", dpi=110)


if __name__ == "__main__":
    main()
