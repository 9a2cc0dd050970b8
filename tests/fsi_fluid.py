#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""ctest cases for fsi_app: the fluid block (fixed and moving meshes) and the geometry block:
Poiseuille, the pulse, the manufactured ALE flows, shape derivatives, geometric conservation,
the harmonic extension. Each case runs fsi_app and asserts numbers of its run report
(tests/fsilib.py) against references independent of the code."""
import math

from fsilib import *  # noqa: F401,F403 (the cases' shared runners, meshes and scenes)
from testlib import between, case, main, run


@case
def fluid_poiseuille():
    """Hagen-Poiseuille flow in the rigid fluid region of tube #1: a fluid-only scene allocates
    no structure, geometry or multiplier unknowns; Newton (exact Jacobian, convection included)
    converges quadratically; FGMRES with the fieldsplit Schur preconditioner of
    scenes/fluid_schur.opts, and SIMPLE (scenes/fluid_simple.opts), give MUMPS's solution; the flux and velocity errors against the
    exact flow fall at rate 2 from tube1_L0 to tube1_L1 (the straight-sided tetrahedra's
    polygonal cross-section: the discretisation itself is exact for the quadratic profile only
    on an exact geometry), and so does the wall shear stress's against R dp / (2L) (measured
    1.94: 7.8 % -> 2.0 %); its OSI is 0 (a steady flow); 2 ranks give the flux and the wall
    shear stress of 1."""
    r = [flow(*POISEUILLE, "-mesh", os.path.join(MESHES, f"tube1_L{k}.msh"), "-snes_monitor") for k in (0, 1)]
    assert r[0]["unknowns"] == {"fluid": 2142, "pressure": 339}, r[0]
    assert r[1]["unknowns"]["fluid"] == 22974 and r[1]["unknowns"]["pressure"] == 1828, r[1]
    norms = r[0]["norms"]
    print("Newton residuals", norms)
    assert r[0]["newton"] <= 4 and norms[2] < 1e-3 * norms[1] and norms[1] < 1e-2 * norms[0], norms
    between(r[0]["krylov"] / r[0]["newton"], 5, 40, "FGMRES iterations per Newton step, fieldsplit Schur selfp + BoomerAMG")
    direct = flow(*POISEUILLE, "-ksp_type", "preonly", "-pc_type", "lu", "-pc_factor_mat_solver_type", "mumps")
    between(abs(direct["flux"] / r[0]["flux"] - 1), 0, 1e-6, "fieldsplit / MUMPS flux")
    simple = flow(*POISEUILLE, "-options_file", os.path.join(MESHES, "..", "scenes", "fluid_simple.opts"), "-ksp_view")
    between(abs(direct["flux"] / simple["flux"] - 1), 0, 1e-6, "SIMPLE / MUMPS flux")
    between(simple["krylov"] / simple["newton"], 5, 60, "FGMRES iterations per Newton step, SIMPLE")
    assert re.search(r"KSP solver for upper A00 in upper triangular factor\s+KSP Object: \(fieldsplit_pressure_upper_\).*?type: jacobi", simple["out"], re.S), "SIMPLE's diag(F)^-1"
    for key in ("flux_error", "l2_relative"):
        between(rates([x[key] for x in r])[0], 1.8, 2.4, f"{key} rate L0 -> L1")
    assert r[1]["flux_error"] < 0.035, r[1]
    two = flow(*POISEUILLE, np=2)
    between(two["flux"] / r[0]["flux"], 1 - 1e-6, 1 + 1e-6, "2 ranks / 1 rank flux")
    # the wall shear stress against R dp / (2L) = 4 mu Q / (pi R^3): the nodes of the ranks' seam sum both sides
    between(rates([x["results"]["wss_relative_error"] for x in r])[0], 1.7, 2.4, "wall shear stress rate L0 -> L1")
    between(two["results"]["wss_relative_error"] / r[0]["results"]["wss_relative_error"], 1 - 1e-6, 1 + 1e-6, "2 ranks / 1 rank wall shear stress error")
    between(r[0]["results"]["osi_max"], 0, 1e-12, "OSI of a steady flow")


@case
def fluid_poiseuille_curved():
    """The same flow on curved cells (tube1_L0 and tube1_L1 made with gmsh -order 2: the wall's
    edge nodes on the cylinder): the parabolic profile is P2, so only the geometry's error was
    left, and it now falls faster than the straight cells' rate 2: velocity L2 rate >= 2.7
    (measured 3.35: 5.2e-3 -> 5.1e-4 relative, against 11.4 % -> 2.7 % straight), the flux error
    below 1e-3 at L1 (7.8e-5, against 3.1 %). The wall shear stress against R dp / (2L) =
    4 mu Q / (pi R^3): rate >= 2 (measured 3.69: 6.3 % -> 0.49 %), its mean over the wall at L1
    within 0.2 % (0.013 %)."""
    r = [flow(*POISEUILLE, "-mesh", os.path.join(MESHES, f"tube1_L{k}_o2.msh")) for k in (0, 1)]
    assert r[0]["unknowns"] == {"fluid": 2142, "pressure": 339}, r[0]
    between(rates([x["l2_relative"] for x in r])[0], 2.7, 5, "velocity L2 rate L0 -> L1, curved cells")
    between(r[1]["flux_error"], 0, 1e-3, "relative flux error at L1, curved cells")
    wss = [x["results"]["wss_relative_error"] for x in r]
    between(rates(wss)[0], 2.0, 5, f"wall shear stress rate L0 -> L1, curved cells (errors {wss})")
    between(r[1]["results"]["tawss_mean"] / (0.15 * 10 / (2 * 2.5)), 0.998, 1.002, "mean wall shear stress / R dp / (2L), L1 curved")


@case
def fluid_pulse():
    """The seed's inflow pulse (1330 dyn/cm^2 for t <= 3 ms) in the rigid tube #1, backward
    Euler dt 0.5 ms up to 4 ms, 2 ranks, against the exact flow of a rigid pipe (unidirectional:
    the convection vanishes, the pressure is linear in z): on the axis p = p_in (1 - z/L) while the
    load acts (inlet p_in, outlet 0) and p = 0 after it, to 0.5 % of p_in (measured 0.13 %); what
    enters leaves (1e-6); the flux at 4 ms is 0.8-1.02 times the exact Q(4 ms) - Q(1 ms) of a
    3 ms pulse (Szymanski's flow superposed; measured 0.876 on tube1_L0, whose cells of 0.1 cm do
    not resolve the Stokes layer sqrt(nu t) = 0.01 cm: 0.95 on tube1_L1 at 2 ms). Newton
    converges in every step within 3 iterations, FGMRES with the fieldsplit preconditioner needs
    at most 20 iterations per Newton step; the XDMF output has velocity, pressure and the wall
    shear stress, its time average and OSI in every frame (the largest |wss| in the file is the
    report's); flow_boundaries.csv holds each boundary's flow and mean pressure per step (the
    exact flow's mean pressures to 0.5 % of p_in, no flow through the wall)."""
    tmp = tempfile.mkdtemp()
    p_in, L, axis = 1330, 2.5, [0, 0.625, 1.25, 1.875, 2.5]
    r = scene("-options_file", os.path.join(SCENES, "fluid_tube1_pulse.opts"), "-mesh", os.path.join(MESHES, "tube1_L0.msh"),
              "-t_final", 4e-3, "-output", os.path.join(tmp, "flow.xdmf"), "-fluid_probes", ",".join(f"0,0,{z}" for z in axis), np=2)
    steps = [(s["newton"], s["krylov"]) for s in r["steps"]]
    print(steps)
    assert len(steps) == 8 and all(n <= 3 and k <= 20 * n for n, k in steps), steps
    probes = r["probes"][0]
    for k, t in enumerate(probes["t"]):
        p = probes["values"][k * len(axis):(k + 1) * len(axis)]
        exact = [p_in * (1 - z / L) if t <= 3e-3 + 1e-12 else 0.0 for z in axis]
        between(max(abs(a - b) for a, b in zip(p, exact)) / p_in, 0, 5e-3, f"t {t}: max |p - p_in (1 - z/L)| on the axis / p_in")
    q_in, q_out = -r["results"]["inlet_flux"], r["results"]["outlet_flux"]
    between(abs(q_in - q_out) / q_out, 0, 1e-6, "|inflow - outflow| / outflow")
    between(q_out / (pipe_flux_step(p_in, 4e-3) - pipe_flux_step(p_in, 1e-3)), 0.8, 1.02, "flux at 4 ms / the exact pipe flow's")
    # the output holds velocity (P2) and pressure (P1, linear on the edges) at the 1894 P2 nodes, 9 frames
    listing = subprocess_out(["h5ls", "-r", os.path.join(tmp, "flow.h5")])
    assert len(re.findall(r"/fields/velocity_\d+ +Dataset \{1894, 3\}", listing)) == 9, listing
    assert len(re.findall(r"/fields/pressure_\d+ +Dataset \{1894\}", listing)) == 9, listing
    for name, shape in (("wss", "1894, 3"), ("tawss", "1894"), ("osi", "1894")):
        assert len(re.findall(rf"/fields/{name}_\d+ +Dataset \{{{shape}\}}", listing)) == 9, (name, listing)
    # the last frame's wall shear stress is the report's: nonzero only at the wall's nodes
    dump = subprocess_out(["h5dump", "-y", "-w", "0", "-m", "%.17g", "-d", "/fields/wss_8", os.path.join(tmp, "flow.h5")]).split("DATA {")[1]
    values = [float(v) for v in re.findall(r"-?\d+(?:\.\d+)?(?:e[-+]\d+)?", dump)]
    assert len(values) == 3 * 1894, len(values)
    tau = [math.sqrt(sum(v * v for v in values[3 * k:3 * k + 3])) for k in range(1894)]
    between(max(tau) / r["results"]["wss_max"], 1 - 1e-10, 1 + 1e-10, "largest |wss| in the file / the report's")
    assert 0 < sum(t > 0 for t in tau) < 1894, sum(t > 0 for t in tau)  # zero inside the fluid
    # each boundary's flow and mean pressure per step: the pipe's p_in (1 - z/L) averages to p_in at
    # the inlet, 0 at the outlet, p_in / 2 over the wall; nothing crosses the no-slip wall
    with open(os.path.join(tmp, "flow_boundaries.csv")) as f:
        rows = [line.strip().split(",") for line in f]
    assert rows[0] == ["t", "Q_inlet", "p_inlet", "Q_outlet", "p_outlet", "Q_interface", "p_interface"] and len(rows) == 9, rows
    for row in rows[1:]:
        t, q_in, p_inlet, q_out, p_outlet, q_wall, p_wall = map(float, row)
        on = p_in if t <= 3e-3 + 1e-12 else 0.0
        for value, exact, name in ((p_inlet, on, "inlet"), (p_outlet, 0.0, "outlet"), (p_wall, on / 2, "wall")):
            between(abs(value - exact) / p_in, 0, 5e-3, f"t {t}: |mean pressure - exact| on the {name} / p_in")
        assert q_wall == 0 and abs(q_in + q_out) <= 1e-6 * abs(q_out), row
    between(float(rows[-1][3]) / r["results"]["outlet_flux"], 1 - 1e-9, 1 + 1e-9, "the CSV's last outlet flow / the report's")
    shutil.rmtree(tmp)


@case
def fluid_pressure_waveform():
    """The inlet pressure as a signal of time, in the rigid tube #1 (2 ranks, backward Euler,
    dt 1 ms past one period of T = 10 ms): a Fourier series of its mean alone (T,1330) is the
    constant pressure of -fluid_inlet_pressure to round-off; samples of
    p = 1000 + 500 sin(2 pi t/T) + 200 cos(4 pi t/T) (64 per period, periodic cubic spline)
    give its Fourier series' flow within the spline's error bound 5/384 h^4 max|p^(4)| (4.4e-3
    dyn/cm^2, 4.4e-6 of the mean: the flow is linear in the data), and 16 samples at least 16
    times farther; the samples, named in an options file, are found beside it."""
    tmp = tempfile.mkdtemp()
    base = ["-options_file", os.path.join(SCENES, "fluid_tube1_pulse.opts"), "-t_final", 0.013, "-dt", 1e-3, "-ksp_rtol", 1e-12, "-fluid_inlet_pressure", 0]
    res = lambda *opts: scene(*base, *opts, np=2)["results"]
    const = res("-fluid_inlet_pressure", 1330, "-fluid_inlet_pressure_until", 0)
    mean = res("-fluid_inlet_pressure_fourier", "0.01,1330")
    for k in ("outlet_flux", "pressure_l2_norm", "velocity_l2_norm"):
        between(abs(mean[k] / const[k] - 1), 0, 1e-12, f"Fourier mean / constant pressure: {k}")
    T, p = 0.01, lambda t: 1000 + 500 * math.sin(2 * math.pi * t / T) + 200 * math.cos(4 * math.pi * t / T)
    fourier = res("-fluid_inlet_pressure_fourier", f"{T},1000,0,500,200,0")
    err = {}
    for n in (16, 64):
        samples = os.path.join(tmp, f"p{n}.dat")
        open(samples, "w").write("# t (s)  p (dyn/cm^2)\n" + "".join(f"{k * T / n:.17g} {p(k * T / n):.17g}\n" for k in range(n + 1)))
        opts = os.path.join(tmp, f"inlet{n}.opts")
        open(opts, "w").write(f"-fluid_inlet_pressure_waveform p{n}.dat\n")  # beside the options file
        sampled = res("-options_file", opts)
        err[n] = abs(sampled["outlet_flux"] / fourier["outlet_flux"] - 1)
    print("relative flux differences to the Fourier series", err)
    between(err[64], 0, 4.4e-6, "64 samples: |Q / Q_Fourier - 1| (the spline's error bound)")
    assert err[64] < err[16] / 16, err
    shutil.rmtree(tmp)


@case
def fluid_high_reynolds():
    """The pulse ten times stronger in a fluid a hundred times less viscous: Reynolds number
    (2 R u_max / nu) above 5,000 (8,200) after 1 ms, and backward Euler with Newton still converges in
    every step; the same flow sought as a steady state stops with a sentence that names the
    failure, nonzero exit status, and nothing but finite numbers printed."""
    base = ["-options_file", os.path.join(MESHES, "..", "scenes", "fluid_tube1_pulse.opts"), "-mesh", os.path.join(MESHES, "tube1_L0.msh"),
            "-fluid_viscosity", 3e-4, "-fluid_inlet_pressure", 13300]
    r = scene(*base, "-t_final", 1e-3, np=2)
    umax, steps = r["results"]["max_velocity"], [s["newton"] for s in r["steps"]]
    print("Reynolds", 2 * 0.15 * umax / 3e-4, "Newton per step", steps)
    assert len(steps) == 2 and all(n <= 4 for n in steps), steps
    assert 2 * 0.15 * umax / 3e-4 > 5e3, umax
    out = run([APP] + base + ["-dt", 0, "-max_step_cuts", 1], 2, fail=True)
    assert "failed in step 1" in out or "did not converge in step 1" in out, out[-2000:]
    assert "-pc_type lu -pc_factor_mat_solver_type mumps" in out or "-structure_load_steps" in out
    assert not re.search(r"max velocity (nan|inf)", out, re.I)


@case
def fluid_inflow():
    """A prescribed plug inflow u = (0, 0, 1) cm/s on tube #1's inlet, no-slip wall, stress-free
    outlet, steady, 2 ranks: what enters leaves (the discrete divergence is orthogonal to the
    constants, so to the solver's tolerance); the inflow is the plug over the inlet but the
    no-slip rim (between 0.6 and 1 times pi R^2); the inlet cannot also take a pressure."""
    base = ["-blocks", "fluid", "-mesh", os.path.join(MESHES, "tube1_L0.msh"), "-fluid_inflow_velocity", "0,0,1",
            "-options_file", os.path.join(SCENES, "fluid_schur.opts"), "-ksp_rtol", 1e-10]
    res = scene(*base, np=2)["results"]
    q_in, q_out = res["inlet_flux"], res["outlet_flux"]
    between(abs(q_in + q_out) / abs(q_in), 0, 1e-6, "|inflow - outflow| / inflow")
    between(-q_in / (3.141592653589793 * 0.15**2), 0.6, 1.0, "inflow / (pi R^2 U)")
    out = run([APP] + base + ["-fluid_inlet_pressure", 100], 1, fail=True)
    assert "-fluid_inflow_velocity: the inlet cannot also take -fluid_inlet_pressure" in out, out[-2000:]


@case
def fluid_ale_manufactured():
    """The manufactured Navier-Stokes flow (trigonometric, steady) on the unit cube whose mesh is
    displaced by the harmonic field a (x^2 - y^2, -2xy, 0), a = 0.1 (curved, isoparametric P2
    cells; its extension into the cube is exact): velocity L2 error at rate 3 and pressure L2
    error at rate 2 from refinement 1 to 2; the same rates, and errors within 6 % of the
    displaced mesh's, with the mesh moving under the steady flow (BDF2, 4 steps: the discrete
    time derivative at fixed X and the -(w . grad) u term must cancel); the fluid-only scene with
    a moving mesh allocates velocity, pressure and geometry unknowns and nothing else."""
    static = [ale("-refine", k) for k in range(3)]
    assert static[0]["unknowns"] == {"fluid": 249, "pressure": 45, "geometry": 186}, static[0]["unknowns"]
    moving = [ale("-refine", k, "-dt", 0.25, "-t_final", 1, "-geometry_ramp", 1) for k in (1, 2)]
    for name, runs in (("displaced", static[1:]), ("moving", moving)):
        u = [r["results"]["l2_error"] for r in runs]
        p = [r["results"]["pressure_l2_error"] for r in runs]
        print(name, "velocity L2", u, "pressure L2", p)
        between(rates(u)[0], 2.8, 3.2, f"velocity L2 rate, refinement 1 -> 2, {name} mesh")
        between(rates(p)[0], 1.8, 2.3, f"pressure L2 rate, refinement 1 -> 2, {name} mesh")
        assert all(n <= 5 for r in runs for n in r["newton_per_step"]), [r["newton_per_step"] for r in runs]
    for s, m in zip(static[1:], moving):
        between(m["results"]["l2_error"] / s["results"]["l2_error"], 0.97, 1.06, "velocity error moving / displaced mesh (measured 1.00 and 1.04: the time error shows at refinement 2)")
        between(m["results"]["max_mesh_displacement"], 0.14, 0.2, "the mesh moved (largest d_f)")


@case
def fluid_ale_exact_newton():
    """The Jacobian lacks the shape derivatives (d R_fluid / d d_f); -snes_mf_operator gives
    Newton the exact derivative (finite differences of the residual) with it as the
    preconditioning matrix: the same solution, and no more Newton steps."""
    quasi = ale("-refine", 1)
    exact = ale("-refine", 1, "-snes_mf_operator", "-ksp_type", "gmres")
    print("Newton steps: assembled", quasi["newton_per_step"], "matrix-free exact", exact["newton_per_step"])
    between(exact["results"]["l2_error"] / quasi["results"]["l2_error"], 1 - 1e-6, 1 + 1e-6, "velocity error -snes_mf_operator / assembled")
    assert exact["newton_per_step"][0] <= quasi["newton_per_step"][0], (exact["newton_per_step"], quasi["newton_per_step"])


@case
def fluid_shape_derivatives():
    """The fluid's shape derivatives (closed form for the volume terms, the body force's
    gradient by differences) against PETSc's finite-difference Jacobian of the whole residual
    (-snes_test_jacobian) on the manufactured flow with a moving mesh (BDF2: the mesh velocity
    moves with d_f): ||J - J_fd||_F / ||J||_F at most 1e-6 at every Newton step (measured
    2.5e-8, the differences' own error); without them 0.3 (the test can tell). The cube has no
    traction faces; their differenced derivatives are covered by fsi_exact_newton's quadratic
    convergence on the tube."""
    def worst(*opts):
        out = run([APP] + ALE_CUBE + ["-dt", 0.25, "-t_final", 0.5, "-geometry_ramp", 1, "-snes_test_jacobian", "-snes_max_it", 2,
                                      "-snes_rtol", 1e-14, "-snes_atol", 1e-30] + list(opts), 1, fail=None)
        ratios = [float(m) for m in re.findall(r"\|\|J - Jfd\|\|_F/\|\|J\|\|_F = (\S+),", out)]
        assert len(ratios) >= 4, out[-2000:]
        return max(ratios)
    exact, quasi = worst(), worst("-fluid_shape_derivatives", "false")
    print("largest ||J - J_fd|| / ||J||: with shape derivatives", exact, "without", quasi)
    between(exact, 0, 1e-6, "relative difference from the finite-difference Jacobian")
    between(quasi, 0.1, 1, "relative difference without the shape derivatives")


@case
def fluid_ale_time_order():
    """An unsteady manufactured flow (rising as sin^2 over 1 s) on the mesh moving with it: the
    successive differences of the largest velocity at t = 1 fall at rate 1 for backward Euler
    and rate 2 for BDF2 as the step halves."""
    for scheme, lo, hi in (("backward_euler", 0.8, 1.2), ("bdf2", 1.8, 2.6)):
        m = [ale("-dt", 0.125 / 2**k, "-t_final", 1, "-geometry_ramp", 1, "-mms_ramp", 1, "-time_scheme", scheme)["results"]["max_velocity"] for k in range(4)]
        d = [abs(m[k] - m[k + 1]) for k in range(3)]
        print(scheme, "largest velocity", m, "differences", d, "rates", rates(d))
        between(rates(d)[-1], lo, hi, f"{scheme} rate in dt on the moving mesh")


@case
def fluid_ale_geometric_conservation():
    """A uniform flow u = (1, 1/2, 1/4) stays uniform, to round-off, on a mesh that moves under
    it (a = 0.1 over 0.2 s, BDF2), on 2 ranks; the XDMF output carries the mesh displacement
    in every frame (ParaView: Warp By Vector shows the moved mesh)."""
    tmp = tempfile.mkdtemp()
    res = ale("-refine", 1, "-mms_flow", "uniform", "-dt", 0.05, "-t_final", 0.2, "-geometry_ramp", 0.2, "-output", os.path.join(tmp, "flow.xdmf"), np=2)["results"]
    between(res["l2_error"], 0, 1e-12, "velocity L2 error of the uniform flow")
    between(res["pressure_l2_error"], 0, 1e-12, "pressure L2 error (zero pressure)")
    between(res["max_mesh_displacement"], 0.1, 0.2, "largest mesh displacement")
    listing = subprocess_out(["h5ls", "-r", os.path.join(tmp, "flow.h5")])
    assert len(re.findall(r"/fields/displacement_\d+ +Dataset \{\d+, 3\}", listing)) == 5, listing
    shutil.rmtree(tmp)


@case
def fluid_ale_inverted_mesh():
    """A prescribed interface displacement too large for its harmonic extension (a = 0.5: J < 0
    near the corner x = y = 1) stops, on 2 ranks, with a sentence naming the option, a nonzero
    exit status and no NaN printed; no-slip walls on a moving mesh (they would need u = w, which
    the coupling will impose) are refused with a sentence."""
    out = run([APP] + ALE_CUBE + ["-geometry_amplitude", 0.5], 2, fail=True)
    assert "a cell of the moved fluid mesh inverted (J <= 0)" in out and "reduce -geometry_amplitude (0.5 now)" in out, out[-2000:]
    assert not re.search(r"\bnan\b", out, re.I)
    out = run([APP] + ALE_CUBE + ["-fluid_noslip", "x0"], 1, fail=True)
    assert "-blocks fluid,geometry with -fluid_noslip x0: a wall that moves needs u = w" in out, out[-2000:]


@case
def geometry_harmonic():
    """The geometry block alone: the harmonic extension into tube #1's fluid region of the
    interface displacement a (x^2 - y^2, -2xy, 0), sliding on the planar ends (z component
    zero): this field is harmonic and quadratic, so P2 reproduces it to the solver's tolerance;
    only geometry unknowns are allocated; 1 and 2 ranks agree."""
    for np in (1, 2):
        r = scene("-blocks", "geometry", "-mesh", os.path.join(MESHES, "tube1_L0.msh"), "-snes_type", "ksponly", "-ksp_type", "cg",
                  "-ksp_rtol", 1e-12, "-pc_type", "gamg", np=np)
        assert r["unknowns"] == {"geometry": 2088}, r["unknowns"]
        between(max(r["results"]["l2_relative"], r["results"]["h1_relative"]), 0, 1e-10, f"relative L2 and H1 errors of the extension, {np} rank(s)")
        between(r["krylov"], 5, 30, "CG + GAMG iterations (vector Laplacian)")


@case
def time_predictor_extrapolation():
    """Newton's first iterate extrapolated from the past states (-time_predictor_order k): the
    geometry block alone on a prescribed interface motion a s(t) (x^2 - y^2, -2xy, 0),
    s = sin^2(pi t / 2), is linear in its data, so the solution is s(t) D(x) and the first
    residual of the step to t^(n+1) is |s^(n+1) - p_k| |A D|, p_k the polynomial through
    s^n ... s^(n-k) at t^(n+1) (the states before t = 0 at rest). Each step's first residual,
    relative to order 0's first one, equals that closed form (BDF2 keeps four states: k <= 3)."""
    dt, steps = 0.1, 5
    s = [math.sin(math.pi * max(n, 0) * dt / 2) ** 2 for n in range(-4, steps + 1)]  # s[n + 4] = s(n dt)
    base = ["-blocks", "geometry", "-mesh", os.path.join(MESHES, "tube1_L0.msh"), "-fluid_region", "fluid", "-geometry_interface", "interface",
            "-geometry_slip", "inlet:z,outlet:z", "-geometry_amplitude", 0.1, "-geometry_ramp", 1, "-dt", dt, "-t_final", steps * dt,
            "-time_scheme", "bdf2", "-ksp_type", "cg", "-ksp_rtol", 1e-12, "-pc_type", "gamg"]
    unit = None
    for k in (0, 1, 2, 3):
        first = [st["first_residual"] for st in scene(*base, "-time_predictor_order", k)["steps"]]
        assert len(first) == steps, first
        unit = unit or first[0] / s[5]
        for n in range(steps):  # the step from n dt to (n + 1) dt
            w = [math.prod((1 + m) / (m - i) for m in range(k + 1) if m != i) for i in range(k + 1)]  # Lagrange weights at tau = 1
            predicted = sum(w[i] * s[n - i + 4] for i in range(k + 1))
            between(first[n] / unit, abs(s[n + 5] - predicted) * (1 - 1e-6), abs(s[n + 5] - predicted) * (1 + 1e-6),
                    f"order {k}, step {n + 1}: first residual relative to |A D|")


if __name__ == "__main__":
    main("fsi_fluid")
