# produced by scripts/bench_arterial.py support
# load average (1, 5, 15 min) at start: 7.87 8.03 7.39, at end: 6.35 6.63 7.06; CPU steal during the runs: 0.2 %; run from the repository root
mpiexec -n 2 install/bin/fsi_app -options_file scenes/fsi_tube1_arterial.opts -options_file scenes/fsi_facsi.opts -t_final 1.5e-2 -fluid_probes 0,0,0.625,0,0,1.25,0,0,1.875 -report r.json
mpiexec -n 2 install/bin/fsi_app -options_file scenes/fsi_tube1_arterial.opts -options_file scenes/fsi_facsi.opts -t_final 1.5e-2 -fluid_probes 0,0,0.625,0,0,1.25,0,0,1.875 -structure_support 1e+06 -report r.json
mpiexec -n 2 install/bin/fsi_app -options_file scenes/fsi_tube1_arterial.opts -options_file scenes/fsi_facsi.opts -t_final 1.5e-2 -fluid_probes 0,0,0.625,0,0,1.25,0,0,1.875 -structure_support 3e+06 -report r.json
mpiexec -n 2 install/bin/fsi_app -options_file scenes/fsi_tube1_arterial.opts -options_file scenes/fsi_facsi.opts -t_final 1.5e-2 -fluid_probes 0,0,0.625,0,0,1.25,0,0,1.875 -structure_support 1e+07 -report r.json
