#!/usr/bin/python3
# SPDX-License-Identifier: BSD-2-Clause
"""Error against run time of the coupled problem: the pressure wave in tube #1 (linear wall,
scenes/fsi_tube1_linear.opts) to t = 12 ms, 2 ranks.

Grid: mesh levels 0-2 (tube1_L<k>.msh; scripts/make-meshes makes L2) on straight and on curved
cells (tube1_L<k>_o2.msh) x dt = 0.4, 0.2, 0.1 ms x backward Euler and BDF2 x the solver
configurations a user chooses from: MUMPS on the whole system, FaCSI with GDSW
(scenes/fsi_facsi.opts), and FaCSI with the inexact Newton options (scenes/fsi_inexact_newton.opts);
MUMPS only on level 0 unless --configs names it (on L1 it takes 20 s per step, 40 min per run
at dt = 0.1 ms).

Quantities, at z = 0.625, 1.25, 1.875 cm: the front's arrival (the axis pressure reaching half
the inlet's), the first peak of the axis pressure and of the inner wall's radial displacement
(the first local maximum above half the series' largest, refined by the parabola through the
three samples around it); and the interface displacement's L2 norm in space and time.

Every solver configuration solves the same discrete problem (the inexact options' Newton to 1e-4
of each step's first residual, which moves the state by about 1e-7 of its peaks: far below any
discretisation error here), so the error of a run is that of its (mesh, dt, scheme). Every run is measured against one reference per
quantity: Richardson's extrapolation from BDF2's runs, on curved cells where they have a space
correction (backward Euler's and straight cells', computed the same way, are written next to
it; backward Euler's extrapolates from outside its asymptotic range), under the model
q(h, dt) = q* + E_h(h) + E_t(dt): q* = q(h_c, dt_c) - E_t(dt_c) - E_h(h_c) at the finest run (the
finest level, its smallest step). E_t(dt) = (q(2 dt3) - q(dt3)) / (2^p_t - 1) (dt / dt3)^p_t from the three steps
(dt3 the smallest) of the finest level run at all of them, p_t observed there; E_h(h_c) =
(q(h_c-1) - q(h_c)) / ((h_c-1 / h_c)^p_h - 1) at the smallest step run on three levels, p_h
observed there (h ~ fluid velocity unknowns^(-1/3), as the levels are not nested); orders
clipped to [0.5, 4]. Where every level has every step this is the extrapolation from the finest
level and step in both directions. The same extrapolation from the finest level's next larger
step (reference_from_2dt) checks the model: it differs where E_t depends on h. Errors are
relative to |q*| (arrivals: to the arrival time).

Each run is one row of bench/results/work_precision_fsi.csv, with the commit it ran at (the
scene files change); a run already there is not run again (delete its row to repeat it), so the
grid can be filled over several calls.
Usage: scripts/bench_fsi_work_precision.py [--levels 0,1,2] [--geometry straight,curved]
  [--schemes backward_euler,bdf2] [--configs mumps,facsi,inexact] [--dts 4e-4,2e-4,1e-4] [--plot]"""
import csv
import math
import os
import subprocess
import sys
import tempfile

from benchlib import TOP, check_command_line, loadavg, run_report, write_results

check_command_line(__doc__, valued=("--levels", "--geometry", "--schemes", "--configs", "--dts"), flags=("--plot",))

APP = os.path.join(TOP, "install", "bin", "fsi_app")
OUT = os.path.join(TOP, "bench", "results", "work_precision_fsi")
Z = (0.625, 1.25, 1.875)
RI = 0.15  # tube #1's inner radius
T_FINAL = 12e-3
DTS = (4e-4, 2e-4, 1e-4)
CONFIGS = {"mumps": ("MUMPS", ""),
           "facsi": ("FaCSI, GDSW", "-options_file scenes/fsi_facsi.opts"),
           "inexact": ("FaCSI, GDSW, inexact Newton", "-options_file scenes/fsi_facsi.opts -options_file scenes/fsi_inexact_newton.opts")}
PROBES = "-fluid_probes " + ",".join(f"0,0,{z}" for z in Z) + " -structure_probes " + ",".join(f"{RI},0,{z}" for z in Z)
QUANTITIES = [f"arrival_{z}" for z in Z] + [f"peak_pressure_{z}" for z in Z] + [f"peak_displacement_{z}" for z in Z] + ["interface_l2"]
KEY = ("config", "scheme", "geometry", "level", "dt")


def arg(name, default):
    return sys.argv[sys.argv.index(name) + 1].split(",") if name in sys.argv else default


def mesh(level, geometry):
    name = f"meshes/tube1_L{level}{'_o2' if geometry == 'curved' else ''}.msh"
    if not os.path.exists(os.path.join(TOP, name)):
        subprocess.run([os.path.join(TOP, "scripts", "make-meshes"), "tube1", str(level)] + (["2"] if geometry == "curved" else []), check=True, cwd=TOP)
    return name


def first_peak(t, x):
    """The first local maximum of x(t) above half its largest value, refined by the parabola
    through the three samples around it; None if the series ends before it."""
    top = max(x)
    k = next((k for k in range(1, len(x) - 1) if x[k - 1] < x[k] >= x[k + 1] and x[k] > top / 2), None)
    if k is None:
        return None
    a, b, c = x[k - 1], x[k], x[k + 1]
    curvature = a - 2 * b + c
    s = 0.5 * (a - c) / curvature if curvature != 0 else 0.0  # offset of the vertex in samples, |s| <= 1/2
    return b - 0.25 * (a - c) * s


def quantities(r):
    series = {s["field"]: s for s in r["probes"]}
    out = {f"arrival_{z}": r["results"].get(f"arrival_{i}", -1) for i, z in enumerate(Z)}
    for field, name in (("pressure", "pressure"), ("displacement", "displacement")):
        s, n = series[field], len(Z)
        for i, z in enumerate(Z):  # component 0: radial at (RI, 0, z) and the pressure itself on the axis
            out[f"peak_{name}_{z}"] = first_peak(s["t"], [s["values"][s["components"] * (n * k + i)] for k in range(len(s["t"]))])
    out["interface_l2"] = r["results"]["interface_displacement_l2"]
    return {k: ("" if v is None or (k.startswith("arrival") and v < 0) else v) for k, v in out.items()}


def command(config, scheme, geometry, level, dt, report):
    return (f"mpiexec -n 2 {APP} -options_file scenes/fsi_tube1_linear.opts {CONFIGS[config][1]} -mesh {mesh(level, geometry)} "
            f"-dt {dt:g} -t_final {T_FINAL:g} -time_scheme {scheme} {PROBES} -report {report}")


def load():
    return list(csv.DictReader(open(OUT + ".csv"))) if os.path.exists(OUT + ".csv") else []


def commands_of(rows):
    return [command(r["config"], r["scheme"], r["geometry"], int(r["level"]), float(r["dt"]), "report.json") for r in rows]


def main():
    dts = [float(d) for d in arg("--dts", [f"{d:g}" for d in DTS])]
    if any(not any(math.isclose(d, D) for D in DTS) for d in dts):
        sys.exit(f"--dts {','.join(arg('--dts', []))}: the study's steps are {', '.join(f'{d:g}' for d in DTS)} (s)")
    rows, start = load(), loadavg()
    # the scene files and the code a row was measured with (rows are kept across calls)
    git = lambda *a: subprocess.run(["git", *a], cwd=TOP, stdout=subprocess.PIPE, text=True).stdout.strip()
    commit = git("rev-parse", "--short", "HEAD") + ("-dirty" if git("status", "--porcelain", "--untracked-files=no", "--", ".", ":!bench/results") else "")
    done = {tuple(str(r[k]) for k in KEY) for r in rows}
    report = os.path.join(tempfile.mkdtemp(), "report.json")
    for level in map(int, arg("--levels", ["0", "1", "2"])):
        for geometry in arg("--geometry", ["straight", "curved"]):
            for scheme in arg("--schemes", ["backward_euler", "bdf2"]):
                for config in arg("--configs", list(CONFIGS)):
                    for dt in dts:
                        key = (config, scheme, geometry, str(level), f"{dt:g}")
                        if key in done or (config == "mumps" and level > 0 and "--configs" not in sys.argv):
                            continue
                        r = run_report(command(config, scheme, geometry, level, dt, report), report, 4 * 3600)
                        if not r:
                            print(f"no report: {key}", flush=True)
                            continue
                        newton = sum(s["newton"] for s in r["steps"])
                        row = dict(zip(KEY, key), unknowns=sum(r["unknowns"].values()), fluid_unknowns=r["unknowns"]["fluid"],
                                   steps=len(r["steps"]), converged=int(all(s["reason"].startswith("CONVERGED") for s in r["steps"])),
                                   newton=newton, krylov=sum(s["krylov"] for s in r["steps"]), seconds=round(r["seconds"]["total"], 2),
                                   peak_memory_mib=r["peak_memory_mib"], **quantities(r), commit=commit)
                        print(row, flush=True)
                        rows.append(row)
                        write_results(OUT, rows, commands_of(rows), "scripts/bench_fsi_work_precision.py (one run each; the rows of earlier calls kept)", start, keep_earlier=True)
    errors(rows, verbose=True)
    plot(rows)


def observed(q, ratio):
    """Order from three values on a sequence refined by `ratio` each time, clipped to [0.5, 4]; None if flat."""
    d1, d2 = abs(q[0] - q[1]), abs(q[1] - q[2])
    if d1 == 0 or d2 == 0:
        return None
    return min(4.0, max(0.5, math.log(d1 / d2) / math.log(ratio)))


def errors(rows, verbose=False):
    """Per scheme and geometry: the observed orders and Richardson's reference of each quantity
    (written to work_precision_fsi_orders.csv, printed if verbose); each row's relative errors
    are returned as {id(row): {quantity: error}}."""
    out, table = {}, []
    for scheme in ("backward_euler", "bdf2"):
        for geometry in ("straight", "curved"):
            runs = [r for r in rows if r["scheme"] == scheme and r["geometry"] == geometry]
            if not runs:
                continue
            levels = sorted({int(r["level"]) for r in runs})
            h = {lv: float(next(r["fluid_unknowns"] for r in runs if int(r["level"]) == lv)) ** (-1 / 3) for lv in levels}

            def value(level, dt, q):  # any configuration: they solve the same discrete problem
                v = [float(r[q]) for r in runs if int(r["level"]) == level and math.isclose(float(r["dt"]), dt) and r[q] != ""]
                return sum(v) / len(v) if v else None

            for q in QUANTITIES:
                has = lambda lv, dt: value(lv, dt, q) is not None
                corner = next(((lv, dt) for lv in reversed(levels) for dt in reversed(DTS) if has(lv, dt)), None)
                if corner is None:
                    continue
                row = {"scheme": scheme, "geometry": geometry, "quantity": q, "finest": value(*corner, q), "finest_level": corner[0], "finest_dt": corner[1]}
                time_error, space_error = (lambda dt: 0.0), 0.0  # -E_t(dt), -E_h(h_c)
                # the time error, from the finest level run at all three steps
                lt = next((lv for lv in reversed(levels) if all(has(lv, dt) for dt in DTS)), None)
                if lt is not None:
                    qt = [value(lt, dt, q) for dt in DTS]
                    pt = observed(qt, 2.0)
                    row.update(order_dt=pt, order_dt_level=lt)
                    if pt:
                        time_error = lambda dt: (qt[2] - qt[1]) / (2 ** pt - 1) * (dt / DTS[-1]) ** pt
                # the space error, from the smallest step run on the three finest levels
                top3 = levels[-3:]
                dh = next((dt for dt in reversed(DTS) if len(top3) == 3 and all(has(lv, dt) for lv in top3)), None)
                if dh is not None and corner[0] == top3[-1]:
                    qh = [value(lv, dh, q) for lv in top3]
                    ratio = math.sqrt(h[top3[0]] / h[top3[2]])  # geometric mean of the two refinements
                    ph = observed(qh, ratio)
                    row.update(order_h=ph, order_h_dt=dh)
                    if ph:
                        space_error = (qh[2] - qh[1]) / ((h[top3[1]] / h[top3[2]]) ** ph - 1)
                row["reference"] = row["finest"] + time_error(corner[1]) + space_error
                # the same from the finest level's next larger step: where the error model holds, the same value
                if has(corner[0], 2 * corner[1]):
                    row["reference_from_2dt"] = value(corner[0], 2 * corner[1], q) + time_error(2 * corner[1]) + space_error
                table.append(row)
    # both schemes on both geometries converge to the same solution (the tube's, as h and dt go to
    # 0): every run is measured against one reference per quantity, the one with the most in it -
    # a space correction over none, BDF2's over backward Euler's (extrapolated from outside its
    # asymptotic range), curved cells' over straight ones'
    rank = lambda row: (row.get("order_h") is not None, row["scheme"] == "bdf2", row["geometry"] == "curved")
    best = {}
    for row in table:
        if row["quantity"] not in best or rank(row) > rank(best[row["quantity"]]):
            best[row["quantity"]] = row
    for r in rows:
        for q in QUANTITIES:
            ref = best[q]["reference"] if q in best else None
            if ref and r[q] != "":
                out.setdefault(id(r), {})[q] = abs(float(r[q]) - ref) / abs(ref)
    if table:
        keys = ["scheme", "geometry", "quantity", "finest", "finest_level", "finest_dt", "order_dt", "order_dt_level", "order_h", "order_h_dt", "reference", "reference_from_2dt"]
        with open(OUT + "_orders.csv", "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=keys)
            w.writeheader()
            w.writerows(table)
        for row in table:
            if verbose:
                print(row)
    return out


def plot(rows):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    err = errors(rows)
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.6))
    for ax, title, pick in ((axes[0], "interface displacement, L2 in space and time", lambda e: e.get("interface_l2")),
                            (axes[1], "first peak of the axis pressure at z = 1.25 cm", lambda e: e.get("peak_pressure_1.25"))):
        for config, (name, _) in CONFIGS.items():
            for scheme, style in (("backward_euler", "o-"), ("bdf2", "s--")):
                for geometry in ("straight", "curved"):
                    pts = sorted((float(r["seconds"]), pick(err.get(id(r), {}))) for r in rows
                                 if r["config"] == config and r["scheme"] == scheme and r["geometry"] == geometry)
                    pts = [p for p in pts if p[1]]
                    if not pts:
                        continue
                    front, best = [], float("inf")  # the runs no faster run beats: what a user would pick
                    for t, e in pts:
                        if e < best:
                            front.append((t, e))
                            best = e
                    line, = ax.loglog([p[0] for p in front], [p[1] for p in front], style,
                                      label=f"{name}, {'BE' if scheme == 'backward_euler' else 'BDF2'}{', curved' if geometry == 'curved' else ''}")
                    ax.loglog([p[0] for p in pts], [p[1] for p in pts], style[0], color=line.get_color(), alpha=0.35, ms=3)  # the runs beaten
        ax.set_title(title, fontsize=9)
        ax.set_xlabel("run time, 2 ranks (s)")
        ax.set_ylabel("error against Richardson's reference (relative)")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=6)
    levels = ", ".join(f"L{lv}" for lv in sorted({int(r["level"]) for r in rows}))
    fig.suptitle(f"coupled tube #1, linear wall, to 12 ms: {levels} x dt 0.4/0.2/0.1 ms (each curve: its runs that no faster run beats)"
                 + ("; one level: the errors are the time discretisation's" if "," not in levels else ""), fontsize=9)
    fig.tight_layout()
    fig.savefig(OUT + ".png", dpi=110)


if __name__ == "__main__":
    plot(load()) if "--plot" in sys.argv else main()
