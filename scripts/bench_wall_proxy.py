#!/usr/bin/python3
"""The seed's Table 2 in kind, for the wall alone (structure-only proxy of the FSI scene): tube #1
wall, clamped rings, the seed's inflow pressure 0.133 kPa applied inside for t <= T, backward
differences in time; for each material and time step: Newton steps per time step and CG (linear)
or GMRES (Neo-Hooke) iterations per Newton step, with the structure preconditioned by
  GDSW (element subdomains, overlap 1), GDSW-nr, OS1 (the same subdomains, no coarse level),
  PCASM (algebraic, one block per rank, overlap 1).
2 MPI ranks, 8 subdomains per rank. Writes bench/results/wall_proxy.{csv,cmd}.
Usage: scripts/bench_wall_proxy.py [T]   (default T = 0.003 s, the length of the pulse)"""
import os
import re
import sys

from benchlib import run, write_results

top = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
app = os.path.join(top, "build", "fsi_app", "fsi_app")
out = os.path.join(top, "bench", "results", "wall_proxy")
T = sys.argv[1] if len(sys.argv) > 1 else "0.003"

PCS = {
    "GDSW": "-pc_type gdsw",
    "GDSW-nr": "-pc_type gdsw -pc_gdsw_rotations 0",
    "OS1": "-pc_type gdsw -pc_gdsw_coarse_space none",
    "PCASM": "-pc_type asm -pc_asm_overlap 1 -pc_asm_type basic -sub_pc_type cholesky -sub_pc_factor_mat_solver_type cholmod",
}
MATERIALS = {"linear": "-material linear -snes_type ksponly -ksp_type cg",
             "neohooke": "-material neohooke -snes_type newtonls -snes_rtol 1e-8 -snes_atol 1e-8 -ksp_type gmres"}
rows, cmds = [], []
for mat, mopts in MATERIALS.items():
    for dt in ("1e-4", "5e-4"):
        for name, popts in PCS.items():
            cmd = (f"mpiexec -n 2 {app} -options_file {top}/scenes/wall_tube1_static.opts -dt {dt} -t_final {T} "
                   f"-structure_pressure_until 0.003 {mopts} -ksp_rtol 1e-6 {popts}")
            log = run(cmd)
            m = re.search(r"steps (\d+) newton per step (\S+) krylov per newton (\S+)", log)
            t = re.search(r"time (\S+) s", log)
            row = {"material": mat, "dt": dt, "preconditioner": name,
                   "newton_per_step": m.group(2) if m else "failed", "krylov_per_newton": m.group(3) if m else "failed",
                   "time_s": t.group(1) if t else "failed"}
            print(row, flush=True)
            rows.append(row)
            cmds.append(cmd)
write_results(out, rows, cmds, "scripts/bench_wall_proxy.py " + T)
