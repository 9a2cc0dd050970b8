# produced by scripts/bench_fsi_pulse.py (one run)
# load average (1, 5, 15 min) at start: 0.34 1.53 1.68, at end: 2.01 2.01 1.93; CPU steal during the runs: 0.3 %; run from the repository root
mpiexec -n 2 build-dev/fsi_app/fsi_app -options_file scenes/fsi_tube1_arterial.opts -options_file scenes/fsi_facsi.opts -options_file scenes/fsi_inexact_newton.opts -mesh meshes/tube1_seed_fsi.msh -structure_subdomains 64 -dt 5e-4 -t_final 1e-2 -fluid_probes 0,0,0.625,0,0,1.25,0,0,1.875 -structure_probes 0.15,0,0.625,0.15,0,1.25,0.15,0,1.875 -report report.json
