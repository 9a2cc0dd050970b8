# produced by scripts/bench_arterial.py subdomains
# load average (1, 5, 15 min) at start: 0.40 0.62 2.21, at end: 4.10 5.04 5.55; CPU steal during the runs: 0.2 %; run from the repository root
mpiexec -n 2 install/bin/fsi_app -options_file scenes/carotid_bifurcation.opts -options_file scenes/fsi_facsi_lu_fluid.opts -t_final 0.01 -structure_subdomains 1 -report r.json
mpiexec -n 2 install/bin/fsi_app -options_file scenes/carotid_bifurcation.opts -options_file scenes/fsi_facsi_lu_fluid.opts -t_final 0.01 -structure_subdomains 1 -fieldsplit_structure_pc_gdsw_coarse_space none -report r.json
mpiexec -n 2 install/bin/fsi_app -options_file scenes/carotid_bifurcation.opts -options_file scenes/fsi_facsi_lu_fluid.opts -t_final 0.01 -structure_subdomains 4 -report r.json
mpiexec -n 2 install/bin/fsi_app -options_file scenes/carotid_bifurcation.opts -options_file scenes/fsi_facsi_lu_fluid.opts -t_final 0.01 -structure_subdomains 4 -fieldsplit_structure_pc_gdsw_coarse_space none -report r.json
mpiexec -n 2 install/bin/fsi_app -options_file scenes/carotid_bifurcation.opts -options_file scenes/fsi_facsi_lu_fluid.opts -t_final 0.01 -structure_subdomains 16 -report r.json
mpiexec -n 2 install/bin/fsi_app -options_file scenes/carotid_bifurcation.opts -options_file scenes/fsi_facsi_lu_fluid.opts -t_final 0.01 -structure_subdomains 16 -fieldsplit_structure_pc_gdsw_coarse_space none -report r.json
mpiexec -n 2 install/bin/fsi_app -options_file scenes/carotid_bifurcation.opts -options_file scenes/fsi_facsi_lu_fluid.opts -t_final 0.01 -structure_subdomains 64 -report r.json
mpiexec -n 2 install/bin/fsi_app -options_file scenes/carotid_bifurcation.opts -options_file scenes/fsi_facsi_lu_fluid.opts -t_final 0.01 -structure_subdomains 64 -fieldsplit_structure_pc_gdsw_coarse_space none -report r.json
