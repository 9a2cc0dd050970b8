# produced by hand with farm-bench -n 3 --warmup 0 (whole process, median of 3), quiet machine (load 1.6 at start); run from the repository root
mpiexec -n 2 build/tests/petsc_ksp_ksp_ex71 -pde_type Elasticity -dim 3 -cells 31,31,31 -ksp_type cg -ksp_rtol 1e-8 -dll_append build/pc_gdsw/libpetscgdsw.so -pc_type gdsw -dm_mat_type is
mpiexec -n 2 build/tests/petsc_ksp_ksp_ex71 -pde_type Elasticity -dim 3 -cells 31,31,31 -ksp_type cg -ksp_rtol 1e-8 -dll_append build/pc_gdsw/libpetscgdsw.so -pc_type gdsw -dm_mat_type is -pc_gdsw_subdomains 1
mpiexec -n 2 build/tests/petsc_ksp_ksp_ex71 -pde_type Elasticity -dim 3 -cells 31,31,31 -ksp_type cg -ksp_rtol 1e-8 -dll_append build/pc_gdsw/libpetscgdsw.so -pc_type gdsw -dm_mat_type aij
