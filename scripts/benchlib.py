# SPDX-License-Identifier: BSD-2-Clause
"""Shared by the bench_* scripts: run one command, and write its results as CSV plus the exact
commands that produced them."""
import csv
import json
import os
import re
import signal
import subprocess

ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
TOP = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))  # scenes name their files from here


def run(cmd, timeout=None):
    """Output (stdout and stderr) of a command line. After `timeout` seconds the command's process
    group (mpiexec and its ranks) is ended and the output ends with "benchlib: TIMEOUT"."""
    p = subprocess.Popen(cmd.split(), env=ENV, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                         start_new_session=True, cwd=TOP)
    try:
        return p.communicate(timeout=timeout)[0]
    except subprocess.TimeoutExpired:
        os.killpg(p.pid, signal.SIGTERM)  # mpiexec passes it on to its ranks
        try:
            out = p.communicate(timeout=10)[0]
        except subprocess.TimeoutExpired:
            os.killpg(p.pid, signal.SIGKILL)
            out = p.communicate()[0]
        return out + f"\nbenchlib: TIMEOUT after {timeout} s\n"


def loadavg():
    return " ".join(f"{x:.2f}" for x in os.getloadavg())


def portable(cmd):
    """A command line as a reader reruns it from the repository root: paths inside the repository
    relative to it, a temporary report file named report.json."""
    cmd = cmd.replace(TOP + "/", "")
    return re.sub(r"/tmp/[^ ]*/([^/ ]+\.json)", r"\1", cmd)


def write_results(out, rows, cmds, producer, load_at_start=None):
    """out.csv with one row per run, out.cmd with the command of each run, to be run from the
    repository root (and the load average at the start, if given, and now)."""
    if load_at_start is not None:
        producer += f"\n# load average (1, 5, 15 min) at start: {load_at_start}, at end: {loadavg()}"
    with open(out + ".csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    with open(out + ".cmd", "w") as f:
        f.write(f"# produced by {producer}; run from the repository root\n" + "\n".join(portable(c) for c in cmds) + "\n")


def run_report(cmd, report, timeout=None):
    """The JSON run report of an fsi_app command line (which writes it to `report`), None if the
    run wrote none (its output's tail is printed)."""
    if os.path.exists(report):
        os.remove(report)
    log = run(cmd, timeout=timeout)
    if not os.path.exists(report):
        print(log[-1500:])
        return None
    return json.load(open(report))


def step_costs(r):
    """Per time step of a run report: Newton steps, GMRES iterations per Newton step, seconds
    (total, assembly, the structure split's set-up, the other set-up, Krylov), peak memory."""
    steps, s = r["steps"], r["seconds"]
    n, newton = len(steps), sum(x["newton"] for x in steps)
    structure = s.get("setup_structure", 0.0)
    return {
        "converged": int(all(x["reason"].startswith("CONVERGED") for x in steps)),
        "unknowns": sum(r["unknowns"].values()), "structure_unknowns": r["unknowns"]["structure"],
        "steps": n, "newton_per_step": newton / n, "gmres_per_newton": sum(x["krylov"] for x in steps) / max(newton, 1),
        "seconds_per_step": s["total"] / n, "assembly_per_step": s["assembly"] / n, "structure_setup_per_step": structure / n,
        "other_setup_per_step": (s["preconditioner_setup"] - structure) / n, "krylov_per_step": s["krylov"] / n,
        "peak_memory_mib": r["peak_memory_mib"],
    }
