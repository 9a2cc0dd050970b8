# produced by scripts/bench_gdsw_suite.py --sweep; run from the repository root
# GDSW_BUILD=build
# load average (1, 5, 15 min) at start: 2.44 2.35 2.29
# load average (1, 5, 15 min) at end: 2.78 2.86 2.56
mpiexec -n 2 build/pc_gdsw/gdsw_elasticity -n 23 -pc_gdsw_subdomains 1 -ksp_type cg -ksp_rtol 1e-8 -ksp_max_it 2000 -ksp_converged_reason -log_view -memory_view
mpiexec -n 2 build/pc_gdsw/gdsw_elasticity -n 23 -pc_gdsw_subdomains 2 -ksp_type cg -ksp_rtol 1e-8 -ksp_max_it 2000 -ksp_converged_reason -log_view -memory_view
mpiexec -n 2 build/pc_gdsw/gdsw_elasticity -n 23 -pc_gdsw_subdomains 4 -ksp_type cg -ksp_rtol 1e-8 -ksp_max_it 2000 -ksp_converged_reason -log_view -memory_view
mpiexec -n 2 build/pc_gdsw/gdsw_elasticity -n 23 -pc_gdsw_subdomains 8 -ksp_type cg -ksp_rtol 1e-8 -ksp_max_it 2000 -ksp_converged_reason -log_view -memory_view
mpiexec -n 2 build/pc_gdsw/gdsw_elasticity -n 23 -pc_gdsw_subdomains 16 -ksp_type cg -ksp_rtol 1e-8 -ksp_max_it 2000 -ksp_converged_reason -log_view -memory_view
mpiexec -n 2 build/pc_gdsw/gdsw_elasticity -n 23 -pc_gdsw_subdomains 32 -ksp_type cg -ksp_rtol 1e-8 -ksp_max_it 2000 -ksp_converged_reason -log_view -memory_view
mpiexec -n 2 build/pc_gdsw/gdsw_elasticity -n 31 -pc_gdsw_subdomains 1 -ksp_type cg -ksp_rtol 1e-8 -ksp_max_it 2000 -ksp_converged_reason -log_view -memory_view
mpiexec -n 2 build/pc_gdsw/gdsw_elasticity -n 31 -pc_gdsw_subdomains 2 -ksp_type cg -ksp_rtol 1e-8 -ksp_max_it 2000 -ksp_converged_reason -log_view -memory_view
mpiexec -n 2 build/pc_gdsw/gdsw_elasticity -n 31 -pc_gdsw_subdomains 4 -ksp_type cg -ksp_rtol 1e-8 -ksp_max_it 2000 -ksp_converged_reason -log_view -memory_view
mpiexec -n 2 build/pc_gdsw/gdsw_elasticity -n 31 -pc_gdsw_subdomains 8 -ksp_type cg -ksp_rtol 1e-8 -ksp_max_it 2000 -ksp_converged_reason -log_view -memory_view
mpiexec -n 2 build/pc_gdsw/gdsw_elasticity -n 31 -pc_gdsw_subdomains 16 -ksp_type cg -ksp_rtol 1e-8 -ksp_max_it 2000 -ksp_converged_reason -log_view -memory_view
mpiexec -n 2 build/pc_gdsw/gdsw_elasticity -n 31 -pc_gdsw_subdomains 32 -ksp_type cg -ksp_rtol 1e-8 -ksp_max_it 2000 -ksp_converged_reason -log_view -memory_view
mpiexec -n 2 build/pc_gdsw/gdsw_elasticity -n 39 -pc_gdsw_subdomains 1 -ksp_type cg -ksp_rtol 1e-8 -ksp_max_it 2000 -ksp_converged_reason -log_view -memory_view
mpiexec -n 2 build/pc_gdsw/gdsw_elasticity -n 39 -pc_gdsw_subdomains 2 -ksp_type cg -ksp_rtol 1e-8 -ksp_max_it 2000 -ksp_converged_reason -log_view -memory_view
mpiexec -n 2 build/pc_gdsw/gdsw_elasticity -n 39 -pc_gdsw_subdomains 4 -ksp_type cg -ksp_rtol 1e-8 -ksp_max_it 2000 -ksp_converged_reason -log_view -memory_view
mpiexec -n 2 build/pc_gdsw/gdsw_elasticity -n 39 -pc_gdsw_subdomains 8 -ksp_type cg -ksp_rtol 1e-8 -ksp_max_it 2000 -ksp_converged_reason -log_view -memory_view
mpiexec -n 2 build/pc_gdsw/gdsw_elasticity -n 39 -pc_gdsw_subdomains 16 -ksp_type cg -ksp_rtol 1e-8 -ksp_max_it 2000 -ksp_converged_reason -log_view -memory_view
mpiexec -n 2 build/pc_gdsw/gdsw_elasticity -n 39 -pc_gdsw_subdomains 32 -ksp_type cg -ksp_rtol 1e-8 -ksp_max_it 2000 -ksp_converged_reason -log_view -memory_view
