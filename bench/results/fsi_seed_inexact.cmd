# produced by hand on one machine, back to back, quiet (load 2.0: the runs' own ranks), 2026-12-02; run from the repository root.
# Rows 1-2 ran the code of the commit they name; rows 3-4 (two runs) the commit that added this file; the -log_view output is row 4's.
mpiexec -n 2 install/bin/fsi_app -options_file scenes/fsi_tube1_arterial.opts -options_file scenes/fsi_facsi.opts -options_file scenes/fsi_inexact_newton.opts -mesh meshes/tube1_seed_fsi.msh -dt 5e-4 -t_final 5e-4 -snes_monitor -ksp_converged_reason -structure_subdomains 64 -log_view :fsi_seed_inexact.log_view.txt -report report.json
# plot: scripts/plot_fsi_seed.py (writes fsi_seed_inexact.png from the CSV)
