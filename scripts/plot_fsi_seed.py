#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""The coupled step at the benchmark's size by phase: one stacked bar per row of
bench/results/fsi_seed_inexact.csv (assembly, the structure's set-up, the other set-up, and the
rest of the step: Krylov less the inner solvers' set-up that split PCs do inside KSPSolve, which
the report counts in both), the 5-minute target as a line. Writes
bench/results/fsi_seed_inexact.png.

Usage: scripts/plot_fsi_seed.py"""
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

top = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
rows = list(csv.DictReader(open(os.path.join(top, "bench", "results", "fsi_seed_inexact.csv"))))
phases = (("assembly_per_step", "assembly"), ("structure_setup_per_step", "structure set-up (GDSW)"),
          ("other_setup_per_step", "other set-up"), (None, "Krylov (the rest of the step)"))
fig, ax = plt.subplots(figsize=(8, 4.5))
bottom = [0.0] * len(rows)
for key, name in phases:
    values = [float(r[key]) if key else float(r["seconds_per_step"]) - b for r, b in zip(rows, bottom)]
    ax.bar(range(len(rows)), values, bottom=bottom, label=name)
    bottom = [b + v for b, v in zip(bottom, values)]
for k, r in enumerate(rows):
    ax.text(k, bottom[k] + 5, f"{float(r['seconds_per_step']):.0f} s\n{float(r['gmres_per_newton']) * float(r['newton_per_step']):.0f} GMRES\n"
            f"{float(r['peak_memory_mib']) / 1024:.1f} GiB", ha="center", va="bottom", fontsize=8,
            bbox=dict(facecolor="white", edgecolor="none", pad=1))
ax.axhline(300, color="k", ls="--", lw=1, label="5 minutes")
ax.set_xticks(range(len(rows)))
ax.set_xticklabels([f"{k + 1}" for k in range(len(rows))])
ax.set_xlabel("row of bench/results/fsi_seed_inexact.csv (same machine, back to back)")
ax.set_ylabel("seconds for the time step")
ax.set_ylim(0, 1.25 * max(bottom))
ax.set_title("tube #1 at the benchmark's size (1.67 M unknowns), arterial wall, dt = 0.5 ms, 2 ranks", fontsize=9)
ax.legend(fontsize=8, loc="upper right")
fig.tight_layout()
out = os.path.join(top, "bench", "results", "fsi_seed_inexact.png")
fig.savefig(out, dpi=120)
print(out)
