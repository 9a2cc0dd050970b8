# produced by scripts/bench_work_precision.py; run from the repository root
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_poiseuille.opts -mesh meshes/tube1_L0.msh  -ksp_rtol 1e-8 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_poiseuille.opts -mesh meshes/tube1_L0.msh -ksp_type preonly -pc_type lu -pc_factor_mat_solver_type mumps -ksp_rtol 1e-8 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_poiseuille.opts -mesh meshes/tube1_L1.msh  -ksp_rtol 1e-8 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_poiseuille.opts -mesh meshes/tube1_L1.msh -ksp_type preonly -pc_type lu -pc_factor_mat_solver_type mumps -ksp_rtol 1e-8 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_poiseuille.opts -mesh meshes/tube1_L2.msh  -ksp_rtol 1e-8 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_poiseuille.opts -mesh meshes/tube1_L2.msh -ksp_type preonly -pc_type lu -pc_factor_mat_solver_type mumps -ksp_rtol 1e-8 -report r.json
