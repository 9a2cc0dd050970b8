# produced by scripts/bench_work_precision.py fsi; run from the repository root
# load: 1.3 at the start (a build had just finished), nothing else ran; 2 ranks; 36 min in all
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fsi_tube1_linear.opts -mesh meshes/tube1_L0.msh -dt 0.0005 -t_final 0.006 -fluid_probes 0,0,1.25 -structure_probes 0.18,0,1.25 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fsi_tube1_linear.opts -mesh meshes/tube1_L0.msh -dt 0.00025 -t_final 0.006 -fluid_probes 0,0,1.25 -structure_probes 0.18,0,1.25 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fsi_tube1_linear.opts -mesh meshes/tube1_L0.msh -dt 0.000125 -t_final 0.006 -fluid_probes 0,0,1.25 -structure_probes 0.18,0,1.25 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fsi_tube1_linear.opts -mesh meshes/tube1_L1.msh -dt 0.0005 -t_final 0.006 -fluid_probes 0,0,1.25 -structure_probes 0.18,0,1.25 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fsi_tube1_linear.opts -mesh meshes/tube1_L1.msh -dt 0.00025 -t_final 0.006 -fluid_probes 0,0,1.25 -structure_probes 0.18,0,1.25 -report r.json
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fsi_tube1_linear.opts -mesh meshes/tube1_L1.msh -dt 0.000125 -t_final 0.006 -fluid_probes 0,0,1.25 -structure_probes 0.18,0,1.25 -report r.json
