#!/usr/bin/python3
# SPDX-License-Identifier: BSD-2-Clause
"""The arterial boundary conditions' benchmarks (2 ranks, FaCSI):

reflection  The paper's tube #1 pulse (scenes/fsi_tube1_arterial.opts, tube1_L0, 1330 dyn/cm^2
            for 3 ms, dt 0.5 ms, 15 ms) with the traction-free outlet, then with a resistance
            equal to the tube's characteristic impedance Z_c = rho c / A, c the wave speed the
            first run measures (probes on the axis at z = 0.625 and 1.25 cm). The reflected wave
            is the pressure at z = 0.625 cm after the incident pulse has passed: max |p| over
            t >= (2 L - z) / c - 1 ms, when the reflection from the outlet arrives. Writes
            bench/results/arterial_reflection.{csv,cmd,png} (the two pressure series, and the
            ratio of the reflected amplitudes).
carotid     scenes/carotid_tube.opts for three cardiac cycles (552 steps of 5 ms, BDF2) with
            scenes/fsi_facsi_lu_fluid.opts: the outlet's flow and pressure every step (the run's
            CSV) and per cycle the pressure's range and mean, and their change from cycle 2 to 3.
            Writes bench/results/arterial_carotid.{csv,cmd,png} and arterial_carotid_cycles.csv.

support     The same pulse with the wall's outer surface held by the tissue support
            (-structure_support k_s) for k_s = 0, 1e6, 3e6, 1e7 dyn/cm^3: the wave speed the probes
            measure (z = 0.625, 1.25, 1.875 cm) against the long-wave estimate for a thin wall,
            c(k_s) = c(0) sqrt(1 + k_s Ro / (2 rho c(0)^2)) (the spring adds k_s Ro / Ri to the
            wall's pressure per radial displacement, 2 rho c(0)^2 / Ri), and the largest wall
            displacement. Writes bench/results/arterial_support.{csv,cmd,png}.

bifurcation scenes/carotid_bifurcation.opts for one cardiac cycle (184 steps of 5 ms, BDF2,
            2 ranks) with scenes/fsi_facsi_lu_fluid.opts, in --work DIR (default
            $TMPDIR/gdsw_bifurcation): checkpoints every 10 steps, and a run that finds DIR's
            checkpoint continues from it (the cycle takes hours here). Per step: Newton and FGMRES
            counts, seconds, the CCA's flow and pressure and each branch's (its RCR's P and Pi).
            Writes bench/results/arterial_bifurcation.{csv,cmd,png} and, with ParaView, the WSS
            on the lumen and the wall's displacement at peak systole
            (arterial_bifurcation_wss.png, arterial_bifurcation_displacement.png).
subdomains  The bifurcation's first 2 time steps with the wall split into 2, 8, 32, 128 GDSW
            subdomains (-structure_subdomains per rank, 2 ranks), with the GDSW and the RGDSW
            coarse space and with none (one-level Schwarz) on the same subdomains
            (-fieldsplit_structure_pc_gdsw_coarse_space gdsw|rgdsw|none): FGMRES iterations per Newton step
            and Newton steps, what a user with more cores (one subdomain per core) can expect.
            Writes bench/results/arterial_bifurcation_subdomains.{csv,cmd,png}.

Usage: scripts/bench_arterial.py reflection|carotid|support|bifurcation|subdomains [--app PATH] [--work DIR] [--plot]"""
import csv
import glob
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile

from benchlib import ENV, TOP, check_command_line, loadavg, run_report, step_costs, write_results

check_command_line(__doc__, valued=("--app", "--work"), flags=("--plot",), modes=("reflection", "carotid", "support", "bifurcation", "subdomains"))
OUT = os.path.join(TOP, "bench", "results", "arterial_")
MMHG, PREF, PERIOD = 1333.2, 80.0, 0.92  # the carotid scene's pressures are relative to 80 mmHg
L, RI, RO, RHO = 2.5, 0.15, 0.21, 1.0     # tube #1
Z = (0.625, 1.25)


def results(name):
    """The rows of bench/results/arterial_<name>.csv."""
    return list(csv.DictReader(open(OUT + name + ".csv")))


def pyplot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def app():
    return sys.argv[sys.argv.index("--app") + 1] if "--app" in sys.argv else os.path.join(TOP, "install", "bin", "fsi_app")


def report_of(cmd, report, log):
    with open(log, "w") as f:
        p = subprocess.run(cmd.split(), env=ENV, cwd=TOP, stdout=f, stderr=subprocess.STDOUT)
    if not os.path.exists(report):
        sys.exit(f"bench_arterial: the run wrote no report (exit {p.returncode}); see {log}")
    return json.load(open(report))


def reflection():
    tmp = tempfile.mkdtemp()
    base = (f"mpiexec -n 2 {app()} -options_file scenes/fsi_tube1_arterial.opts -options_file scenes/fsi_facsi.opts -t_final 1.5e-2 "
            f"-fluid_probes " + ",".join(f"0,0,{z}" for z in Z))
    load = loadavg()
    free = base + f" -report {tmp}/free.json"
    r0 = report_of(free, f"{tmp}/free.json", f"{tmp}/free.log")
    c = r0["results"]["wave_speed"]
    zc = RHO * c / (3.141592653589793 * RI * RI)
    matched = base + f" -blocks structure,fluid,geometry,coupling,outlets -outlets_outlet_resistance {zc:.1f} -report {tmp}/matched.json"
    r1 = report_of(matched, f"{tmp}/matched.json", f"{tmp}/matched.log")
    t_refl = (2 * L - Z[0]) / c - 1e-3
    rows, amp = [], {}
    for name, r in (("traction_free", r0), ("resistance_zc", r1)):
        p = next(s for s in r["probes"] if s["field"] == "pressure")
        n = len(Z)
        series = [(t, p["values"][n * k]) for k, t in enumerate(p["t"])]
        amp[name] = max(abs(v) for t, v in series if t >= t_refl)
        for t, v in series:
            rows.append({"outlet": name, "t": t, "pressure_z0.625": v})
    print(f"wave speed {c:.1f} cm/s, Z_c {zc:.1f} dyn s/cm^5; reflected amplitude at z = 0.625 (t >= {1e3 * t_refl:.2f} ms): "
          f"traction-free {amp['traction_free']:.1f}, Z_c {amp['resistance_zc']:.1f} dyn/cm^2, ratio {amp['traction_free'] / amp['resistance_zc']:.2f}")
    rows.append({"outlet": "reflected_amplitude_ratio", "t": t_refl, "pressure_z0.625": amp["traction_free"] / amp["resistance_zc"]})
    cmds = [x.replace(app(), "install/bin/fsi_app").replace(tmp + "/", "") for x in (free, matched)]
    write_results(OUT + "reflection", rows, cmds, f"scripts/bench_arterial.py reflection (c {c:.1f} cm/s, Z_c {zc:.1f} dyn s/cm^5, "
                  f"reflected amplitude {amp['traction_free']:.1f} -> {amp['resistance_zc']:.1f} dyn/cm^2)", load)
    shutil.rmtree(tmp)
    plot_reflection()


def plot_reflection():
    plt, rows = pyplot(), results("reflection")
    fig, ax = plt.subplots(figsize=(7, 4))
    for name, label in (("traction_free", "traction-free outlet"), ("resistance_zc", "resistance R = Z_c")):
        sel = [r for r in rows if r["outlet"] == name]
        ax.plot([1e3 * float(r["t"]) for r in sel], [float(r["pressure_z0.625"]) for r in sel], label=label)
    t_refl = next(float(r["t"]) for r in rows if r["outlet"] == "reflected_amplitude_ratio")
    ax.axvline(1e3 * t_refl, color="grey", ls=":", label="reflection arrives")
    ax.set(xlabel="t (ms)", ylabel="pressure on the axis at z = 0.625 cm (dyn/cm²)", title="tube #1: the pulse and its reflection from the outlet")
    ax.legend()
    fig.tight_layout()
    fig.savefig(OUT + "reflection.png", dpi=120)


def carotid():
    tmp = tempfile.mkdtemp()
    cmd = (f"mpiexec -n 2 {app()} -options_file scenes/carotid_tube.opts -options_file scenes/fsi_facsi_lu_fluid.opts "
           f"-output {tmp}/carotid.xdmf -output_every 1000 -report {tmp}/r.json")
    load = loadavg()
    r = report_of(cmd, f"{tmp}/r.json", OUT + "carotid.log")
    out = next(s for s in r["probes"] if s["field"] == "outlet_outlet")
    steps = {s["step"]: s for s in r["steps"]}
    rows = []
    for k, t in enumerate(out["t"]):
        q, p, pi = out["values"][3 * k:3 * k + 3]
        s = steps.get(k + 1, {})
        rows.append({"t": t, "Q": q, "P_mmHg": p / MMHG + PREF, "Pi_mmHg": pi / MMHG + PREF, "newton": s.get("newton"), "gmres": s.get("krylov"),
                     "seconds": s.get("seconds", {}).get("total")})
    write_results(OUT + "carotid", rows, [cmd.replace(app(), "install/bin/fsi_app").replace(tmp + "/", "")], "scripts/bench_arterial.py carotid", load)
    cycles(rows)
    shutil.rmtree(tmp)
    plot_carotid()


def cycles(rows):
    out = []
    for c in range(3):
        p = [r["P_mmHg"] for r in rows if c * PERIOD < float(r["t"]) <= (c + 1) * PERIOD + 1e-9]
        q = [r["Q"] for r in rows if c * PERIOD < float(r["t"]) <= (c + 1) * PERIOD + 1e-9]
        out.append({"cycle": c + 1, "P_min_mmHg": min(p), "P_max_mmHg": max(p), "P_mean_mmHg": sum(p) / len(p), "Q_mean": sum(q) / len(q), "Q_max": max(q)})
    for key in ("P_min_mmHg", "P_max_mmHg", "P_mean_mmHg"):
        out.append({"cycle": f"change_2_3_{key}", "P_mean_mmHg": abs(out[2][key] - out[1][key]) / abs(out[2][key])})
    with open(OUT + "carotid_cycles.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=["cycle", "P_min_mmHg", "P_max_mmHg", "P_mean_mmHg", "Q_mean", "Q_max"])
        w.writeheader()
        w.writerows(out)
    for o in out:
        print(o)


def plot_carotid():
    plt, rows = pyplot(), results("carotid")
    t = [float(r["t"]) for r in rows]
    fig, ax = plt.subplots(figsize=(8, 4))
    ax.plot(t, [float(r["P_mmHg"]) for r in rows], color="C3", label="outlet pressure P")
    ax.set(xlabel="t (s)", ylabel="pressure (mmHg)", title="carotid tube: outlet (RCR) over three cardiac cycles")
    ax2 = ax.twinx()
    ax2.plot(t, [float(r["Q"]) for r in rows], color="C0", label="outlet flow Q")
    ax2.set(ylabel="flow (mL/s)")
    fig.legend(loc="upper right")
    fig.tight_layout()
    fig.savefig(OUT + "carotid.png", dpi=120)


def support():
    tmp = tempfile.mkdtemp()
    probes = (0.625, 1.25, 1.875)
    base = (f"mpiexec -n 2 {app()} -options_file scenes/fsi_tube1_arterial.opts -options_file scenes/fsi_facsi.opts -t_final 1.5e-2 "
            f"-fluid_probes " + ",".join(f"0,0,{z}" for z in probes))
    load, rows, cmds = loadavg(), [], []
    for k in (0, 1e6, 3e6, 1e7):
        cmd = base + (f" -structure_support {k:g}" if k else "") + f" -report {tmp}/r.json"
        r = report_of(cmd, f"{tmp}/r.json", f"{tmp}/run.log")
        rows.append({"k_s": k, "wave_speed": r["results"]["wave_speed"], "max_displacement": r["results"]["max_displacement"],
                     "newton": sum(s["newton"] for s in r["steps"]), "gmres": sum(s["krylov"] for s in r["steps"])})
        cmds.append(cmd.replace(app(), "install/bin/fsi_app").replace(tmp + "/", ""))
    c0 = rows[0]["wave_speed"]
    for row in rows:
        row["wave_speed_estimate"] = c0 * (1 + row["k_s"] * RO / (2 * RHO * c0 * c0)) ** 0.5
        print(row)
    write_results(OUT + "support", rows, cmds, "scripts/bench_arterial.py support", load)
    shutil.rmtree(tmp)
    plot_support()


def plot_support():
    plt, rows = pyplot(), results("support")
    k = [float(r["k_s"]) for r in rows]
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.plot(k, [float(r["wave_speed"]) for r in rows], "o-", label="measured (probes)")
    ax.plot(k, [float(r["wave_speed_estimate"]) for r in rows], "s--", label="thin wall, long wave: c(0) sqrt(1 + k_s Ro / 2 rho c(0)²)")
    ax.set(xlabel="tissue support k_s (dyn/cm³)", ylabel="wave speed (cm/s)", title="tube #1: the pulse's speed with the wall held by the tissue")
    ax.legend()
    fig.tight_layout()
    fig.savefig(OUT + "support.png", dpi=120)


def work_dir():
    return sys.argv[sys.argv.index("--work") + 1] if "--work" in sys.argv else os.path.join(tempfile.gettempdir(), "gdsw_bifurcation")


def bifurcation_command(work):
    return (f"mpiexec -n 2 {app()} -options_file scenes/carotid_bifurcation.opts -options_file scenes/fsi_facsi_lu_fluid.opts "
            f"-output {work}/bif.xdmf -output_every 4 -checkpoint {work}/bif.chk -checkpoint_every 10")


def bifurcation():
    work = work_dir()
    os.makedirs(work, exist_ok=True)
    chk, logs = os.path.join(work, "bif.chk"), glob.glob(os.path.join(work, "run*.log"))
    load = loadavg()
    with open(os.path.join(work, f"run{len(logs)}.log"), "w") as f:
        subprocess.run((bifurcation_command(work) + (f" -restart {chk}" if os.path.exists(chk) else "")).split(), env=ENV, cwd=TOP, stdout=f,
                       stderr=subprocess.STDOUT)
    collect(work, load)
    plot_bifurcation()


def collect(work, load):
    """bench/results/arterial_bifurcation.csv from the run's logs and CSV files in work (a run
    not finished yet gives the steps it has)."""
    steps = {}
    for name in sorted(glob.glob(os.path.join(work, "run*.log"))):  # a step run again after a restart: its last record
        for m in re.finditer(r"^step (\d+)/\d+ t (\S+) newton (\d+) krylov (\d+) (\w+).*\((\S+) s, peak memory (\d+) MiB\)", open(name).read(), re.M):
            steps[int(m.group(1))] = {"newton": int(m.group(3)), "gmres": int(m.group(4)), "reason": m.group(5), "seconds": float(m.group(6)), "peak_MiB": int(m.group(7))}
    flows = list(csv.DictReader(open(os.path.join(work, "bif_boundaries.csv"))))
    rcr = {b: list(csv.DictReader(open(os.path.join(work, f"bif_outlet_outlet_{b}.csv")))) for b in ("ica", "eca")}
    rows = []
    for k, f in enumerate(flows):
        row = {"t": float(f["t"]), **steps.get(k + 1, {}), "Q_cca": -float(f["Q_inlet"]), "p_cca_mmHg": float(f["p_inlet"]) / MMHG + PREF}
        for b in ("ica", "eca"):
            row[f"Q_{b}"] = float(f[f"Q_outlet_{b}"])
            row[f"P_{b}_mmHg"] = float(rcr[b][k]["P"]) / MMHG + PREF
            row[f"Pi_{b}_mmHg"] = float(rcr[b][k]["Pi"]) / MMHG + PREF
        rows.append(row)
    cmd = bifurcation_command(work).replace(app(), "install/bin/fsi_app").replace(work + "/", "")
    write_results(OUT + "bifurcation", rows, [cmd, cmd + " -restart bif.chk  # after a stop: continues from the newest checkpoint"],
                  f"scripts/bench_arterial.py bifurcation ({len(steps)} of 184 steps run)", load)


def render(work, part, field, png, warp, title):
    """pvbatch scripts/render_vessel.py at peak systole (the inflow's largest), under a virtual X
    display; ParaView may abort on closing the display after it saved the picture."""
    rows = results("bifurcation")
    peak = max(rows, key=lambda r: float(r["Q_cca"]))["t"]
    cmd = ["xvfb-run", "-a", "-s", "-screen 0 1600x1200x24", "pvbatch", os.path.join(TOP, "scripts", "render_vessel.py"), os.path.join(work, "bif.xdmf"),
           png, peak, part, field, str(warp), title]
    log = os.path.join(work, f"render_{part}.log")  # a file, not a pipe: xvfb-run's X server inherits it and may outlive pvbatch
    with open(log, "w") as f:
        p = subprocess.Popen(cmd, env=ENV, stdout=f, stderr=subprocess.STDOUT, start_new_session=True)
        try:
            p.wait(timeout=600)
        except subprocess.TimeoutExpired:
            print(f"pvbatch still running after 600 s: stopped (see {log})")
        try:
            os.killpg(p.pid, signal.SIGKILL)  # the X server with it
        except ProcessLookupError:
            pass
        p.wait()
    print(open(log).read().splitlines()[:1])


def plot_bifurcation():
    work = work_dir()
    if "--plot" in sys.argv and os.path.exists(os.path.join(work, "bif_boundaries.csv")):
        collect(work, None)
    plt, rows = pyplot(), results("bifurcation")
    t = [float(r["t"]) for r in rows]
    fig, ax = plt.subplots(1, 3, figsize=(15, 4))
    for key, label in (("cca", "CCA (inlet)"), ("ica", "ICA"), ("eca", "ECA")):
        ax[0].plot(t, [float(r[f"Q_{key}"]) for r in rows], label=label)
    ax[0].set(xlabel="t (s)", ylabel="flow (mL/s)", title="flow rates")
    ax[1].plot(t, [float(r["p_cca_mmHg"]) for r in rows], label="CCA inlet (mean)")
    for b in ("ica", "eca"):
        ax[1].plot(t, [float(r[f"P_{b}_mmHg"]) for r in rows], label=f"{b.upper()} outlet (RCR P)")
    ax[1].set(xlabel="t (s)", ylabel="pressure (mmHg)", title="pressures")
    done = [r for r in rows if r.get("newton")]
    ax[2].plot([float(r["t"]) for r in done], [int(r["newton"]) for r in done], "o", ms=3, label="Newton steps")
    ax2 = ax[2].twinx()
    ax2.plot([float(r["t"]) for r in done], [int(r["gmres"]) / max(int(r["newton"]), 1) for r in done], "C1.", ms=4, label="FGMRES per Newton")
    ax[2].set(xlabel="t (s)", ylabel="Newton steps per time step", title="solver per time step")
    ax2.set(ylabel="FGMRES iterations per Newton step")
    for a in ax[:2]:
        a.legend()
    fig.suptitle("carotid bifurcation (bifurcation_L0, arterial wall, FaCSI + RGDSW on the wall, 2 ranks)")
    fig.tight_layout()
    fig.savefig(OUT + "bifurcation.png", dpi=120)
    if len(rows) == 184 and os.path.exists(os.path.join(work, "bif.xdmf")) and shutil.which("pvbatch"):  # peak systole is known once the cycle has run
        render(work, "fluid", "wss", OUT + "bifurcation_wss.png", 1, "wall shear stress at peak systole (dyn/cm^2)")
        render(work, "wall", "displacement", OUT + "bifurcation_displacement.png", 5, "wall displacement at peak systole (cm), warped 5x")


COARSE_SPACES = {"gdsw": "GDSW (two levels)", "rgdsw": "RGDSW (two levels)", "none": "one-level Schwarz"}


def subdomains():
    tmp = tempfile.mkdtemp()
    base = f"mpiexec -n 2 {app()} -options_file scenes/carotid_bifurcation.opts -options_file scenes/fsi_facsi_lu_fluid.opts -t_final 0.01"
    load, rows, cmds = loadavg(), [], []
    for total in (2, 8, 32, 128):
        for coarse in COARSE_SPACES:
            cmd = base + f" -structure_subdomains {total // 2} -fieldsplit_structure_pc_gdsw_coarse_space {coarse}"
            r = run_report(cmd + f" -report {tmp}/r.json", f"{tmp}/r.json")
            row = {"subdomains": total, "coarse_space": coarse, **(step_costs(r) if r else {"converged": 0})}
            print(row)
            rows.append(row)
            cmds.append(cmd.replace(app(), "install/bin/fsi_app") + " -report r.json")
    write_results(OUT + "bifurcation_subdomains", rows, cmds, "scripts/bench_arterial.py subdomains", load)
    shutil.rmtree(tmp)
    plot_subdomains()


def plot_subdomains():
    plt, rows = pyplot(), results("bifurcation_subdomains")
    fig, ax = plt.subplots(figsize=(6, 4))
    for coarse, label in COARSE_SPACES.items():
        mine = [r for r in rows if r["coarse_space"] == coarse and r.get("gmres_per_newton")]
        ax.plot([int(r["subdomains"]) for r in mine], [float(r["gmres_per_newton"]) for r in mine], "o-", label=label)
    ax.set(xscale="log", xlabel="wall subdomains", ylabel="FGMRES iterations per Newton step",
           title="carotid bifurcation (arterial wall), FaCSI: the wall's preconditioner")
    ax.legend()
    fig.tight_layout()
    fig.savefig(OUT + "bifurcation_subdomains.png", dpi=120)


if __name__ == "__main__":
    mode = sys.argv[1]
    run, plot = {"reflection": (reflection, plot_reflection), "carotid": (carotid, plot_carotid), "support": (support, plot_support),
                 "bifurcation": (bifurcation, plot_bifurcation), "subdomains": (subdomains, plot_subdomains)}[mode]
    plot() if "--plot" in sys.argv else run()
