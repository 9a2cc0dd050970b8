# produced by scripts/bench_work_precision.py
mpiexec -n 2 /work/main/build/fsi_app/fsi_app -options_file /work/main/scenes/fluid_poiseuille.opts -mesh /work/main/meshes/tube1_L0.msh  -ksp_rtol 1e-8 -report /tmp/tmpvatxj0kn/r.json
mpiexec -n 2 /work/main/build/fsi_app/fsi_app -options_file /work/main/scenes/fluid_poiseuille.opts -mesh /work/main/meshes/tube1_L0.msh -ksp_type preonly -pc_type lu -pc_factor_mat_solver_type mumps -ksp_rtol 1e-8 -report /tmp/tmpvatxj0kn/r.json
mpiexec -n 2 /work/main/build/fsi_app/fsi_app -options_file /work/main/scenes/fluid_poiseuille.opts -mesh /work/main/meshes/tube1_L1.msh  -ksp_rtol 1e-8 -report /tmp/tmpvatxj0kn/r.json
mpiexec -n 2 /work/main/build/fsi_app/fsi_app -options_file /work/main/scenes/fluid_poiseuille.opts -mesh /work/main/meshes/tube1_L1.msh -ksp_type preonly -pc_type lu -pc_factor_mat_solver_type mumps -ksp_rtol 1e-8 -report /tmp/tmpvatxj0kn/r.json
mpiexec -n 2 /work/main/build/fsi_app/fsi_app -options_file /work/main/scenes/fluid_poiseuille.opts -mesh /work/main/meshes/tube1_L2.msh  -ksp_rtol 1e-8 -report /tmp/tmpvatxj0kn/r.json
mpiexec -n 2 /work/main/build/fsi_app/fsi_app -options_file /work/main/scenes/fluid_poiseuille.opts -mesh /work/main/meshes/tube1_L2.msh -ksp_type preonly -pc_type lu -pc_factor_mat_solver_type mumps -ksp_rtol 1e-8 -report /tmp/tmpvatxj0kn/r.json
