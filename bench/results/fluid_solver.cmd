# produced by scripts/bench_fluid.py (load: 19:17:41 up  1:29,  0 user,  load average: 0.42, 1.09, 1.63 / after: 19:28:54 up  1:41,  0 user,  load average: 2.08, 1.95, 1.85); run from the repository root
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_tube1_pulse.opts -mesh meshes/tube1_L0.msh -dt 1e-4 -t_final 0.0004  -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_tube1_pulse.opts -mesh meshes/tube1_L0.msh -dt 1e-4 -t_final 0.0004 -options_file scenes/fluid_simple.opts -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_tube1_pulse.opts -mesh meshes/tube1_L0.msh -dt 1e-4 -t_final 0.0004 -ksp_type preonly -pc_type lu -pc_factor_mat_solver_type mumps -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_tube1_pulse.opts -mesh meshes/tube1_L0.msh -dt 5e-4 -t_final 0.002  -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_tube1_pulse.opts -mesh meshes/tube1_L0.msh -dt 5e-4 -t_final 0.002 -options_file scenes/fluid_simple.opts -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_tube1_pulse.opts -mesh meshes/tube1_L0.msh -dt 5e-4 -t_final 0.002 -ksp_type preonly -pc_type lu -pc_factor_mat_solver_type mumps -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_tube1_pulse.opts -mesh meshes/tube1_L0.msh -dt 2e-3 -t_final 0.008  -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_tube1_pulse.opts -mesh meshes/tube1_L0.msh -dt 2e-3 -t_final 0.008 -options_file scenes/fluid_simple.opts -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_tube1_pulse.opts -mesh meshes/tube1_L0.msh -dt 2e-3 -t_final 0.008 -ksp_type preonly -pc_type lu -pc_factor_mat_solver_type mumps -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_tube1_pulse.opts -mesh meshes/tube1_L1.msh -dt 1e-4 -t_final 0.0004  -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_tube1_pulse.opts -mesh meshes/tube1_L1.msh -dt 1e-4 -t_final 0.0004 -options_file scenes/fluid_simple.opts -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_tube1_pulse.opts -mesh meshes/tube1_L1.msh -dt 1e-4 -t_final 0.0004 -ksp_type preonly -pc_type lu -pc_factor_mat_solver_type mumps -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_tube1_pulse.opts -mesh meshes/tube1_L1.msh -dt 5e-4 -t_final 0.002  -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_tube1_pulse.opts -mesh meshes/tube1_L1.msh -dt 5e-4 -t_final 0.002 -options_file scenes/fluid_simple.opts -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_tube1_pulse.opts -mesh meshes/tube1_L1.msh -dt 5e-4 -t_final 0.002 -ksp_type preonly -pc_type lu -pc_factor_mat_solver_type mumps -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_tube1_pulse.opts -mesh meshes/tube1_L1.msh -dt 2e-3 -t_final 0.008  -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_tube1_pulse.opts -mesh meshes/tube1_L1.msh -dt 2e-3 -t_final 0.008 -options_file scenes/fluid_simple.opts -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_tube1_pulse.opts -mesh meshes/tube1_L1.msh -dt 2e-3 -t_final 0.008 -ksp_type preonly -pc_type lu -pc_factor_mat_solver_type mumps -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_tube1_pulse.opts -mesh meshes/tube1_L2.msh -dt 1e-4 -t_final 0.0004  -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_tube1_pulse.opts -mesh meshes/tube1_L2.msh -dt 1e-4 -t_final 0.0004 -options_file scenes/fluid_simple.opts -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_tube1_pulse.opts -mesh meshes/tube1_L2.msh -dt 5e-4 -t_final 0.002  -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_tube1_pulse.opts -mesh meshes/tube1_L2.msh -dt 5e-4 -t_final 0.002 -options_file scenes/fluid_simple.opts -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_tube1_pulse.opts -mesh meshes/tube1_L2.msh -dt 5e-4 -t_final 0.002 -ksp_type preonly -pc_type lu -pc_factor_mat_solver_type mumps -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_tube1_pulse.opts -mesh meshes/tube1_L2.msh -dt 2e-3 -t_final 0.008  -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_tube1_pulse.opts -mesh meshes/tube1_L2.msh -dt 2e-3 -t_final 0.008 -options_file scenes/fluid_simple.opts -report r.json
