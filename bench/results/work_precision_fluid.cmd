# produced by scripts/bench_work_precision.py; run from the repository root
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_ale_mms_cube.opts -refine 0 -fieldsplit_1_pc_type fieldsplit -ksp_rtol 1e-8 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_ale_mms_cube.opts -refine 0  -ksp_rtol 1e-8 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_ale_mms_cube.opts -refine 0 -ksp_type preonly -pc_type lu -pc_factor_mat_solver_type mumps -ksp_rtol 1e-8 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_ale_mms_cube.opts -refine 1 -fieldsplit_1_pc_type fieldsplit -ksp_rtol 1e-8 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_ale_mms_cube.opts -refine 1  -ksp_rtol 1e-8 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_ale_mms_cube.opts -refine 1 -ksp_type preonly -pc_type lu -pc_factor_mat_solver_type mumps -ksp_rtol 1e-8 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_ale_mms_cube.opts -refine 2 -fieldsplit_1_pc_type fieldsplit -ksp_rtol 1e-8 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_ale_mms_cube.opts -refine 2  -ksp_rtol 1e-8 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_ale_mms_cube.opts -refine 2 -ksp_type preonly -pc_type lu -pc_factor_mat_solver_type mumps -ksp_rtol 1e-8 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_ale_mms_cube.opts -refine 0 -dt 0.25 -t_final 1 -geometry_ramp 1 -fieldsplit_1_pc_type fieldsplit -ksp_rtol 1e-8 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_ale_mms_cube.opts -refine 0 -dt 0.25 -t_final 1 -geometry_ramp 1  -ksp_rtol 1e-8 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_ale_mms_cube.opts -refine 0 -dt 0.25 -t_final 1 -geometry_ramp 1 -ksp_type preonly -pc_type lu -pc_factor_mat_solver_type mumps -ksp_rtol 1e-8 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_ale_mms_cube.opts -refine 1 -dt 0.25 -t_final 1 -geometry_ramp 1 -fieldsplit_1_pc_type fieldsplit -ksp_rtol 1e-8 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_ale_mms_cube.opts -refine 1 -dt 0.25 -t_final 1 -geometry_ramp 1  -ksp_rtol 1e-8 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_ale_mms_cube.opts -refine 1 -dt 0.25 -t_final 1 -geometry_ramp 1 -ksp_type preonly -pc_type lu -pc_factor_mat_solver_type mumps -ksp_rtol 1e-8 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_ale_mms_cube.opts -refine 2 -dt 0.25 -t_final 1 -geometry_ramp 1 -fieldsplit_1_pc_type fieldsplit -ksp_rtol 1e-8 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_ale_mms_cube.opts -refine 2 -dt 0.25 -t_final 1 -geometry_ramp 1  -ksp_rtol 1e-8 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_ale_mms_cube.opts -refine 2 -dt 0.25 -t_final 1 -geometry_ramp 1 -ksp_type preonly -pc_type lu -pc_factor_mat_solver_type mumps -ksp_rtol 1e-8 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_ale_mms_cube.opts -refine 0 -dt 0.25 -t_final 1 -geometry_ramp 1 -mms_ramp 1 -fieldsplit_1_pc_type fieldsplit -ksp_rtol 1e-8 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_ale_mms_cube.opts -refine 0 -dt 0.25 -t_final 1 -geometry_ramp 1 -mms_ramp 1  -ksp_rtol 1e-8 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_ale_mms_cube.opts -refine 0 -dt 0.25 -t_final 1 -geometry_ramp 1 -mms_ramp 1 -ksp_type preonly -pc_type lu -pc_factor_mat_solver_type mumps -ksp_rtol 1e-8 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_ale_mms_cube.opts -refine 1 -dt 0.09090909091 -t_final 1 -geometry_ramp 1 -mms_ramp 1 -fieldsplit_1_pc_type fieldsplit -ksp_rtol 1e-8 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_ale_mms_cube.opts -refine 1 -dt 0.09090909091 -t_final 1 -geometry_ramp 1 -mms_ramp 1  -ksp_rtol 1e-8 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_ale_mms_cube.opts -refine 1 -dt 0.09090909091 -t_final 1 -geometry_ramp 1 -mms_ramp 1 -ksp_type preonly -pc_type lu -pc_factor_mat_solver_type mumps -ksp_rtol 1e-8 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_ale_mms_cube.opts -refine 2 -dt 0.03125 -t_final 1 -geometry_ramp 1 -mms_ramp 1 -fieldsplit_1_pc_type fieldsplit -ksp_rtol 1e-8 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_ale_mms_cube.opts -refine 2 -dt 0.03125 -t_final 1 -geometry_ramp 1 -mms_ramp 1  -ksp_rtol 1e-8 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_ale_mms_cube.opts -refine 2 -dt 0.03125 -t_final 1 -geometry_ramp 1 -mms_ramp 1 -ksp_type preonly -pc_type lu -pc_factor_mat_solver_type mumps -ksp_rtol 1e-8 -report r.json
