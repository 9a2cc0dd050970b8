# produced by scripts/bench_fsi_solvers.py per_core
# load average (1, 5, 15 min) at start: 0.60 1.47 1.89, at end: 1.06 1.26 1.73; CPU steal during the runs: 0.0 %; run from the repository root
mpiexec -n 1 --mca mpi_yield_when_idle 1 build-dev/fsi_app/fsi_app -options_file scenes/fsi_tube1_linear.opts -options_file scenes/fsi_mumps_lagged.opts -mesh meshes/tube1_L1.msh -dt 1e-4 -t_final 2e-3 -report r.json
mpiexec -n 1 --mca mpi_yield_when_idle 1 build-dev/fsi_app/fsi_app -options_file scenes/fsi_tube1_linear.opts -options_file scenes/fsi_facsi.opts -structure_subdomains 16 -mesh meshes/tube1_L1.msh -dt 1e-4 -t_final 2e-3 -report r.json
mpiexec -n 1 --mca mpi_yield_when_idle 1 build-dev/fsi_app/fsi_app -options_file scenes/fsi_tube1_linear.opts -options_file scenes/fsi_facsi.opts -options_file scenes/fsi_inexact_newton.opts -structure_subdomains 16 -mesh meshes/tube1_L1.msh -dt 1e-4 -t_final 2e-3 -report r.json
