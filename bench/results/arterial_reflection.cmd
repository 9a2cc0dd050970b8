# produced by scripts/bench_arterial.py reflection (c 367.6 cm/s, Z_c 5200.0 dyn s/cm^5, reflected amplitude 305.1 -> 50.9 dyn/cm^2)
# load average (1, 5, 15 min) at start: 1.26 1.87 3.56, at end: 1.71 1.89 3.46; CPU steal during the runs: 0.1 %; run from the repository root
mpiexec -n 2 install/bin/fsi_app -options_file scenes/fsi_tube1_arterial.opts -options_file scenes/fsi_facsi.opts -t_final 1.5e-2 -fluid_probes 0,0,0.625,0,0,1.25 -report free.json
mpiexec -n 2 install/bin/fsi_app -options_file scenes/fsi_tube1_arterial.opts -options_file scenes/fsi_facsi.opts -t_final 1.5e-2 -fluid_probes 0,0,0.625,0,0,1.25 -blocks structure,fluid,geometry,coupling,outlets -outlets_outlet_resistance 5200.0 -report matched.json
