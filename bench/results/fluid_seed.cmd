# produced by scripts/bench_fluid.py seed (load: 19:12:19 up  1:24,  0 user,  load average: 2.02, 2.00, 2.00 / after: 19:14:12 up  1:26,  0 user,  load average: 2.00, 1.98, 2.00); run from the repository root
mpiexec -n 2 build/fsi_app/fsi_app -options_file scenes/fluid_tube1_pulse.opts -mesh meshes/tube1_seed_fluid.msh -dt 5e-4 -t_final 0.001  -report r.json
