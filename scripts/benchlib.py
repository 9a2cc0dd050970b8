# SPDX-License-Identifier: BSD-2-Clause
"""Shared by the bench_* scripts: run one command, and write its results as CSV plus the exact
commands that produced them."""
import csv
import json
import os
import re
import signal
import subprocess
import sys
import time

# One thread per MPI rank: CHOLMOD (libgomp) otherwise starts OpenMP threads in every rank, more
# threads than cores (the 499 k-dof cube on 2 ranks: 20.5 -> 16.5 s for the same gdsw run)
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1", OMP_NUM_THREADS="1")
TOP = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))  # scenes name their files from here


def run(cmd, timeout=None, cwd=TOP):
    """Output (stdout and stderr) of a command line, run in cwd (the repository's root unless
    given). After `timeout` seconds the command's process group (mpiexec and its ranks) is ended
    and the output ends with "benchlib: TIMEOUT"."""
    p = subprocess.Popen(cmd.split(), env=ENV, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                         start_new_session=True, cwd=cwd)
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


def measure_solve(cmd, timeout):
    """One linear solve run with -ksp_converged_reason -log_view -memory_view: its status,
    iterations, set-up (PCSetUp) and solve (KSPSolve) times (max over ranks), peak memory (sum
    over ranks) and wall time, parsed from its output."""
    t0 = time.time()
    out = run(cmd, timeout)
    wall = time.time() - t0

    def event(name):
        m = re.search(rf"^{name}\s+\d+ \S+ (\S+)", out, re.M)
        return float(m.group(1)) if m else float("nan")
    reason = re.search(r"Linear solve (?:converged|did not converge) due to (\w+) iterations (\d+)", out)
    dofs = re.search(r"^dofs (\d+)|unknowns: structure (\d+)|^\s+rows=(\d+), cols", out, re.M)
    mem = re.search(r"Maximum \(over computational time\) process memory:\s+total (\S+)", out)
    if "benchlib: TIMEOUT" in out:
        status = f"timeout ({timeout} s)"
    elif re.search(r"out of memory|Out of memory|OOM|Killed", out):
        status = "out of memory"
    elif "PETSc ERROR" in out or "exited on signal" in out or not reason:
        # PETSc's error class and message: the first two lines of its report that are not rules
        said = [m for m in re.findall(r"PETSC ERROR: (.*\S)", out) if not m.startswith("---")][:2]
        status = "error: " + (": ".join(said) if said else out.strip().splitlines()[-1] if out.strip() else "no output")[:120]
    elif not reason.group(1).startswith("CONVERGED"):
        status = "diverged " + reason.group(1)
    else:
        status = "ok"
    setup, solve = event("PCSetUp"), event("KSPSolve")
    return {"dofs": next(int(g) for g in dofs.groups() if g) if dofs else "",
            "status": status, "iterations": int(reason.group(2)) if reason else "",
            "setup_s": round(setup, 3), "solve_s": round(solve, 3), "total_s": round(setup + solve, 3),
            "memory_MB": round(float(mem.group(1)) / 1e6) if mem else "", "wall_s": round(wall, 1)}


def loadavg():
    return " ".join(f"{x:.2f}" for x in os.getloadavg())


def _cpu_times():
    """(steal, total) jiffies of all CPUs since boot (Linux /proc/stat), or None."""
    try:
        with open("/proc/stat") as f:
            v = [int(x) for x in f.readline().split()[1:]]
        return v[7] if len(v) > 7 else 0, sum(v[:8])
    except OSError:
        return None


_CPU_AT_START = _cpu_times()


def cpu_steal():
    """The share of CPU time a virtual machine's host took for others since the script started:
    timings of a run with a large share are slower than the code."""
    now = _cpu_times()
    if not now or not _CPU_AT_START or now[1] == _CPU_AT_START[1]:
        return "unknown"
    return f"{100.0 * (now[0] - _CPU_AT_START[0]) / (now[1] - _CPU_AT_START[1]):.1f} %"


def portable(cmd):
    """A command line as a reader reruns it from the repository root: paths inside the repository
    relative to it, a temporary report file named report.json."""
    cmd = cmd.replace(TOP + "/", "")
    return re.sub(r"/tmp/[^ ]*/([^/ ]+\.json)", r"\1", cmd)


_HEADERS = {}  # out -> the header lines this process last wrote there


def write_results(out, rows, cmds, producer, load_at_start=None, keep_earlier=False):
    """out.csv with one row per run, out.cmd with the command of each run, to be run from the
    repository root (and the load average at the start, if given, and now). keep_earlier: the
    rows come partly from earlier calls, so the header lines of those calls in out.cmd are kept
    below this call's."""
    if load_at_start is not None:
        producer += f"\n# load average (1, 5, 15 min) at start: {load_at_start}, at end: {loadavg()}; CPU steal during the runs: {cpu_steal()}"
    header = f"# produced by {producer}; run from the repository root".splitlines()
    earlier = []
    if keep_earlier and os.path.exists(out + ".cmd"):
        own = _HEADERS.get(out, [])
        earlier = [l for l in open(out + ".cmd").read().splitlines() if l.startswith("#") and l not in own]
    _HEADERS[out] = header
    with open(out + ".csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(dict.fromkeys(k for r in rows for k in r)))  # rows of earlier calls may lack later columns
        w.writeheader()
        w.writerows(rows)
    with open(out + ".cmd", "w") as f:
        f.write("\n".join(header + earlier + [portable(c) for c in cmds]) + "\n")


def run_report(cmd, report, timeout=None, cwd=TOP):
    """The JSON run report of an fsi_app command line run in cwd (which writes it to `report`),
    None if the run wrote none (its output's tail is printed)."""
    if os.path.exists(report):
        os.remove(report)
    log = run(cmd, timeout=timeout, cwd=cwd)
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


def check_command_line(doc, valued=(), flags=(), modes=(), mode_args=0):
    """Checks a script's command line before any run starts: -h or --help prints its usage (doc)
    and exits; an option it does not take, an option without its value, or a word that is not one
    of its modes stops it with a sentence naming what it takes. A mode may be followed by up to
    mode_args words of its own (bench_wall.py seed 3), which the script checks."""
    argv, name = sys.argv[1:], os.path.basename(sys.argv[0])
    if "-h" in argv or "--help" in argv:
        print(doc.strip())
        sys.exit(0)
    takes = ", ".join([f"{o} VALUE" for o in valued] + list(flags) + (["one of " + "|".join(modes)] if modes else [])) or "no arguments"
    words, i = [], 0
    while i < len(argv):
        a = argv[i]
        if a in valued:
            if i + 1 == len(argv) or argv[i + 1].startswith("--"):
                sys.exit(f"{name}: {a} needs a value; the script takes {takes} (--help for details)")
            i += 2
            continue
        if a.startswith("-") and a not in flags:
            sys.exit(f"{name}: unknown option {a}; the script takes {takes} (--help for details)")
        if not a.startswith("-"):
            words.append(a)
        i += 1
    if words and (words[0] not in modes or len(words) > 1 + mode_args):
        sys.exit(f"{name}: unexpected argument '{' '.join(words)}'; the script takes {takes} (--help for details)")
