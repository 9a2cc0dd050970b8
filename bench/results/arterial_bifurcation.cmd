# produced by scripts/bench_arterial.py bifurcation (184 of 184 steps run)
# load average (1, 5, 15 min) at start: 1.21 1.76 2.50, at end: 2.08 2.04 2.46; CPU steal during the runs: 0.4 %; run from the repository root
mpiexec -n 2 install/bin/fsi_app -options_file scenes/carotid_bifurcation.opts -options_file scenes/fsi_facsi_lu_fluid.opts -output bif.xdmf -output_every 4 -checkpoint bif.chk -checkpoint_every 10
mpiexec -n 2 install/bin/fsi_app -options_file scenes/carotid_bifurcation.opts -options_file scenes/fsi_facsi_lu_fluid.opts -output bif.xdmf -output_every 4 -checkpoint bif.chk -checkpoint_every 10 -restart bif.chk  # after a stop: continues from the newest checkpoint
