"""Shared by the bench_* scripts: run one command, and write its results as CSV plus the exact
commands that produced them."""
import csv
import os
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


def write_results(out, rows, cmds, producer):
    """out.csv with one row per run, out.cmd with the command of each run."""
    with open(out + ".csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    with open(out + ".cmd", "w") as f:
        f.write(f"# produced by {producer}\n" + "\n".join(cmds) + "\n")
