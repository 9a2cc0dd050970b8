# produced by scripts/bench_work_precision.py; run from the repository root
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/lame_cylinder.opts -mesh meshes/quarter_cylinder_L0.msh -ksp_type cg -pc_type gdsw -ksp_rtol 1e-10 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/lame_cylinder.opts -mesh meshes/quarter_cylinder_L0.msh -ksp_type cg -pc_type asm -pc_asm_overlap 1 -pc_asm_type basic -sub_pc_type cholesky -sub_pc_factor_mat_solver_type cholmod -ksp_rtol 1e-10 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/lame_cylinder.opts -mesh meshes/quarter_cylinder_L0.msh -ksp_type cg -pc_type gamg -ksp_rtol 1e-10 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/lame_cylinder.opts -mesh meshes/quarter_cylinder_L0.msh -ksp_type preonly -pc_type cholesky -pc_factor_mat_solver_type mumps -ksp_rtol 1e-10 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/lame_cylinder.opts -mesh meshes/quarter_cylinder_L1.msh -ksp_type cg -pc_type gdsw -ksp_rtol 1e-10 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/lame_cylinder.opts -mesh meshes/quarter_cylinder_L1.msh -ksp_type cg -pc_type asm -pc_asm_overlap 1 -pc_asm_type basic -sub_pc_type cholesky -sub_pc_factor_mat_solver_type cholmod -ksp_rtol 1e-10 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/lame_cylinder.opts -mesh meshes/quarter_cylinder_L1.msh -ksp_type cg -pc_type gamg -ksp_rtol 1e-10 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/lame_cylinder.opts -mesh meshes/quarter_cylinder_L1.msh -ksp_type preonly -pc_type cholesky -pc_factor_mat_solver_type mumps -ksp_rtol 1e-10 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/lame_cylinder.opts -mesh meshes/quarter_cylinder_L2.msh -ksp_type cg -pc_type gdsw -ksp_rtol 1e-10 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/lame_cylinder.opts -mesh meshes/quarter_cylinder_L2.msh -ksp_type cg -pc_type asm -pc_asm_overlap 1 -pc_asm_type basic -sub_pc_type cholesky -sub_pc_factor_mat_solver_type cholmod -ksp_rtol 1e-10 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/lame_cylinder.opts -mesh meshes/quarter_cylinder_L2.msh -ksp_type cg -pc_type gamg -ksp_rtol 1e-10 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/lame_cylinder.opts -mesh meshes/quarter_cylinder_L2.msh -ksp_type preonly -pc_type cholesky -pc_factor_mat_solver_type mumps -ksp_rtol 1e-10 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/mms_elasticity_cube.opts -refine 0 -ksp_type cg -pc_type gdsw -ksp_rtol 1e-10 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/mms_elasticity_cube.opts -refine 0 -ksp_type cg -pc_type asm -pc_asm_overlap 1 -pc_asm_type basic -sub_pc_type cholesky -sub_pc_factor_mat_solver_type cholmod -ksp_rtol 1e-10 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/mms_elasticity_cube.opts -refine 0 -ksp_type cg -pc_type gamg -ksp_rtol 1e-10 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/mms_elasticity_cube.opts -refine 0 -ksp_type preonly -pc_type cholesky -pc_factor_mat_solver_type mumps -ksp_rtol 1e-10 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/mms_elasticity_cube.opts -refine 1 -ksp_type cg -pc_type gdsw -ksp_rtol 1e-10 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/mms_elasticity_cube.opts -refine 1 -ksp_type cg -pc_type asm -pc_asm_overlap 1 -pc_asm_type basic -sub_pc_type cholesky -sub_pc_factor_mat_solver_type cholmod -ksp_rtol 1e-10 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/mms_elasticity_cube.opts -refine 1 -ksp_type cg -pc_type gamg -ksp_rtol 1e-10 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/mms_elasticity_cube.opts -refine 1 -ksp_type preonly -pc_type cholesky -pc_factor_mat_solver_type mumps -ksp_rtol 1e-10 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/mms_elasticity_cube.opts -refine 2 -ksp_type cg -pc_type gdsw -ksp_rtol 1e-10 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/mms_elasticity_cube.opts -refine 2 -ksp_type cg -pc_type asm -pc_asm_overlap 1 -pc_asm_type basic -sub_pc_type cholesky -sub_pc_factor_mat_solver_type cholmod -ksp_rtol 1e-10 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/mms_elasticity_cube.opts -refine 2 -ksp_type cg -pc_type gamg -ksp_rtol 1e-10 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/mms_elasticity_cube.opts -refine 2 -ksp_type preonly -pc_type cholesky -pc_factor_mat_solver_type mumps -ksp_rtol 1e-10 -report r.json
