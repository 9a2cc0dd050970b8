# produced by scripts/bench_arterial.py carotid
# load average (1, 5, 15 min) at start: 1.34 1.73 3.31, at end: 2.08 2.03 2.07; CPU steal during the runs: 0.1 %; run from the repository root
mpiexec -n 2 install/bin/fsi_app -options_file scenes/carotid_tube.opts -options_file scenes/fsi_facsi_lu_fluid.opts -output carotid.xdmf -output_every 1000 -report r.json
