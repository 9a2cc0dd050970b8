"""Shared by the bench_* scripts: run one command, and write its results as CSV plus the exact
commands that produced them."""
import csv
import os
import subprocess

ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")


def run(cmd):
    """Output (stdout and stderr) of a command line."""
    return subprocess.run(cmd.split(), env=ENV, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True).stdout


def write_results(out, rows, cmds, producer):
    """out.csv with one row per run, out.cmd with the command of each run."""
    with open(out + ".csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    with open(out + ".cmd", "w") as f:
        f.write(f"# produced by {producer}\n" + "\n".join(cmds) + "\n")
