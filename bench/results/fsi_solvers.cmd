# produced by scripts/bench_fsi_solvers.py solvers; run from the repository root
# load average (1, 5, 15 min) at start: 2.07 2.14 2.25, at end: 2.01 2.10 2.22
mpiexec -n 2 --mca mpi_yield_when_idle 1 build/fsi_app/fsi_app -options_file scenes/fsi_tube1_linear.opts  -mesh meshes/tube1_L0.msh -dt 5e-4 -t_final 1e-3 -report r.json
mpiexec -n 2 --mca mpi_yield_when_idle 1 build/fsi_app/fsi_app -options_file scenes/fsi_tube1_linear.opts -options_file scenes/fsi_fieldsplit.opts -mesh meshes/tube1_L0.msh -dt 5e-4 -t_final 1e-3 -report r.json
mpiexec -n 2 --mca mpi_yield_when_idle 1 build/fsi_app/fsi_app -options_file scenes/fsi_tube1_linear.opts -options_file scenes/fsi_facsi.opts -structure_subdomains 16 -mesh meshes/tube1_L0.msh -dt 5e-4 -t_final 1e-3 -report r.json
mpiexec -n 2 --mca mpi_yield_when_idle 1 build/fsi_app/fsi_app -options_file scenes/fsi_tube1_linear.opts  -mesh meshes/tube1_L1.msh -dt 5e-4 -t_final 1e-3 -report r.json
mpiexec -n 2 --mca mpi_yield_when_idle 1 build/fsi_app/fsi_app -options_file scenes/fsi_tube1_linear.opts -options_file scenes/fsi_fieldsplit.opts -mesh meshes/tube1_L1.msh -dt 5e-4 -t_final 1e-3 -report r.json
mpiexec -n 2 --mca mpi_yield_when_idle 1 build/fsi_app/fsi_app -options_file scenes/fsi_tube1_linear.opts -options_file scenes/fsi_facsi.opts -structure_subdomains 16 -mesh meshes/tube1_L1.msh -dt 5e-4 -t_final 1e-3 -report r.json
