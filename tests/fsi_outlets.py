#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""ctest cases for fsi_app's arterial boundary conditions: an inflow rate Q(t) with its velocity
profile (plug, parabolic, Womersley), the outlets block's 0D models (resistance, three-element
Windkessel) on several outlets, implicit in Newton, in FaCSI's sweep and in a restart, and the
backflow term. References: Womersley's analytic flow, the models' own equations integrated here
by the scheme's recurrence from the flows the run reports, the volume balance, an exact solver."""
import math
import os
import re
import tempfile

from fsilib import *  # noqa: F401,F403 (the cases' shared runners, meshes and scenes)
from testlib import between, case, main, run

SPLIT = ["-mesh", os.path.join(MESHES, "split_tube_L0.msh"), "-blocks", "fluid,outlets", "-fluid_region", "fluid",
         "-fluid_noslip", "interface", "-fluid_inlet", "inlet", "-fluid_outlet", "outlet_a,outlet_b",
         "-fluid_density", 1.06, "-fluid_viscosity", 0.035, "-fluid_inlet_pressure", 100,
         "-ksp_type", "preonly", "-pc_type", "lu", "-pc_factor_mat_solver_type", "mumps", "-snes_rtol", 1e-12, "-snes_atol", 1e-12]
R, RP, C, RD, PD = 1000.0, 200.0, 1e-4, 800.0, 30.0
MODELS = ["-outlets_outlet_a_resistance", R, "-outlets_outlet_b_rcr", f"{RP},{C},{RD},{PD}"]


def series(r, group):
    """(t, Q, P, Pi) of an outlet from the run report."""
    s = next(p for p in r["probes"] if p["field"] == "outlet_" + group)
    v = s["values"]
    return s["t"], v[0::3], v[1::3], v[2::3]


def windkessel(q, dt, scheme):
    """Pi and P of C dPi/dt + (Pi - P_d)/R_d = Q, P = R_p Q + Pi, integrated by the scheme's own
    recurrence from rest (Pi = P_d since t = -infinity) for the flows q at t = dt, 2 dt, ..."""
    pi, past = [], [PD, PD]
    for qn in q:
        if scheme == "bdf2":  # (3 Pi^n - 4 Pi^(n-1) + Pi^(n-2)) / (2 dt)
            x = (C * (4 * past[-1] - past[-2]) / (2 * dt) + PD / RD + qn) / (3 * C / (2 * dt) + 1 / RD)
        else:
            x = (C * past[-1] / dt + PD / RD + qn) / (C / dt + 1 / RD)
        pi.append(x)
        past.append(x)
    return pi, [RP * qn + x for qn, x in zip(q, pi)]


WOMERSLEY = ["-blocks", "fluid", "-fluid_region", "fluid", "-fluid_noslip", "interface", "-fluid_inlet", "inlet", "-fluid_outlet", "outlet",
             "-fluid_density", 1.06, "-fluid_viscosity", 0.35, "-fluid_inflow_profile", "womersley", "-womersley", "-time_scheme", "bdf2",
             "-fluid_inflow_fourier", "0.05,0.5,0.3,0.2", "-t_final", 0.1, "-ksp_type", "preonly", "-pc_type", "lu", "-pc_factor_mat_solver_type", "mumps"]


def rate(e0, e1, ratio=2):
    return math.log(e0 / e1) / math.log(ratio)


@case
def womersley_flow():
    """Womersley's flow in a rigid tube (R 0.15 cm, curved cells, 2 ranks): the flow rate
    0.5 + 0.3 cos wt + 0.2 sin wt cm^3/s (period 0.05 s, Womersley number 2.93) through the inlet
    with Womersley's profile, the exact flow's traction on the outlet; from rest for two periods
    (the start's transient decays as exp(-t / 0.012 s)). The velocity's L2 error over the second
    period against Womersley's analytic velocity (Bessel functions of complex argument) falls
    at order >= 2.7 in h (dt = T/80; P2 on curved cells: 3) and >= 1.8 in dt (BDF2, dt = T/5, T/10
    on the finer mesh); the inlet's flux is the given rate at the last step to 1e-12. The wall
    shear stress -mu dW/dr(R, t) against the exact one over the second period: 3.1 % -> 1.1 %
    (rate 1.53: the nodal gradients of the Stokes layer, not the time step: halving dt on
    level 0 leaves 3.08 %), asserted >= 1.3 and <= 1.5 % on level 1."""
    mesh = lambda k: ["-mesh", os.path.join(MESHES, f"womersley_L{k}_o2.msh")]  # noqa: E731
    fine = [scene(*WOMERSLEY, *mesh(k), "-dt", 6.25e-4, np=2) for k in (0, 1)]
    e = [r["results"]["womersley_l2_relative"] for r in fine]
    between(rate(*e), 2.7, 3.5, f"velocity L2 rate in h, errors {e}")
    between(e[1], 0, 1e-3, "relative L2 error, level 1")
    between(abs(fine[1]["results"]["inlet_flux"] + 0.8) / 0.8, 0, 1e-12, "inlet flux / Q(t_final)")
    wss = [r["results"]["womersley_wss_relative"] for r in fine]
    between(rate(*wss), 1.3, 3.5, f"wall shear stress rate in h, errors {wss}")
    between(wss[1], 0, 1.5e-2, "wall shear stress relative error, level 1")
    coarse = [scene(*WOMERSLEY, *mesh(1), "-dt", dt, np=2)["results"]["womersley_l2_relative"] for dt in (1e-2, 5e-3)]
    between(rate(*coarse), 1.8, 2.3, f"velocity L2 rate in dt, errors {coarse}")


@case
def oscillatory_shear():
    """The oscillatory shear index of Womersley's flow for a purely oscillating rate
    Q = sin(2 pi t / T) (zero mean): averaged over the second period, int tau dt = 0 at every wall
    node, so OSI = 1/2 everywhere (0.4995-0.5: what is left of the start's transient,
    exp(-T / 0.012 s)); a steady Poiseuille flow's is 0 (fsi_fluid.fluid_poiseuille)."""
    r = scene(*WOMERSLEY, "-mesh", os.path.join(MESHES, "womersley_L0_o2.msh"), "-dt", 2.5e-3, "-fluid_inflow_fourier", "0.05,0,1", "-fluid_wall_shear_from", 0.05, np=2)["results"]
    between(r["osi_min"], 0.499, 0.5 + 1e-12, "smallest OSI on the wall")
    between(r["osi_max"], 0.5 - 1e-6, 0.5 + 1e-12, "largest OSI on the wall")


@case
def inflow_profiles():
    """A steady flow rate (0.5 cm^3/s) through tube #1's circular inlet (curved cells) with each
    profile: the inlet's flux is the rate to 1e-12 (each profile scaled by its discrete flux);
    the parabolic profile (a Poisson solve on the inlet) and Womersley's (its mean: the
    parabola) give the same flow to 2e-3; a uniform profile differs. Womersley's profile on a
    half disc is refused: it needs a circular inlet."""
    base = ["-mesh", os.path.join(MESHES, "tube1_L0_o2.msh"), "-blocks", "fluid", "-fluid_region", "fluid", "-fluid_noslip", "interface",
            "-fluid_inlet", "inlet", "-fluid_outlet", "outlet", "-fluid_inflow_fourier", "1,0.5", "-dt", 0.01, "-t_final", 0.03,
            "-ksp_type", "preonly", "-pc_type", "lu", "-pc_factor_mat_solver_type", "mumps"]
    r = {p: scene(*base, "-fluid_inflow_profile", p, np=2)["results"] for p in ("plug", "parabolic", "womersley")}
    for p, res in r.items():
        between(abs(res["inlet_flux"] + 0.5) / 0.5, 0, 1e-12, f"{p}: inlet flux / Q")
    between(abs(r["parabolic"]["velocity_l2_norm"] / r["womersley"]["velocity_l2_norm"] - 1), 0, 2e-3, "parabolic / Womersley's mean: velocity L2 norm")
    between(abs(r["plug"]["velocity_l2_norm"] / r["womersley"]["velocity_l2_norm"] - 1), 2e-3, 1, "plug / Womersley's mean: velocity L2 norm")
    refused([APP, "-mesh", os.path.join(MESHES, "split_tube_L0.msh")] + base[2:] + ["-fluid_inlet", "outlet_a", "-fluid_outlet", "inlet", "-fluid_inflow_profile", "womersley"],
            "-fluid_inflow_profile womersley: the inlet outlet_a is not a circle", np=2)


@case
def outlets_resistance_rcr():
    """A rigid tube whose outlet is split into two groups, driven by an inlet pressure: one outlet
    a resistance, the other an RCR Windkessel, on 1 and 2 ranks, backward Euler and BDF2. At every
    step P = R Q + P_d on the first to round-off, the second's (Pi, P) equal the Windkessel ODE's
    recurrence from the reported flows to round-off, each outlet's unknown Q equals the flux of
    the velocity through it, and inflow = the sum of the outflows (the volume balance)."""
    dt = 1e-2
    for scheme, np in (("backward_euler", 1), ("bdf2", 2)):
        r = scene(*SPLIT, *MODELS, "-dt", dt, "-t_final", 6 * dt, "-time_scheme", scheme, np=np)
        assert r["unknowns"]["outlets"] == 6, r["unknowns"]
        t, qa, pa, _ = series(r, "outlet_a")
        assert len(t) == 6 and abs(t[-1] - 6 * dt) < 1e-12, t
        worst = max(abs(p - R * q) / abs(p) for q, p in zip(qa, pa))
        between(worst, 0, 1e-12, f"{scheme}: |P - R Q| / P at the resistance outlet, every step")
        _, qb, pb, pib = series(r, "outlet_b")
        pi, p = windkessel(qb, dt, scheme)
        worst = max(max(abs(x - y) / abs(y) for x, y in zip(pib, pi)), max(abs(x - y) / abs(y) for x, y in zip(pb, p)))
        between(worst, 0, 1e-12, f"{scheme}: Windkessel (Pi, P) against the ODE's recurrence, every step")
        res = r["results"]
        for g, q in (("outlet_a", qa[-1]), ("outlet_b", qb[-1])):
            between(abs(q - res["outlet_flux_" + g]) / abs(q), 0, 1e-9, f"{g}: the unknown Q / the flux of u")
        balance = res["inlet_flux"] + res["outlet_flux_outlet_a"] + res["outlet_flux_outlet_b"]
        between(abs(balance) / abs(res["inlet_flux"]), 0, 1e-10, "inflow - outflows, relative")
        between(res["outlet_flux_outlet_a"] / res["outlet_flux"], 0.2, 0.8, "the resistance outlet's share of the flow")


@case
def backflow_stabilization():
    """The backflow term -beta rho (u.n)_- u.v on the outlets. Steady flow driven backwards (the
    inlet's pressure -200 dyn/cm^2 below the outlets'), so fluid enters through the traction-free
    outlets at Re ~ 300: without the term Newton does not converge (the energy the entering
    fluid brings in is unbounded); with beta = 0.2 it converges quadratically (the term's
    Jacobian is exact), and beta = 1 damps the entering flow more. While the flow leaves
    everywhere the term is exactly zero: beta = 0 and 0.2 give the same transient run."""
    steady = SPLIT[:3] + ["fluid"] + SPLIT[4:] + ["-fluid_inlet_pressure", -200, "-snes_monitor", "-snes_max_it", 40, "-max_step_cuts", 0]
    off = run([APP] + [str(o) for o in steady] + ["-fluid_backflow_stabilization", 0], np=2, fail=True)
    assert re.search(r"^load step 1/1 .* DIVERGED_", off, re.M), off[-2000:]
    on = flow(*steady, np=2)
    norms = on["norms"]
    assert on["newton"] <= 8 and norms[-1] < 1e-12 * norms[0] and norms[-2] < 1e-3 * norms[-3], norms
    between(on["results"]["inlet_flux"], 1, 10, "the flux leaving through the inlet (cm^3/s)")
    damped = flow(*steady, "-fluid_backflow_stabilization", 1, np=2)
    between(damped["results"]["inlet_flux"] / on["results"]["inlet_flux"], 0.3, 0.95, "beta 1 / beta 0.2: the flow entering the outlets")
    forward = [SPLIT[:3] + ["fluid"] + SPLIT[4:], "-dt", 0.01, "-t_final", 0.06]
    a, b = (scene(*forward[0], *forward[1:], "-fluid_backflow_stabilization", beta)["results"] for beta in (0, 0.2))
    for key in ("outlet_flux", "velocity_l2_norm", "pressure_l2_norm"):
        assert a[key] == b[key], (key, a[key], b[key])


@case
def carotid_scene():
    """scenes/carotid_tube.opts with scenes/fsi_facsi_lu_fluid.opts, three 5 ms steps on 2 ranks:
    Womersley's inflow on a coupled wall (the rim moves with it: interface continuity to
    round-off), the RCR outlet started at Pi_0 = -10 mmHg: its (Pi, P) follow the Windkessel's
    BDF2 recurrence from the reported flows to round-off, and the volume balance holds; FGMRES
    takes 10-40 iterations per Newton step."""
    r = scene("-options_file", os.path.join(SCENES, "carotid_tube.opts"), "-options_file", os.path.join(SCENES, "fsi_facsi_lu_fluid.opts"), "-t_final", 0.015, np=2)
    res = r["results"]
    between(res["interface_velocity_jump"], 0, 1e-12, "max |u - d_t d_s| on the interface")
    between(res["volume_balance"] / res["max_inflow"], 0, 1e-9, "volume balance / inflow")
    between(r["krylov"] / r["newton"], 10, 40, "FGMRES iterations per Newton step")
    t, q, p, pi = series(r, "outlet")
    rp, c, rd, pd, pi0 = 2781.0, 6e-5, 17883.0, -106656.0, -13332.0
    dt, past, worst = 5e-3, [pi0, pi0], 0
    for qn, pn, pin in zip(q, p, pi):
        x = (c * (4 * past[-1] - past[-2]) / (2 * dt) + pd / rd + qn) / (3 * c / (2 * dt) + 1 / rd)
        past.append(x)
        worst = max(worst, abs(pin - x) / abs(x), abs(pn - (rp * qn + x)) / abs(pn))
    between(worst, 0, 1e-10, "RCR (Pi, P) against the BDF2 recurrence from Pi_0")


@case
def windkessel_sinusoid():
    """A rigid tube (tube #1) fed Q(t) = 1 + 0.5 cos(2 pi t / T), T = 0.1 s, with an RCR outlet
    (R_p 100, C 2e-5, R_d 1000: tau = R_d C = T/5), three periods: the outlet's flow is the
    inflow (incompressible, rigid) to 1e-9, and its pressure approaches the Windkessel's analytic
    periodic solution P = R_p Q + R_d a_0 + Re[R_d Q_1 e^(iwt) / (1 + i w R_d C)] at the scheme's
    order: BDF2 error over the third period falls at rate 1.8-2.3 from dt = T/20 to T/40 (measured 1.93)."""
    T, a0, a1, rp, c, rd = 0.1, 1.0, 0.5, 100.0, 2e-5, 1000.0
    base = ["-mesh", os.path.join(MESHES, "tube1_L0.msh"), "-blocks", "fluid,outlets", "-fluid_region", "fluid", "-fluid_noslip", "interface",
            "-fluid_inlet", "inlet", "-fluid_outlet", "outlet", "-fluid_inflow_fourier", f"{T},{a0},{a1}", "-fluid_inflow_profile", "parabolic",
            "-outlets_outlet_rcr", f"{rp},{c},{rd}", "-time_scheme", "bdf2", "-t_final", 3 * T,
            "-ksp_type", "preonly", "-pc_type", "lu", "-pc_factor_mat_solver_type", "mumps"]
    w = 2 * math.pi / T
    errors = []
    for n in (20, 40):
        r = scene(*base, "-dt", T / n, np=2)
        t, q, p, _ = series(r, "outlet")
        worst_q = max(abs(qk - (a0 + a1 * math.cos(w * tk))) for tk, qk in zip(t, q))
        between(worst_q, 0, 1e-9, f"dt = T/{n}: |Q_outlet - Q_inflow|")
        exact = lambda tk: rp * (a0 + a1 * math.cos(w * tk)) + rd * a0 + (rd * a1 * complex(math.cos(w * tk), math.sin(w * tk)) / complex(1, w * rd * c)).real  # noqa: E731
        errors.append(max(abs(pk - exact(tk)) for tk, pk in zip(t, p) if tk > 2 * T + 1e-9) / (rd * a1))
    between(rate(*errors), 1.8, 2.3, f"BDF2 rate of the outlet pressure against the periodic solution, errors {errors}")


@case
def outlets_pressure():
    """A prescribed outlet pressure p(t) = 20 + 10 cos(2 pi t / 0.05) dyn/cm^2 on one outlet of the
    split tube (BDF2, 2 ranks), a resistance on the other: at every step the first outlet's P is
    p(t) to round-off, the resistance's P = R Q, and the flows balance the inflow."""
    r = scene(*SPLIT, "-outlets_outlet_a_pressure_fourier", "0.05,20,10", "-outlets_outlet_b_resistance", R, "-dt", 5e-3, "-t_final", 0.03,
              "-time_scheme", "bdf2", np=2)
    t, _, p, _ = series(r, "outlet_a")
    worst = max(abs(pk - (20 + 10 * math.cos(2 * math.pi * tk / 0.05))) for tk, pk in zip(t, p))
    between(worst, 0, 1e-10, "|P - p(t)| at the pressure outlet, every step")
    _, q, p, _ = series(r, "outlet_b")
    between(max(abs(pk - R * qk) / abs(pk) for qk, pk in zip(q, p)), 0, 1e-12, "|P - R Q| / P at the resistance outlet")
    res = r["results"]
    between(abs(res["inlet_flux"] + res["outlet_flux"]) / abs(res["inlet_flux"]), 0, 1e-10, "inflow - outflows, relative")


@case
def outlets_restart():
    """Restart = uninterrupted run with a Windkessel (BDF2): the capacitor's pressure is a state
    of the checkpoint, so the resumed run's outlet series equal the uninterrupted run's to 1e-12,
    and so are the wall shear stress's time average and OSI (their sums are in it too); the
    per-outlet CSV and the fluid's boundaries CSV hold every step once."""
    tmp = tempfile.mkdtemp()
    f = lambda name: os.path.join(tmp, name)  # noqa: E731
    base = SPLIT + MODELS + ["-dt", 1e-2, "-time_scheme", "bdf2"]
    full = scene(*base, "-t_final", 0.06)
    run([APP] + [str(o) for o in base] + ["-t_final", 0.03, "-checkpoint", f("c.chk"), "-checkpoint_every", 1, "-output", f("o.xdmf")])
    resumed = scene(*base, "-t_final", 0.06, "-restart", f("c.chk"), "-output", f("o.xdmf"))
    assert resumed["restarted_at_step"] == 3, resumed["restarted_at_step"]
    _, q, p, pi = series(full, "outlet_b")
    _, q2, p2, pi2 = series(resumed, "outlet_b")
    for a, b, name in ((q, q2, "Q"), (p, p2, "P"), (pi, pi2, "Pi")):
        between(max(abs(x - y) / abs(x) for x, y in zip(a[3:], b)), 0, 1e-12, f"restarted / uninterrupted {name}")
    for key in ("tawss_mean", "osi_max"):  # the time averages' sums are in the checkpoint
        between(abs(resumed["results"][key] - full["results"][key]), 0, 1e-10 * full["results"][key], f"restarted / uninterrupted {key}")
    assert full["results"]["osi_max"] > 0, full["results"]
    with open(f("o_outlet_outlet_b.csv")) as csv:
        rows = csv.read().split()
    assert rows[0] == "t,Q,P,Pi" and len(rows) == 7, rows
    ts = [float(r.split(",")[0]) for r in rows[1:]]
    assert all(abs(x - 0.01 * (k + 1)) < 1e-12 for k, x in enumerate(ts)), ts
    between(abs(float(rows[-1].split(",")[2]) / p[-1] - 1), 0, 1e-9, "the CSV's last P / the report's")
    with open(f("o_boundaries.csv")) as csv:  # the fluid's boundaries: the same steps once, Q of outlet_b the outlet's
        rows = [line.split(",") for line in csv.read().split()]
    assert rows[0][:5] == ["t", "Q_inlet", "p_inlet", "Q_outlet_a", "p_outlet_a"] and len(rows) == 7, rows
    assert all(abs(float(x[0]) - 0.01 * (k + 1)) < 1e-12 for k, x in enumerate(rows[1:])), rows
    between(abs(float(rows[-1][rows[0].index("Q_outlet_b")]) / q[-1] - 1), 0, 1e-9, "the boundaries CSV's last Q of outlet_b / the outlet's")


@case
def outlets_facsi():
    """The coupled tube #1 (FaCSI, 2 ranks) with a resistance outlet instead of the traction-free
    one: its unknowns join the split 'outlets' after the fluid; Newton keeps its steps and GMRES
    its iterations per Newton step within 20 % of the traction-free run's, and MUMPS on the whole
    system gives the same outlet flow and pressure."""
    facsi = ["-options_file", os.path.join(SCENES, "fsi_facsi.opts"), "-t_final", 2.5e-3]
    outlet = ["-blocks", "structure,fluid,geometry,coupling,outlets", "-outlets_outlet_resistance", 1e4]
    free = fsi(*facsi, scene_file=os.path.join(SCENES, "fsi_tube1_arterial.opts"))
    r = fsi(*facsi, *outlet, scene_file=os.path.join(SCENES, "fsi_tube1_arterial.opts"))
    assert r["unknowns"]["outlets"] == 3, r["unknowns"]
    assert r["newton"] <= free["newton"] + 1, (r["newton"], free["newton"])
    between((r["krylov"] / r["newton"]) / (free["krylov"] / free["newton"]), 0.8, 1.2, "GMRES per Newton, resistance / traction-free")
    exact = fsi("-options_file", os.path.join(SCENES, "fsi_mumps.opts"), "-t_final", 2.5e-3, *outlet, scene_file=os.path.join(SCENES, "fsi_tube1_arterial.opts"))
    assert exact["krylov"] == exact["newton"], "one MUMPS solve per Newton step"
    for key in ("outlet_outlet_flow", "outlet_outlet_pressure"):
        between(abs(r["results"][key] / exact["results"][key] - 1), 0, 1e-5, f"{key}: FaCSI / MUMPS")
    between(r["results"]["outlet_outlet_pressure"] / (1e4 * r["results"]["outlet_outlet_flow"]), 1 - 1e-12, 1 + 1e-12, "P / (R Q)")


if __name__ == "__main__":
    main("fsi_outlets")
